// Issue 35 part 2: an anti-aliasing method against the truth of the pixel's
// area, the reference's 16-sample box average (`reference --spp 16`). SSAA
// 4x4 estimates the same integral with a regular grid, so on the pixels at
// geometry edges (depth discontinuities) its L-buffer (ssaa.lbuffer) is
// within two of the reference's standard errors (reference.spp_error) on the
// mean over those pixels, and nearer the reference than the pixel centres
// (aa.method=none) are. MSAA 4x (deferred: per-sample shading on its
// aa.edges pixels only) is nearer the reference than the pixel centres on
// those edge pixels, and equals the pixel centres elsewhere (per-pixel
// shading of the same G-buffer: the same values). FXAA and TAA (converged on
// a still camera) work on the display image: on the edge pixels their final
// image is nearer the reference's final image than the pixel centres' is.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "renderer/RunConfig.h"
#include "renderer/reference/LuminanceReference.h"
#include "renderer/reference/ReferenceRenderer.h"
#include "tests/support/TestSupport.h"

namespace dw {
namespace {

constexpr int kW = 64, kH = 36;

// Everything but the pixel's area at its most accurate (ReferenceGpuAgreementTest's list).
const std::vector<std::string> kAccurate = {"lighting.strategy=fullscreen", "lighting.threshold=1e-5",
                                            "ao.enabled=false", "gbuffer.material_format=unorm16",
                                            "gbuffer.texture_filter=base_level", "shadows.enabled=false"};

double lum(const FloatImage& img, int x, int y) {
    const float* p = &img.pixels[(static_cast<size_t>(y) * img.width + x) * img.channels];
    return reference::luminance(p[0], p[1], p[2]);
}

// Pixels at a depth discontinuity. Reversed depth is proportional to
// 1/distance, which is affine in screen space on any plane: its second
// difference along x or y is 0 on a plane (a floor at a grazing angle
// included) and large where the surface changes. A pixel is at an edge when
// a neighbour sees the sky and it does not (or the reverse), or when a
// second difference is over 5% of its depth.
std::vector<std::pair<int, int>> edgePixels(const FloatImage& depth) {
    std::vector<std::pair<int, int>> edges;
    auto d = [&](int x, int y) { return depth.pixels[(static_cast<size_t>(y) * depth.width + x) * depth.channels]; };
    for (int y = 0; y < depth.height; ++y)
        for (int x = 0; x < depth.width; ++x) {
            const float c = d(x, y);
            bool edge = false;
            for (auto [dx, dy] : {std::pair{1, 0}, {0, 1}}) {
                const int x0 = x - dx, y0 = y - dy, x1 = x + dx, y1 = y + dy;
                for (auto [nx, ny] : {std::pair{x0, y0}, {x1, y1}})
                    if (nx >= 0 && ny >= 0 && nx < depth.width && ny < depth.height && (d(nx, ny) <= 0.0f) != (c <= 0.0f))
                        edge = true;
                if (x0 < 0 || y0 < 0 || x1 >= depth.width || y1 >= depth.height) continue;
                if (std::fabs(d(x0, y0) + d(x1, y1) - 2.0f * c) > 0.05f * c) edge = true;
            }
            if (edge) edges.emplace_back(x, y);
        }
    return edges;
}

std::unique_ptr<RenderSession> accurateSession(const std::vector<std::string>& moreSets = {}) {
    RunConfig run;
    run.scene = "default";
    run.sets = kAccurate;
    run.sets.insert(run.sets.end(), moreSets.begin(), moreSets.end());
    run.width = kW;
    run.height = kH;
    auto session = test::makeSession(kW, kH);
    session->loadScene("default", run);
    return session;
}

reference::ReferenceImages footprintReference(RenderSession& session) {
    reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(session.knobs(), session.scene());
    model.pixelSamples = 16;
    reference::ReferenceRequest r;
    r.camera = session.camera();
    r.width = kW;
    r.height = kH;
    return reference::renderReference(session.scene(), model, r);
}

}  // namespace

TEST(AntialiasingAgainstReference, Msaa4IsNearerTheFootprintThanThePixelCentresOnEdgesAndEqualsThemElsewhere) {
    auto session = accurateSession();
    session->knobs().setFromString("aa.method", "none");
    session->render({{"lbuffer", "gbuffer.depth"}});
    const FloatImage centres = session->readRaw("lbuffer");
    const auto edges = edgePixels(session->readRaw("gbuffer.depth"));
    session->knobs().setFromString("aa.method", "msaa");
    session->knobs().setFromString("aa.samples", "4");
    const FrameReport report = session->render({{"lbuffer", "aa.edges"}});
    ASSERT_TRUE(report.find("msaa")->ran) << report.find("msaa")->reason;
    ASSERT_EQ(session->pipeline().outputs().find("gbuffer.ms.depth")->desc.samples, 4) << "the device caps MSAA below 4";
    const FloatImage msaa = session->readRaw("lbuffer"), mask = session->readRaw("aa.edges");
    const reference::ReferenceImages ref = footprintReference(*session);

    ASSERT_GT(edges.size(), 40u);
    double msaaError = 0.0, centreError = 0.0;
    for (auto [x, y] : edges) {
        const double truth = lum(ref.lbuffer, x, y);
        msaaError += std::fabs(lum(msaa, x, y) - truth);
        centreError += std::fabs(lum(centres, x, y) - truth);
    }
    // Elsewhere (aa.edges 0): the per-pixel shading of the pixel centres' G-buffer, none's.
    double worst = 0.0, sumRelative = 0.0;
    int flat = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            if (mask.pixels[(static_cast<size_t>(y) * kW + x) * mask.channels] >= 0.5f) continue;
            const double a = lum(msaa, x, y), b = lum(centres, x, y);
            const double relative = std::fabs(a - b) / (std::fabs(b) + 1e-3);
            worst = std::max(worst, relative);
            sumRelative += relative;
            ++flat;
        }
    const double n = static_cast<double>(edges.size());
    std::printf("default %dx%d, %zu edge pixels: mean |L - L_ref| msaa 4 %.5f, none %.5f; %d pixels off aa.edges: mean "
                "relative difference from none %.5f, largest %.5f\n",
                kW, kH, edges.size(), msaaError / n, centreError / n, flat, sumRelative / flat, worst);
    EXPECT_LT(msaaError, centreError);
    ASSERT_GT(flat, kW * kH / 4);
    EXPECT_LT(sumRelative / flat, 1e-6);
    EXPECT_LT(worst, 1e-5);
}

TEST(AntialiasingAgainstReference, Ssaa4x4IsWithinTwoStandardErrorsOfTheFootprintOnGeometryEdges) {
    auto session = accurateSession();
    ASSERT_EQ(session->knobs().format(*session->knobs().find("depth.mode")), "reversed");
    session->knobs().setFromString("aa.method", "none");
    session->render({{"lbuffer", "gbuffer.depth"}});
    const FloatImage centres = session->readRaw("lbuffer");
    const FloatImage depth = session->readRaw("gbuffer.depth");
    session->knobs().setFromString("aa.method", "ssaa");
    session->knobs().setFromString("aa.ssaa_factor", "4");
    const FrameReport report = session->render({{"ssaa.lbuffer"}});
    ASSERT_TRUE(report.find("ssaa")->ran) << report.find("ssaa")->reason;
    EXPECT_EQ(session->pipeline().renderScale(), 4);
    const FloatImage ssaa = session->readRaw("ssaa.lbuffer");
    ASSERT_EQ(ssaa.width, kW);
    ASSERT_EQ(ssaa.height, kH);

    const reference::ReferenceImages ref = footprintReference(*session);

    const auto edges = edgePixels(depth);
    ASSERT_GT(edges.size(), 40u);
    double ssaaError = 0.0, centreError = 0.0, standardError = 0.0;
    for (auto [x, y] : edges) {
        const double truth = lum(ref.lbuffer, x, y);
        ssaaError += std::fabs(lum(ssaa, x, y) - truth);
        centreError += std::fabs(lum(centres, x, y) - truth);
        standardError += ref.sppError.pixels[static_cast<size_t>(y) * kW + x];
    }
    const double n = static_cast<double>(edges.size());
    std::printf("default %dx%d, %zu edge pixels: mean |L - L_ref| ssaa 4x4 %.5f, none %.5f; reference's mean standard "
                "error (16 spp) %.5f\n", kW, kH, edges.size(), ssaaError / n, centreError / n, standardError / n);
    EXPECT_LT(ssaaError / n, 2.0 * standardError / n);
    EXPECT_LT(ssaaError, centreError);
}

// The post-process methods against the footprint truth of the display image:
// `final` (tone-mapped, sRGB-encoded, as reference.final) on the geometry
// edge pixels, FXAA after one frame and TAA after 48 frames of a still camera
// (its history converged to the mean of its 16 jittered frames), each nearer
// the 16-sample reference than the pixel centres (aa.method=none). Bloom and
// auto exposure off so the GPU and the reference tone-map alike. Measured
// at 64x36 over 569 edge pixels: none 0.0930, fxaa 0.0920, taa 0.0546:
// FXAA moves the edges only a little toward the area mean (over the whole
// image its FLIP is no nearer: docs/antialiasing.md, "The study").
TEST(AntialiasingAgainstReference, FxaaAndConvergedTaaAreNearerTheFootprintThanThePixelCentresOnEdges) {
    auto session = accurateSession({"bloom.enabled=false", "tonemap.auto_exposure=false"});
    const auto finalOf = [&](const std::string& method, int frames) {
        session->knobs().setFromString("aa.method", method);
        for (int i = 1; i < frames; ++i) session->render({{"final"}});
        const FrameReport report = session->render({{"final", "gbuffer.depth"}});
        if (method != "none") {
            EXPECT_TRUE(report.find(method)->ran) << method << ": " << report.find(method)->reason;
        }
        return session->readRaw("final");
    };
    const FloatImage centres = finalOf("none", 1);
    const auto edges = edgePixels(session->readRaw("gbuffer.depth"));
    const FloatImage fxaa = finalOf("fxaa", 1);
    const FloatImage taa = finalOf("taa", 48);
    const reference::ReferenceImages ref = footprintReference(*session);
    ASSERT_EQ(ref.final.width, kW);

    ASSERT_GT(edges.size(), 40u);
    double centreError = 0.0, fxaaError = 0.0, taaError = 0.0;
    for (auto [x, y] : edges) {
        const double truth = lum(ref.final, x, y);
        centreError += std::fabs(lum(centres, x, y) - truth);
        fxaaError += std::fabs(lum(fxaa, x, y) - truth);
        taaError += std::fabs(lum(taa, x, y) - truth);
    }
    const double n = static_cast<double>(edges.size());
    std::printf("default %dx%d, %zu edge pixels: mean |Y - Y_ref| of the display image: none %.5f, fxaa %.5f, "
                "taa (48 frames) %.5f\n", kW, kH, edges.size(), centreError / n, fxaaError / n, taaError / n);
    EXPECT_LT(fxaaError, centreError);
    EXPECT_LT(taaError, centreError);
}

}  // namespace dw
