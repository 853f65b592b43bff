#pragma once
// The memory budget of every image the workbench decodes (environment maps,
// glTF and scene textures), checked from the file's header before a decoder
// allocates anything from it. A damaged header (OpenEXR's fuzz cases, its
// "memory_DOS" files) can claim a data window of 2^31 x 2^31 pixels: the
// decoder's allocations then end in std::bad_alloc, or in minutes and
// gigabytes spent on an image that was never there.
#include <cstddef>
#include <cstdint>
#include <string>

namespace dw {

// Default budget for one decoded image, in MiB.
constexpr std::uint64_t kDefaultImageLimitMB = 1024;
// The environment variable that raises (or lowers) it: DW_IMAGE_LIMIT_MB=4096.
constexpr const char* kImageLimitVariable = "DW_IMAGE_LIMIT_MB";

// The budget in bytes: DW_IMAGE_LIMIT_MB when set (a whole number of MiB, at
// least 1), else kDefaultImageLimitMB. Throws Error when the variable is set
// to something else.
std::uint64_t imageMemoryLimit();

// Throws FileError(name, ...) when `width` x `height` pixels of `channels`
// channels at `bytesPerPixel` bytes each (all channels) exceed the budget:
// "<what> is W x H pixels of C channels: N MB decoded, over the image memory
// limit of L MB (set DW_IMAGE_LIMIT_MB to raise it)".
void checkImageBudget(std::uint64_t width, std::uint64_t height, int channels, std::uint64_t bytesPerPixel,
                      const std::string& name, const std::string& what = "the image");

// An image file's width, height and channel count from its header alone (no
// pixel is decoded: a caller checks what decoding and working on it would
// take first; compare does, renderer/metrics/ComparisonMemory). Throws FileError (missing,
// unreadable, a damaged header). Defined with the decoders, renderer/io/ImageIO.cpp.
struct ImageShape {
    int width = 0, height = 0, channels = 0;
};
ImageShape readImageShape(const std::string& path);

// True when the bytes start with OpenEXR's magic number.
bool isExr(const std::uint8_t* bytes, std::size_t size);

// How many bytes of an OpenEXR file its header(s) take, scanning `bytes`
// (the start of the file, `fileSize` bytes long in all). Returns 0 when the
// headers continue past `size` < `fileSize` (read more and call again).
// Throws FileError(name, ...) for what OpenEXR or OpenImageIO would allocate
// from or misread: a header cut short or out of shape, a data or display
// window that is empty, inverted or beyond 32-bit coordinates, no channels or
// an unknown channel type, tiles of zero size, deep data, and a data window
// (or tile) whose decoded size, at `bytesPerChannel` per channel, is over
// the budget.
std::size_t checkExrHeader(const std::uint8_t* bytes, std::size_t size, std::uint64_t fileSize, const std::string& name,
                           std::uint64_t bytesPerChannel);

// checkExrHeader on a file, reading only as much of it as the headers take.
// Does nothing for a file that is not OpenEXR.
void checkExrFile(const std::string& path, std::uint64_t bytesPerChannel);

}  // namespace dw
