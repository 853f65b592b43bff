#pragma once
// Image files through OpenImageIO: decoding textures, writing rendered buffers
// (PNG as 8-bit, EXR as raw float), and OIIO's image comparison.
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/io/Image.h"

namespace dw {

// Float pixels, rows top-down, `channels` interleaved.
struct FloatImage {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;
    float& at(int x, int y, int c) { return pixels[(static_cast<size_t>(y) * width + x) * channels + c]; }
    float at(int x, int y, int c) const { return pixels[(static_cast<size_t>(y) * width + x) * channels + c]; }
    // Flips rows in place (GL read-back is bottom-up).
    void flipVertically();
};

// 8-bit RGBA decode of any format OIIO reads. Throws FileError.
Image loadImage8(const std::string& path);
Image decodeImage8(const std::uint8_t* bytes, size_t size, const std::string& nameHint,
                   const std::string& mimeType);
// Float decode (HDR/EXR and anything else). Throws FileError.
FloatImage loadImageFloat(const std::string& path);

// Writes by extension: .png/.jpg/.tga as 8-bit (values clamped to [0,1]),
// .exr/.hdr/.tif as float. A file is written whole or not at all (encoded,
// then written, synced and renamed over the old one; a full disk is an
// error, and no part is left); a device or pipe is written in place.
// Throws FileError naming the path.
void writeImage(const std::string& path, const FloatImage& image,
                const std::vector<std::string>& channelNames = {});
bool isFloatFormat(const std::string& path);

struct ImageDifference {
    double meanError = 0, rmsError = 0, psnr = 0, maxError = 0;
    int maxX = 0, maxY = 0, maxChannel = 0;
    long long failCount = 0;  // pixels whose error exceeds failThreshold
    long long pixelCount = 0;
};
// OIIO ImageBufAlgo::compare on the common channels. Throws Error if sizes differ.
ImageDifference compareImages(const FloatImage& a, const FloatImage& b, float failThreshold = 1e-3f);

}  // namespace dw
