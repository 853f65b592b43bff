// GPU log-average and max luminance (seed 000 section 5.3.1) against the CPU
// double-precision computation: within 1e-3 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "renderer/passes/LuminancePass.h"
#include "renderer/reference/LuminanceReference.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {
glm::vec4 readStats(const gl::Texture& t) {
    const auto v = t.readFloats(0, GL_RGBA, 4);
    return {v[0], v[1], v[2], v[3]};
}
}  // namespace

TEST(Luminance, RandomHdrImageMatchesCpuDoublePrecision) {
    // An odd size (not a multiple of the 16x16 tiles), six decades of values,
    // black pixels, and NaN/Inf pixels that must be left out.
    const int w = 333, h = 177;
    FloatImage img{w, h, 4, std::vector<float>(static_cast<size_t>(w) * h * 4)};
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float scale = std::pow(10.0f, -3.0f + 6.0f * u(rng));
            for (int c = 0; c < 3; ++c) img.at(x, y, c) = scale * u(rng);
            img.at(x, y, 3) = 1.0f;
            if ((x * 7 + y * 13) % 97 == 0) img.at(x, y, 0) = img.at(x, y, 1) = img.at(x, y, 2) = 0.0f;
        }
    img.at(3, 4, 1) = std::numeric_limits<float>::quiet_NaN();
    img.at(100, 50, 0) = std::numeric_limits<float>::infinity();
    img.at(200, 20, 2) = -std::numeric_limits<float>::infinity();

    auto session = test::makeSession(64, 64);  // compiles the shaders
    gl::Texture tex = gl::Texture::create2D(GL_RGBA32F, w, h);
    tex.upload(0, w, h, GL_RGBA, GL_FLOAT, img.pixels.data());
    auto* pass = session->pipeline().pass<LuminancePass>();
    for (double delta : {1e-4, 1e-2}) {
        pass->reduce(tex, static_cast<float>(delta));
        const glm::vec4 gpu = readStats(pass->statsTexture());
        const reference::LuminanceStats cpu = reference::luminanceStats(img, delta);
        EXPECT_EQ(cpu.finiteCount, static_cast<long long>(w) * h - 3);
        EXPECT_EQ(static_cast<long long>(gpu.w), cpu.finiteCount);
        EXPECT_NEAR(gpu.x / cpu.logAverage, 1.0, 1e-3) << "log-average, delta " << delta;
        EXPECT_NEAR(gpu.y / cpu.max, 1.0, 1e-6) << "max";
        EXPECT_NEAR(gpu.z / cpu.mean, 1.0, 1e-3) << "mean";
    }
}

TEST(Luminance, LBufferStatisticsOfARenderedSceneMatch) {
    auto session = test::makeSession(160, 90);
    session->loadScene("default");
    for (const char* background : {"include", "exclude"}) {
        session->knobs().setFromString("luminance.background", background);
        session->render({{"luminance.stats", "gbuffer.depth"}});
        const FloatImage L = session->readRaw("lbuffer");
        const FloatImage stats = session->readRaw("luminance.stats");
        FloatImage counted = L;
        if (std::string(background) == "exclude") {
            const FloatImage depth = session->readRaw("gbuffer.depth");
            for (int y = 0; y < L.height; ++y)
                for (int x = 0; x < L.width; ++x)
                    if (depth.at(x, y, 0) >= 1.0f) counted.at(x, y, 0) = std::numeric_limits<float>::quiet_NaN();
        }
        const reference::LuminanceStats cpu = reference::luminanceStats(counted, 1e-4);
        EXPECT_NEAR(stats.at(0, 0, 0) / cpu.logAverage, 1.0, 1e-3) << background;
        EXPECT_NEAR(stats.at(0, 0, 1) / cpu.max, 1.0, 1e-6) << background;
        EXPECT_EQ(static_cast<long long>(stats.at(0, 0, 3)), cpu.finiteCount) << background;
    }
}
