#pragma once
// What comparing two images takes in memory, held to the image memory budget
// (DW_IMAGE_LIMIT_MB, renderer/io/ImageLimits): compare on files and renders
// (app/CompareInput) and the Python module's compare on arrays use it, so
// both refuse the same shapes with the same message.
//
// Both images, their differences, SSIM and FLIP take kBytesPerPixel +
// kBytesPerChannel x channels a pixel, and each HDR-FLIP evaluation running
// at once FlipParameters::kBytesPerEvaluation (measured: docs/metrics.md,
// "Memory").
#include <string>

namespace dw::comparison_memory {

constexpr double kBytesPerPixel = 4, kBytesPerChannel = 32;

// Bytes comparing `width` x `height` pixels of `channels` channels takes with
// `evaluations` FLIP evaluations at once.
long double bytes(int width, int height, int channels, unsigned evaluations);

// Why an image of this shape cannot be compared within the budget (one FLIP
// evaluation at a time): "W x H pixels of C channels: comparing it takes
// about N MB (...), over the image memory limit of L MB (set
// DW_IMAGE_LIMIT_MB=MB to raise it)", or "" when it can. Throws Error when
// DW_IMAGE_LIMIT_MB is malformed.
std::string refusal(int width, int height, int channels);

// How many HDR-FLIP exposures may run at once within the budget (1 to 4):
// FlipParameters::maxThreads. The result is the same for any number.
unsigned flipThreadsWithin(int width, int height, int channels);

}  // namespace dw::comparison_memory
