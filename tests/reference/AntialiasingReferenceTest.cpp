// Issue 35 part 2: an anti-aliasing method against the truth of the pixel's
// area, the reference's 16-sample box average (`reference --spp 16`). SSAA
// 4x4 estimates the same integral with a regular grid, so on the pixels at
// geometry edges (depth discontinuities) its L-buffer (ssaa.lbuffer) is
// within two of the reference's standard errors (reference.spp_error) on the
// mean over those pixels, and nearer the reference than the pixel centres
// (aa.method=none) are.
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

}  // namespace

TEST(AntialiasingAgainstReference, Ssaa4x4IsWithinTwoStandardErrorsOfTheFootprintOnGeometryEdges) {
    RunConfig run;
    run.scene = "default";
    run.sets = kAccurate;
    run.width = kW;
    run.height = kH;
    auto session = test::makeSession(kW, kH);
    session->loadScene("default", run);
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

    reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(session->knobs(), session->scene());
    model.pixelSamples = 16;
    reference::ReferenceRequest r;
    r.camera = session->camera();
    r.width = kW;
    r.height = kH;
    const reference::ReferenceImages ref = reference::renderReference(session->scene(), model, r);

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

}  // namespace dw
