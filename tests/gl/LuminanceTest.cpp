// GPU log-average and max luminance (seed 000 section 5.3.1) against the CPU
// double-precision computation: within 1e-3 relative.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "renderer/gl/DepthConvention.h"
#include "renderer/passes/LuminancePass.h"
#include "renderer/reference/LuminanceReference.h"
#include "renderer/scene/SceneJsonLoader.h"
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
                    if (DepthConvention().isFar(depth.at(x, y, 0))) counted.at(x, y, 0) = std::numeric_limits<float>::quiet_NaN();
        }
        const reference::LuminanceStats cpu = reference::luminanceStats(counted, 1e-4);
        EXPECT_NEAR(stats.at(0, 0, 0) / cpu.logAverage, 1.0, 1e-3) << background;
        EXPECT_NEAR(stats.at(0, 0, 1) / cpu.max, 1.0, 1e-6) << background;
        EXPECT_EQ(static_cast<long long>(stats.at(0, 0, 3)), cpu.finiteCount) << background;
    }
}

// Statistics of nothing (issue 10): a reduction over no pixel, or over black
// pixels only, has a defined log-average of 1 on the GPU and in the reference.
TEST(Luminance, EmptyOrBlackSetsFallBackToALogAverageOfOne) {
    auto session = test::makeSession(64, 64);
    auto* pass = session->pipeline().pass<LuminancePass>();
    const int w = 37, h = 21;
    for (float value : {0.0f, std::numeric_limits<float>::quiet_NaN()}) {
        FloatImage img{w, h, 4, std::vector<float>(static_cast<size_t>(w) * h * 4, value)};
        gl::Texture tex = gl::Texture::create2D(GL_RGBA32F, w, h);
        tex.upload(0, w, h, GL_RGBA, GL_FLOAT, img.pixels.data());
        pass->reduce(tex, 1e-4f);
        const glm::vec4 gpu = readStats(pass->statsTexture());
        const reference::LuminanceStats cpu = reference::luminanceStats(img, 1e-4);
        EXPECT_EQ(gpu.x, 1.0f) << "pixels " << value;
        EXPECT_EQ(cpu.logAverage, 1.0) << "pixels " << value;
        EXPECT_EQ(gpu.y, 0.0f);
        EXPECT_EQ(gpu.w, std::isnan(value) ? 0.0f : static_cast<float>(w * h));
    }
}

// The case only_sky_in_view.json, small: the camera looks up, away from all
// geometry, with the background excluded from the statistics. Before, the
// count was 0 and Reinhard's auto white turned the frame (1, 1, 1); now it
// is the dark background, exactly as with auto_white off.
TEST(Luminance, OnlySkyInViewGivesADarkFrameAsWithManualWhite) {
    const char* json = R"({
      "settings": { "luminance.background": "exclude", "tonemap.operator": "reinhard" },
      "camera": { "pos": [0, 6, 14], "look-at": [0, 30, 14.5], "up": [0, 0, -1], "fov": 50, "near": 0.1, "far": 80 },
      "lighting": { "ambient": [0.03, 0.03, 0.035], "direction": [-0.3, -1, -0.4], "intensity": [0.15, 0.15, 0.18],
        "lights": [ { "name": "bulb", "type": "point", "pos": [0, 1.2, -2.5], "shadow": true, "intensity": [1.5, 1.2, 0.8],
                      "attenuation": { "constant": 1, "linear": 0.7, "quadratic": 1.8 } } ] },
      "objects": [ { "shape": "plane", "size": [24, 0, 24], "material": { "diffuse": [0.6, 0.6, 0.6] } },
                   { "shape": "sphere", "radius": 1, "pos": [-3, 1, 0], "material": { "diffuse": [0.8, 0.8, 0.7] } } ],
      "background": [0.02, 0.03, 0.06], "sky": { "type": "color" } })";
    auto render = [&](bool autoWhite) {
        auto session = test::makeSession(160, 90);
        session->setScene(parseSceneJson(json, "only_sky_in_view.json"));
        session->knobs().setFromString("luminance.background", "exclude");
        session->knobs().setFromString("tonemap.auto_white", autoWhite ? "true" : "false");
        session->render({{"final", "luminance.stats"}});
        const FloatImage stats = session->readRaw("luminance.stats");
        EXPECT_EQ(stats.at(0, 0, 3), 0.0f) << "no pixel counted";
        EXPECT_EQ(stats.at(0, 0, 0), 1.0f) << "the fallback log-average";
        return session->readRaw("final");
    };
    const FloatImage automatic = render(true), manual = render(false);
    const test::ChannelStats s = test::stats(automatic, 0);
    std::printf("only sky in view: final red mean %.4f, max %.4f\n", s.mean, s.max);
    EXPECT_LT(s.max, 0.1);  // a dark frame, not (1, 1, 1)
    EXPECT_LE(test::maxAbsDifference(automatic, manual, 3), 1.0 / 255.0);
}
