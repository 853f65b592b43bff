// Issue 35 part 2: the anti-aliasing methods of aa.method. Every method
// renders every built-in scene through every lighting strategy with finite
// values; SSAA renders the frame at aa.ssaa_factor times the size (capped);
// TAA's history converges on a still camera to the mean of its jittered
// frames and is thrown away (taa.rejected) where a camera move brings new
// pixels into view. MSAA's edge mask marks silhouettes and nothing on a
// plane facing the camera, its aa.samples is capped by the device (said),
// and the other methods' images do not change with it. SSAA and MSAA against
// the footprint reference: tests/reference/AntialiasingReferenceTest.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "renderer/Error.h"
#include "renderer/passes/MsaaPass.h"
#include "renderer/passes/SsaaPass.h"
#include "renderer/passes/TaaPass.h"
#include "renderer/scene/BuiltinScenes.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

std::vector<std::string> choices(const KnobRegistry& k, const std::string& knob) {
    return k.spec(*k.find(knob)).choices;
}

bool allFinite(const FloatImage& img) {
    for (float v : img.pixels)
        if (!std::isfinite(v)) return false;
    return true;
}

double meanAbs(const FloatImage& a, const FloatImage& b, const std::vector<size_t>* only = nullptr) {
    double sum = 0.0;
    size_t n = 0;
    auto add = [&](size_t p) {
        for (int c = 0; c < 3; ++c) sum += std::fabs(a.pixels[p * a.channels + c] - b.pixels[p * b.channels + c]);
        n += 3;
    };
    if (only)
        for (size_t p : *only) add(p);
    else
        for (size_t p = 0; p < static_cast<size_t>(a.width) * a.height; ++p) add(p);
    return n ? sum / static_cast<double>(n) : 0.0;
}

}  // namespace

TEST(Antialiasing, TheMethodsAreOneKnobAndAnUnbuiltOneIsRefusedNamingThoseThatExist) {
    auto s = test::makeSession(32, 18);
    const auto methods = choices(s->knobs(), "aa.method");
    EXPECT_EQ(methods, (std::vector<std::string>{"none", "msaa", "fxaa", "ssaa", "taa"}));
    EXPECT_EQ(s->knobs().format(*s->knobs().find("aa.method")), "fxaa");  // today's default
    // SSAA's scale and TAA's jitter change every pass's work: the change-cost
    // verdict counts every pass as read by the knobs that choose them.
    for (const char* k : {"aa.method", "aa.ssaa_factor"})
        EXPECT_TRUE(s->pipeline().knobReaders(*s->knobs().find(k)).count("*")) << k;
    EXPECT_FALSE(s->pipeline().knobReaders(*s->knobs().find("aa.taa_blend")).count("*"));
    EXPECT_FALSE(s->pipeline().knobReaders(*s->knobs().find("fxaa.quality")).count("*"));
    try {
        s->knobs().applyAssignment("aa.method=smaa");
        FAIL() << "aa.method=smaa accepted";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("takes one of: none, msaa, fxaa, ssaa, taa; got 'smaa'"), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
    try {
        s->knobs().applyAssignment("aa.ssaa_factor=3");
        FAIL() << "aa.ssaa_factor=3 accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("takes one of: 2, 4; got '3'"), std::string::npos) << e.what();
    }
    try {
        s->knobs().applyAssignment("aa.samples=3");
        FAIL() << "aa.samples=3 accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("takes one of: 2, 4, 8, 16; got '3'"), std::string::npos) << e.what();
    }
}

// Each method (the first test holds this list to the knob's choices) on
// every built-in scene, transparent ones among them, through every lighting
// strategy, two frames each (TAA's second with a history).
class AntialiasingMethod : public ::testing::TestWithParam<std::string> {};

TEST_P(AntialiasingMethod, RendersEveryBuiltinSceneThroughEveryStrategyWithFiniteValues) {
    const std::string method = GetParam();
    auto s = test::makeSession(32, 18);
    FrameRequest request{{"final"}};
    if (method == "ssaa") request.outputs.push_back("ssaa.lbuffer");
    if (method == "taa") request.outputs.push_back("taa.rejected");
    if (method == "msaa") request.outputs.push_back("aa.edges");
    for (const BuiltinSceneInfo& info : builtinScenes()) {
        s->loadScene(info.name);
        for (const std::string& strategy : choices(s->knobs(), "lighting.strategy")) {
            s->knobs().setFromString("lighting.strategy", strategy);
            s->knobs().setFromString("aa.method", method);
            const std::string where = info.name + ", " + strategy;
            s->render(request);
            const FrameReport r = s->render(request);
            if (method != "none") {
                ASSERT_TRUE(r.find(method)->ran) << where << ": " << r.find(method)->reason;
                // MSAA resolves the L-buffer: its display image is the post chain's as without AA.
                if (method != "msaa") {
                    EXPECT_EQ(s->pipeline().resolveFinal(), method + ".result") << where;
                }
            }
            for (const std::string& o : request.outputs) {
                const FloatImage img = s->readRaw(o);
                EXPECT_EQ(img.width, 32) << where << " " << o;
                EXPECT_TRUE(allFinite(img)) << where << " " << o;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, AntialiasingMethod, ::testing::Values("none", "fxaa", "ssaa", "msaa", "taa"));

TEST(Antialiasing, SsaaRendersTheFrameAtTheFactorAndCapsTheSupersampledSize) {
    auto s = test::makeSession(40, 24);
    s->loadScene("spheres");
    s->knobs().setFromString("aa.method", "ssaa");
    for (const char* f : {"2", "4"}) {
        s->knobs().setFromString("aa.ssaa_factor", f);
        const FrameReport r = s->render({{"final", "lbuffer"}});
        EXPECT_EQ(s->pipeline().renderScale(), std::stoi(f));
        EXPECT_EQ(s->readRaw("lbuffer").width, 40 * std::stoi(f));
        EXPECT_EQ(s->readRaw("final").width, 40);
        EXPECT_TRUE(r.warnings().empty());
    }
    // The cap: 4x4 of 1280x720 would be 5120x2880; 2x2 (2560x1440) fits in 3840x2160.
    EXPECT_EQ(SsaaPass::cappedFactor(4, 1280, 720), 2);
    EXPECT_EQ(SsaaPass::cappedFactor(2, 1920, 1080), 2);
    EXPECT_EQ(SsaaPass::cappedFactor(2, 3840, 2160), 1);
    EXPECT_EQ(SsaaPass::cappedFactor(4, 20000, 10), 1);  // 16384 a side
    EXPECT_EQ(SsaaPass::cappedFactor(4, 640, 360), 4);
    // Switched back, the frame is its own size again.
    s->knobs().setFromString("aa.method", "none");
    s->render({{"final", "lbuffer"}});
    EXPECT_EQ(s->pipeline().renderScale(), 1);
    EXPECT_EQ(s->readRaw("lbuffer").width, 40);
}

// Under SSAA the tone mapper's statistics are the output image's: each
// output pixel the mean of its factor x factor rendered pixels (the area
// mean the reference's --spp N estimates), so L_white is the largest of
// those means, not a sub-pixel highlight's, and the count is the output
// pixels'. (With the rendered pixels' statistics SSAA's auto white point
// sat above the reference's, and its images were further from the
// footprint truth than no anti-aliasing: docs/antialiasing.md, "The study".)
TEST(Antialiasing, SsaaToneMapsWithTheStatisticsOfTheOutputPixels) {
    auto s = test::makeSession(40, 24);
    s->loadScene("spheres");
    s->knobs().setFromString("aa.method", "ssaa");
    s->knobs().setFromString("aa.ssaa_factor", "4");
    s->render({{"final", "luminance.stats", "ssaa.lbuffer", "lbuffer"}});
    const FloatImage stats = s->readRaw("luminance.stats"), box = s->readRaw("ssaa.lbuffer"),
                     rendered = s->readRaw("lbuffer");
    ASSERT_EQ(box.width, 40);
    ASSERT_EQ(rendered.width, 160);
    auto lum = [](const FloatImage& img, size_t p) {
        const float* c = &img.pixels[p * img.channels];
        return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    };
    double boxMax = 0.0, renderedMax = 0.0;
    for (size_t p = 0; p < static_cast<size_t>(box.width) * box.height; ++p) boxMax = std::max(boxMax, lum(box, p));
    for (size_t p = 0; p < static_cast<size_t>(rendered.width) * rendered.height; ++p)
        renderedMax = std::max(renderedMax, lum(rendered, p));
    std::printf("spheres 40x24, ssaa 4x4: L_max of the output pixels %.5f, of the rendered pixels %.5f; stats max %.5f, "
                "count %.0f\n", boxMax, renderedMax, stats.pixels[1], stats.pixels[3]);
    EXPECT_EQ(stats.pixels[3], 40.0f * 24.0f);
    EXPECT_NEAR(stats.pixels[1], boxMax, 1e-4 * boxMax);
    EXPECT_GT(renderedMax, boxMax * 1.01) << "the case needs a highlight smaller than a pixel";
}

namespace {

std::unique_ptr<RenderSession> taaSession() {
    auto s = test::makeSession(64, 36);
    s->loadScene("spheres");
    for (const char* k : {"ao.enabled=false", "bloom.enabled=false", "tonemap.auto_exposure=false", "aa.method=taa"})
        s->knobs().applyAssignment(k);
    return s;
}

}  // namespace

// A still camera: the exponential blend of the jittered frames comes to
// rest near their mean (the jitter cycles through kJitterPeriod points),
// much nearer than the pixel centres' image is, on the pixels where the
// jitter matters (edges) and over the whole image.
TEST(Antialiasing, TaaOnAStillCameraConvergesToTheMeanOfItsJitteredFrames) {
    auto s = taaSession();
    s->knobs().setFromString("aa.taa_blend", "1");  // the jittered frame alone
    FloatImage mean;
    for (int i = 0; i < TaaPass::kJitterPeriod; ++i) {
        s->render();
        const FloatImage f = s->readRaw("final");
        if (i == 0) mean = FloatImage{f.width, f.height, f.channels, std::vector<float>(f.pixels.size(), 0.0f)};
        for (size_t p = 0; p < f.pixels.size(); ++p) mean.pixels[p] += f.pixels[p] / TaaPass::kJitterPeriod;
    }
    s->knobs().setFromString("aa.taa_blend", "0.1");
    for (int i = 0; i < 6 * TaaPass::kJitterPeriod; ++i) s->render();
    const FloatImage converged = s->readRaw("final");
    s->knobs().setFromString("aa.method", "none");
    s->render();
    const FloatImage centres = s->readRaw("final");
    std::vector<size_t> edges;
    for (size_t p = 0; p < static_cast<size_t>(mean.width) * mean.height; ++p)
        if (std::fabs(centres.pixels[p * 4 + 1] - mean.pixels[p * 4 + 1]) > 0.05f) edges.push_back(p);
    ASSERT_GT(edges.size(), 20u);
    const double taaEdge = meanAbs(converged, mean, &edges), noneEdge = meanAbs(centres, mean, &edges);
    const double taaAll = meanAbs(converged, mean);
    std::printf("TAA after %d still frames: mean |TAA - jittered mean| %.4f on %zu edge pixels (pixel centres %.4f), "
                "%.4f over the image\n", 6 * TaaPass::kJitterPeriod, taaEdge, edges.size(), noneEdge, taaAll);
    EXPECT_LT(taaEdge, 0.5 * noneEdge);
    EXPECT_LT(taaAll, 0.02);
}

// A camera that moves sideways brings new pixels in at the side it moves
// to: their history is off screen, thrown away, and taa.rejected says so;
// on a still camera few pixels are rejected.
TEST(Antialiasing, TaaRejectsTheHistoryOfPixelsACameraMoveBringsIntoView) {
    auto s = taaSession();
    const FrameRequest request{{"final", "taa.rejected"}};
    for (int i = 0; i < 20; ++i) s->render(request);
    auto fraction = [](const FloatImage& r, int x0, int x1) {
        double sum = 0.0;
        for (int y = 0; y < r.height; ++y)
            for (int x = x0; x < x1; ++x) sum += r.pixels[(static_cast<size_t>(y) * r.width + x) * r.channels];
        return sum / ((x1 - x0) * r.height);
    };
    const FloatImage still = s->readRaw("taa.rejected");
    const double stillAll = fraction(still, 0, still.width);
    Camera& c = s->camera();
    const glm::vec3 forward = glm::normalize(c.target - c.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    const float step = 0.15f * glm::length(c.target - c.position);
    c.position += right * step;
    c.target += right * step;
    s->render(request);
    const FloatImage moved = s->readRaw("taa.rejected");
    const double movedAll = fraction(moved, 0, moved.width), movedRight = fraction(moved, moved.width - 2, moved.width);
    std::printf("taa.rejected: still %.4f of the pixels; after a move %.4f, the 2 columns brought into view %.4f\n",
                stillAll, movedAll, movedRight);
    EXPECT_LT(stillAll, 0.05);
    EXPECT_GT(movedAll, stillAll);
    EXPECT_GT(movedRight, 0.5);
    EXPECT_TRUE(allFinite(s->readRaw("final")));
}

namespace {

double sum(const FloatImage& img) {
    double total = 0.0;
    for (size_t p = 0; p < static_cast<size_t>(img.width) * img.height; ++p) total += img.pixels[p * img.channels];
    return total;
}

}  // namespace

// aa.edges marks silhouettes (spheres against the floor and the sky) and
// nothing on a plane facing the camera, whose samples agree everywhere.
TEST(Antialiasing, MsaaEdgesMarkSilhouettesAndNothingOnAPlaneFacingTheCamera) {
    auto s = test::makeSession(160, 90);
    s->loadScene("spheres");
    s->knobs().setFromString("aa.method", "msaa");
    s->render({{"final", "aa.edges"}});
    const FloatImage spheres = s->readRaw("aa.edges");
    const double marked = sum(spheres);
    std::printf("aa.edges on spheres at 160x90: %.0f pixels\n", marked);
    EXPECT_GT(marked, 200.0);
    EXPECT_LT(marked, 0.4 * 160 * 90);  // edges, not the whole image

    Scene plane = test::planeScene(400.0f);
    plane.camera.position = {0.0f, 10.0f, 0.0f};
    plane.camera.target = {0.0f, 0.0f, 0.0f};
    plane.camera.up = {0.0f, 0.0f, -1.0f};
    s->setScene(plane);
    s->knobs().setFromString("aa.method", "msaa");
    s->render({{"final", "aa.edges"}});
    EXPECT_EQ(sum(s->readRaw("aa.edges")), 0.0);
    // It was a surface everywhere (no background sample to disagree with).
    const FloatImage albedo = s->readRaw("gbuffer.albedo");
    for (size_t p = 0; p < static_cast<size_t>(albedo.width) * albedo.height; ++p)
        ASSERT_GT(albedo.pixels[p * 4 + 3], 0.0f) << p;
}

// aa.samples above what the device offers is capped to it, and the frame says so in one line.
TEST(Antialiasing, MsaaSamplesAboveTheDeviceCapAreCappedAndSaid) {
    auto s = test::makeSession(32, 18);
    s->loadScene("spheres");
    s->knobs().setFromString("aa.method", "msaa");
    const int cap = MsaaPass::deviceCap();
    std::printf("MSAA: the device offers %d samples for the G-buffer's formats\n", cap);
    if (cap >= 16) GTEST_SKIP() << "the device offers 16 samples: nothing to cap";
    s->knobs().setFromString("aa.samples", "16");
    const FrameReport r = s->render({{"final", "aa.edges"}});
    const std::string line = "aa.samples 16 is capped to " + std::to_string(cap) + ": the device offers " +
                             std::to_string(cap) + " samples for the G-buffer's formats";
    ASSERT_EQ(r.warnings().size(), 1u);
    EXPECT_NE(r.warnings().front().find(line), std::string::npos) << r.warnings().front();
    EXPECT_EQ(r.warnings().front().find('\n'), std::string::npos);
    EXPECT_NE(r.find("msaa")->stats.find(std::to_string(cap) + " samples (aa.samples = 16 capped)"), std::string::npos)
        << r.find("msaa")->stats;
    EXPECT_EQ(s->pipeline().outputs().find("gbuffer.ms.depth")->desc.samples, cap);
    // Within the cap: no line.
    s->knobs().setFromString("aa.samples", "2");
    EXPECT_TRUE(s->render({{"final"}}).warnings().empty());
    EXPECT_EQ(s->pipeline().outputs().find("gbuffer.ms.depth")->desc.samples, 2);
}

// MSAA's code paths (the geometry pass's multisampled target, the lighting
// pass's sample loop) leave the other methods alone: their images are the
// same bits before and after an MSAA frame in the same session.
TEST(Antialiasing, TheOtherMethodsImagesAreBitIdenticalAroundAnMsaaFrame) {
    auto s = test::makeSession(40, 24);
    s->loadScene("default");
    for (const char* k : {"bloom.enabled=false", "tonemap.auto_exposure=false"}) s->knobs().applyAssignment(k);
    for (const char* method : {"none", "fxaa", "ssaa"}) {
        s->knobs().setFromString("aa.method", method);
        s->render({{"final", "lbuffer"}});
        const FloatImage before = s->readRaw("final"), lbefore = s->readRaw("lbuffer");
        s->knobs().setFromString("aa.method", "msaa");
        s->render({{"final", "lbuffer"}});
        s->knobs().setFromString("aa.method", method);
        s->render({{"final", "lbuffer"}});
        EXPECT_EQ(before.pixels, s->readRaw("final").pixels) << method;
        EXPECT_EQ(lbefore.pixels, s->readRaw("lbuffer").pixels) << method;
    }
}
