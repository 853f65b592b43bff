#include "renderer/inspect/OutputReadback.h"

#include <cmath>

#include "renderer/Error.h"
#include "renderer/gl/Texture.h"

namespace dw {

bool isDisplayReady(const PublishedOutput& output) {
    return output.decl.kind == OutputKind::Color && output.texture && output.texture->internalFormat() == GL_RGBA8;
}

FloatImage readOutputRaw(const PublishedOutput& output) {
    if (!output.texture) throw Error("buffer '" + output.decl.name + "' has not been allocated");
    const gl::Texture& t = *output.texture;
    FloatImage img;
    img.width = t.width(output.level);
    img.height = t.height(output.level);
    GLenum format = GL_RGBA;
    if (t.isDepth()) {
        format = GL_DEPTH_COMPONENT;
        img.channels = 1;
    } else {
        img.channels = output.channels;
        format = img.channels == 1 ? GL_RED : img.channels == 2 ? GL_RG : img.channels == 3 ? GL_RGB : GL_RGBA;
    }
    img.pixels = t.readFloats(output.level, format, img.channels);
    // Read-back returns sRGB textures' stored (encoded) values; shaders see
    // them decoded, and raw read-back means what the shaders see.
    if (t.isSrgb()) {
        for (size_t i = 0; i < img.pixels.size(); ++i) {
            if (static_cast<int>(i % img.channels) == 3) continue;
            float& c = img.pixels[i];
            c = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
        }
    }
    img.flipVertically();
    return img;
}

FloatImage readRgba8(const gl::Texture& texture) {
    FloatImage img;
    img.width = texture.width();
    img.height = texture.height();
    img.channels = 4;
    const auto bytes = texture.readBytes(0, GL_RGBA, 4);
    img.pixels.resize(bytes.size());
    for (size_t i = 0; i < bytes.size(); ++i) img.pixels[i] = bytes[i] / 255.0f;
    img.flipVertically();
    return img;
}

FloatImage readWindowFramebuffer(int width, int height) {
    FloatImage img;
    img.width = width;
    img.height = height;
    img.channels = 3;
    std::vector<std::uint8_t> bytes(static_cast<size_t>(width) * height * 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());
    img.pixels.resize(bytes.size());
    for (size_t i = 0; i < bytes.size(); ++i) img.pixels[i] = bytes[i] / 255.0f;
    img.flipVertically();
    return img;
}

std::vector<std::string> rawChannelNames(const PublishedOutput& output) {
    if (output.texture && output.texture->isDepth()) return {"Z"};
    switch (output.channels) {
        case 1: return {"Y"};
        case 2: return {"R", "G"};
        case 3: return {"R", "G", "B"};
        default: return {"R", "G", "B", "A"};
    }
}

}  // namespace dw
