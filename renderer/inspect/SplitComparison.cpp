#include "renderer/inspect/SplitComparison.h"
#include "renderer/gl/MemoryLedger.h"

#include <algorithm>
#include <cmath>

#include "renderer/Error.h"
#include "renderer/metrics/HeatMap.h"

namespace dw {

void SplitComparison::upload(gl::Texture& texture, const FloatImage& image) {
    if (!texture || texture.width() != image.width || texture.height() != image.height) {
        gl::MemoryOwner owner("split comparison");
        texture = gl::Texture::create2D(GL_RGBA8, image.width, image.height);
        texture.setFilter(GL_LINEAR, GL_NEAREST);
    }
    // RGBA, bottom-up (GL's row order, as the pipeline's outputs).
    std::vector<float> rgba(static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 4, 1.0f);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            float* out = &rgba[(static_cast<size_t>(image.height - 1 - y) * static_cast<size_t>(image.width) +
                                static_cast<size_t>(x)) * 4];
            for (int c = 0; c < std::min(image.channels, 4); ++c) out[c] = std::clamp(image.at(x, y, c), 0.0f, 1.0f);
            if (image.channels == 1) out[1] = out[2] = out[0];
        }
    texture.upload(0, image.width, image.height, GL_RGBA, GL_FLOAT, rgba.data());
}

void SplitComparison::set(const FloatImage& a, const FloatImage& b) {
    ready_ = false;
    ComparisonSettings settings;  // LDR, as compare takes two PNG files
    comparison_ = ImageComparison::measure(b, a, settings, "B", "A");
    a_ = a;
    b_ = b;
    upload(textureA_, a_);
    upload(textureB_, b_);
    ready_ = true;
}

void SplitComparison::makeHeatMap(Map map) {
    if (!ready_) return;
    FloatImage values;
    if (map == Map::Flip && comparison_.flip) {
        values = comparison_.flip->map;
        heatHigh_ = 1.0;
    } else {
        const FloatImage& d = comparison_.absoluteDifference;
        const int colour = std::min(d.channels, 3);
        values.width = d.width;
        values.height = d.height;
        values.channels = 1;
        values.pixels.resize(static_cast<size_t>(d.width) * static_cast<size_t>(d.height));
        double high = 0.0;
        for (size_t i = 0; i < values.pixels.size(); ++i) {
            double s = 0.0;
            for (int c = 0; c < colour; ++c) s += d.pixels[i * static_cast<size_t>(d.channels) + static_cast<size_t>(c)];
            values.pixels[i] = static_cast<float>(s / colour);
            high = std::max(high, static_cast<double>(values.pixels[i]));
        }
        heatHigh_ = high > 0.0 ? high : 1.0;
    }
    upload(heat_, HeatMap::colour(values, 0, 0.0, heatHigh_));
}

}  // namespace dw
