#include "renderer/metrics/DifferenceStatistics.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "renderer/Error.h"

namespace dw {

namespace OIIO = OIIO_NAMESPACE;

namespace {

DifferenceFigures figures(const OIIO::ImageBufAlgo::CompareResults& r) {
    DifferenceFigures f;
    f.mean = r.meanerror;
    f.rms = r.rms_error;
    f.psnr = r.PSNR;
    f.max = r.maxerror;
    f.maxX = r.maxx;
    f.maxY = r.maxy;
    f.maxChannel = r.maxc;
    f.warnCount = static_cast<long long>(r.nwarn);
    f.failCount = static_cast<long long>(r.nfail);
    return f;
}

}  // namespace

std::string DifferenceStatistics::shape(const FloatImage& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" + std::to_string(image.channels);
}

DifferenceStatistics DifferenceStatistics::measure(const FloatImage& a, const FloatImage& b, double warnThreshold,
                                                   double failThreshold) {
    if (a.width != b.width || a.height != b.height || a.channels != b.channels)
        throw Error("the images differ in shape (" + shape(a) + " vs " + shape(b) + ", width x height x channels)");
    // The buffers wrap the pixels without copying (OIIO reads them only).
    const OIIO::ImageSpec spec(a.width, a.height, a.channels, OIIO::TypeDesc::FLOAT);
    const OIIO::ImageBuf A(spec, const_cast<float*>(a.pixels.data()));
    const OIIO::ImageBuf B(spec, const_cast<float*>(b.pixels.data()));
    DifferenceStatistics s;
    s.pixelCount = static_cast<long long>(a.width) * a.height;
    s.warnThreshold = warnThreshold;
    s.failThreshold = failThreshold;
    const auto all = OIIO::ImageBufAlgo::compare(A, B, static_cast<float>(failThreshold),
                                                 static_cast<float>(warnThreshold));
    // (CompareResults::error is set whenever a value fails, not only on an
    // error of OIIO's: the buffers' own error state is the one to ask.)
    if (A.has_error() || B.has_error()) throw Error("OpenImageIO could not compare the images: " + A.geterror() + B.geterror());
    s.overall = figures(all);
    for (int c = 0; c < a.channels; ++c) {
        OIIO::ROI roi = A.roi();
        roi.chbegin = c;
        roi.chend = c + 1;
        const auto one = OIIO::ImageBufAlgo::compare(A, B, static_cast<float>(failThreshold),
                                                     static_cast<float>(warnThreshold), roi);
        s.perChannel.push_back(figures(one));
    }
    return s;
}

}  // namespace dw
