#include "renderer/io/ImageHistogram.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dw {

ImageHistogram computeHistogram(const FloatImage& image, int bins) {
    ImageHistogram h;
    h.bins = std::max(bins, 1);
    if (image.width <= 0 || image.height <= 0 || image.channels <= 0) return h;
    const int channels = std::min(image.channels, 4);
    OIIO::ImageBuf all(OIIO::ImageSpec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT),
                       const_cast<float*>(image.pixels.data()));
    const OIIO::ImageBuf buf = image.channels > 4 ? OIIO::ImageBufAlgo::channels(all, 4, {}) : all;
    const auto stats = OIIO::ImageBufAlgo::computePixelStats(buf);
    h.lo = std::numeric_limits<float>::max();
    h.hi = std::numeric_limits<float>::lowest();
    h.channels.resize(static_cast<size_t>(channels));
    for (int c = 0; c < channels; ++c) {
        auto& ch = h.channels[static_cast<size_t>(c)];
        ch.nan = stats.nancount[c];
        ch.inf = stats.infcount[c];
        ch.lo = stats.min[c];
        ch.hi = stats.max[c];
        const std::uint64_t finite = static_cast<std::uint64_t>(image.width) * image.height - ch.nan - ch.inf;
        if (finite > 0 && std::isfinite(ch.lo) && std::isfinite(ch.hi)) {
            h.lo = std::min(h.lo, ch.lo);
            h.hi = std::max(h.hi, ch.hi);
        }
    }
    if (h.lo > h.hi) h.lo = h.hi = 0.0f;
    // A constant image still gets a range one bin wide around its value.
    const float hi = h.hi > h.lo ? h.hi : h.lo + std::max(std::fabs(h.lo) * 1e-3f, 1e-6f);
    // OIIO bins values outside the range into the end bins: non-finite
    // values go to bin 0 of a copy, and are taken out of it again.
    OIIO::ImageBuf finite = buf;
    bool anyNonFinite = false;
    for (const auto& ch : h.channels) anyNonFinite = anyNonFinite || ch.nan + ch.inf > 0;
    if (anyNonFinite) {
        finite = OIIO::ImageBuf(buf.spec());
        finite.copy_pixels(buf);
        for (OIIO::ImageBuf::Iterator<float> it(finite); !it.done(); ++it)
            for (int c = 0; c < channels; ++c)
                if (!std::isfinite(it[c])) it[c] = h.lo;
    }
    for (int c = 0; c < channels; ++c) {
        auto& ch = h.channels[static_cast<size_t>(c)];
        const auto counts = OIIO::ImageBufAlgo::histogram(finite, c, h.bins, h.lo, hi, false);
        ch.counts.assign(counts.begin(), counts.end());
        if (!ch.counts.empty()) ch.counts[0] -= std::min<std::uint64_t>(ch.counts[0], ch.nan + ch.inf);
    }
    h.hi = hi;
    return h;
}

}  // namespace dw
