#pragma once
// Per-channel histogram and statistics of an image, for the workbench's
// texture viewer (a histogram of the shown buffer with log counts and the
// display range on it). Both come from OpenImageIO (ImageBufAlgo::
// computePixelStats for min / max / NaN / Inf counts, ImageBufAlgo::histogram
// for the bins); non-finite values are counted, never binned.
#include <cstdint>
#include <vector>

#include "renderer/io/ImageIO.h"

namespace dw {

struct ImageHistogram {
    int bins = 0;
    // Per channel (as many as the image has, at most 4): the finite range,
    // the bin counts over [lo, hi] and how many values were NaN or infinite.
    struct Channel {
        float lo = 0.0f, hi = 0.0f;
        std::vector<std::uint64_t> counts;
        std::uint64_t nan = 0, inf = 0;
    };
    std::vector<Channel> channels;
    // One range over every channel (the union of their finite ranges), so
    // the channels' bins line up on one axis.
    float lo = 0.0f, hi = 0.0f;
};

// `bins` >= 1. An empty image gives no channels.
ImageHistogram computeHistogram(const FloatImage& image, int bins = 128);

}  // namespace dw
