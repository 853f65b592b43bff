#include "renderer/metrics/ComparisonMemory.h"

#include <cstdint>
#include <cstdio>

#include "renderer/io/ImageLimits.h"
#include "renderer/metrics/Flip.h"

namespace dw::comparison_memory {

namespace {

std::string megabytes(long double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0Lf", bytes / (1024.0L * 1024.0L));
    return text;
}

}  // namespace

long double bytes(int width, int height, int channels, unsigned evaluations) {
    const long double pixels = static_cast<long double>(width) * height;
    return pixels * (kBytesPerPixel + kBytesPerChannel * channels + FlipParameters::kBytesPerEvaluation * evaluations);
}

std::string refusal(int width, int height, int channels) {
    const std::uint64_t limit = imageMemoryLimit();
    const long double need = bytes(width, height, channels, 1);
    if (need <= static_cast<long double>(limit)) return "";
    return std::to_string(width) + " x " + std::to_string(height) + " pixels of " + std::to_string(channels) + " channel" +
           (channels == 1 ? "" : "s") + ": comparing it takes about " + megabytes(need) +
           " MB (both images, their differences, SSIM and FLIP), over the image memory limit of " +
           std::to_string(limit / (1024 * 1024)) + " MB (set " + kImageLimitVariable + "=MB to raise it)";
}

unsigned flipThreadsWithin(int width, int height, int channels) {
    const long double limit = static_cast<long double>(imageMemoryLimit());
    unsigned threads = 4;
    while (threads > 1 && bytes(width, height, channels, threads) > limit) --threads;
    return threads;
}

}  // namespace dw::comparison_memory
