// The GPU's L-buffer against the CPU reference (issue "Ground truth and error
// metrics", how it will be checked): with every approximation at its most
// accurate setting the two agree within a stated tolerance on the built-in
// scenes; with shadows on, the shadow maps' error is what remains, and it
// shrinks as the maps grow; a smaller light-volume threshold gives a smaller
// error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "renderer/RunConfig.h"
#include "renderer/reference/LuminanceReference.h"
#include "renderer/reference/ReferenceRenderer.h"
#include "renderer/reference/SsaoDefinition.h"
#include "renderer/scene/SceneLoader.h"
#include "tests/support/TestSupport.h"

namespace dw {
namespace {

constexpr int kW = 160, kH = 90;

// The most accurate GPU settings (the list).
const std::vector<std::string> kAccurate = {"lighting.strategy=fullscreen", "lighting.threshold=1e-5",
                                            "ao.enabled=false", "gbuffer.material_format=unorm16",
                                            "gbuffer.texture_filter=base_level", "shadows.enabled=false"};

struct Agreement {
    double meanRelative = 0.0;  // mean over pixels of |gpu - ref| / (ref + floor), luminance
    double p99Relative = 0.0;   // its 99th percentile
    double meanAbsolute = 0.0;  // mean |gpu - ref| luminance
    int pixels = 0;
};

Agreement compare(const FloatImage& gpu, const FloatImage& ref) {
    Agreement a;
    std::vector<double> rel;
    double sumAbs = 0.0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const float* g = &gpu.pixels[(static_cast<size_t>(y) * gpu.width + x) * gpu.channels];
            const float* r = &ref.pixels[(static_cast<size_t>(y) * ref.width + x) * ref.channels];
            const double lg = reference::luminance(g[0], g[1], g[2]), lr = reference::luminance(r[0], r[1], r[2]);
            const double d = std::abs(lg - lr);
            sumAbs += d;
            rel.push_back(d / (lr + 1e-3));
        }
    a.pixels = static_cast<int>(rel.size());
    a.meanAbsolute = sumAbs / a.pixels;
    double sum = 0.0;
    for (double v : rel) sum += v;
    a.meanRelative = sum / a.pixels;
    std::sort(rel.begin(), rel.end());
    a.p99Relative = rel[static_cast<size_t>(0.99 * (rel.size() - 1))];
    return a;
}

struct Pair {
    FloatImage gpu, ref;
};

Pair renderBoth(const std::string& sceneName, const std::vector<std::string>& sets, int aoRays = 16, int spp = 1) {
    RunConfig run;
    run.scene = sceneName;
    run.sets = sets;
    run.width = kW;
    run.height = kH;
    auto session = test::makeSession(kW, kH);
    session->loadScene(sceneName, run);
    FrameRequest request;
    request.outputs = {"lbuffer"};
    session->render(request);
    Pair p;
    p.gpu = session->readRaw("lbuffer");
    const Scene& scene = session->scene();
    reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(session->knobs(), scene);
    model.aoRays = aoRays;
    reference::ReferenceRequest r;
    model.pixelSamples = spp;
    r.camera = session->camera();
    r.width = kW;
    r.height = kH;
    p.ref = reference::renderReference(scene, model, r).lbuffer;
    return p;
}

class GpuAgreesWithReference : public ::testing::TestWithParam<std::string> {};

TEST_P(GpuAgreesWithReference, AtTheMostAccurateSettings) {
    const Pair p = renderBoth(GetParam(), kAccurate);
    ASSERT_EQ(p.gpu.width, p.ref.width);
    const Agreement a = compare(p.gpu, p.ref);
    std::printf("%s: mean relative %.5f, 99th percentile %.5f, mean absolute %.6f over %d pixels\n", GetParam().c_str(),
                a.meanRelative, a.p99Relative, a.meanAbsolute, a.pixels);
    // Stated tolerance (docs/reference.md): what remains is float arithmetic,
    // the 16-bit G-buffer normals and the threshold's cut at 1e-5. Measured at
    // 160x90: mean 0.19% / 0.22% / 0.17%, 99th percentile 0.92% / 0.68% / 0.81%
    // (default, spheres, street).
    EXPECT_LT(a.meanRelative, 0.005);
    EXPECT_LT(a.p99Relative, 0.02);
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, GpuAgreesWithReference, ::testing::Values("default", "spheres", "street"));

// Transparency (issue 21): the per-pixel linked list is exact, so on the
// glass scene (depth complexity above 8) it matches the reference, which
// composites every blended hit along the ray in exact order; the weighted
// approximation and the object-sorted forward pass do not, by a measured margin.
TEST(GpuAgreesWithReference, LinkedListOitMatchesTheReferenceOnGlass) {
    std::vector<std::string> sets = kAccurate;
    sets.push_back("oit.method=linked_list");
    const Pair exact = renderBoth("glass", sets);
    const Agreement a = compare(exact.gpu, exact.ref);
    std::printf("glass, linked list: mean relative %.5f, 99th percentile %.5f, mean absolute %.6f\n", a.meanRelative,
                a.p99Relative, a.meanAbsolute);
    // The list stores premultiplied colour as half floats (relative 5e-4 a layer).
    EXPECT_LT(a.meanRelative, 0.005);
    EXPECT_LT(a.p99Relative, 0.03);
    for (const char* method : {"weighted", "forward_sorted"}) {
        std::vector<std::string> s = kAccurate;
        s.push_back(std::string("oit.method=") + method);
        const Pair p = renderBoth("glass", s);
        const Agreement b = compare(p.gpu, p.ref);
        std::printf("glass, %s: mean relative %.5f, 99th percentile %.5f, mean absolute %.6f\n", method, b.meanRelative,
                    b.p99Relative, b.meanAbsolute);
        EXPECT_GT(b.meanAbsolute, 2.0 * a.meanAbsolute) << method;
    }
}

// Issue 35: with mip-mapped textures (the default) the GPU filters each
// pixel's footprint; the reference of the pixel's area (16 samples a pixel)
// is nearer to it than the reference of the pixel's centre, in RMS and at
// the 99th percentile, where everything else is at its most accurate.
TEST(GpuAgreesWithReference, TheFootprintReferenceIsNearerTheMipMappedImageThanThePixelCentre) {
    std::vector<std::string> sets = kAccurate;
    sets.erase(std::find(sets.begin(), sets.end(), "gbuffer.texture_filter=base_level"));
    const Pair centre = renderBoth("default", sets, 16, 1), area = renderBoth("default", sets, 16, 16);
    const auto rms = [](const FloatImage& a, const FloatImage& b) {
        double sum = 0.0;
        for (size_t p = 0; p < a.pixels.size() / 4; ++p) {
            const double d = reference::luminance(a.pixels[p * 4], a.pixels[p * 4 + 1], a.pixels[p * 4 + 2]) -
                             reference::luminance(b.pixels[p * 4], b.pixels[p * 4 + 1], b.pixels[p * 4 + 2]);
            sum += d * d;
        }
        return std::sqrt(sum / static_cast<double>(a.pixels.size() / 4));
    };
    const Agreement a1 = compare(centre.gpu, centre.ref), a16 = compare(area.gpu, area.ref);
    const double r1 = rms(centre.gpu, centre.ref), r16 = rms(area.gpu, area.ref);
    std::printf("default, mip-mapped GPU against the reference: 1 spp RMS %.5f, p99 %.4f, mean %.4f; 16 spp RMS %.5f, "
                "p99 %.4f, mean %.4f\n", r1, a1.p99Relative, a1.meanRelative, r16, a16.p99Relative, a16.meanRelative);
    EXPECT_LT(r16, r1);
    EXPECT_LT(a16.p99Relative, a1.p99Relative);
}

TEST(GpuAgreesWithReference, ShadowMapErrorShrinksAsTheMapGrows) {
    std::vector<std::string> sets = kAccurate;
    sets.back() = "shadows.enabled=true";
    sets.push_back("shadows.pcf_radius=0");
    double previous = 1e30;
    for (const char* size : {"128", "512", "2048"}) {
        std::vector<std::string> s = sets;
        s.push_back(std::string("shadows.map_size=") + size);
        const Pair p = renderBoth("spheres", s);
        const Agreement a = compare(p.gpu, p.ref);
        std::printf("spheres, shadow map %s: mean absolute %.6f, mean relative %.5f\n", size, a.meanAbsolute, a.meanRelative);
        EXPECT_LT(a.meanAbsolute, previous) << "map size " << size;
        previous = a.meanAbsolute;
    }
}

TEST(GpuAgreesWithReference, SmallerThresholdSmallerError) {
    double previous = 1e30;
    for (const char* threshold : {"0.1", "0.01", "0.001"}) {
        std::vector<std::string> s = kAccurate;
        s[0] = "lighting.strategy=stencil_volumes";
        s[1] = std::string("lighting.threshold=") + threshold;
        const Pair p = renderBoth("default", s);
        const Agreement a = compare(p.gpu, p.ref);
        std::printf("default, threshold %s: mean absolute %.6f, mean relative %.5f\n", threshold, a.meanAbsolute,
                    a.meanRelative);
        EXPECT_LT(a.meanAbsolute, previous) << "threshold " << threshold;
        previous = a.meanAbsolute;
    }
}

// How much of SSAO's error against the ray-traced AO comes from its
// definition (a kernel in the ball tested against the first surface seen
// through each point, not cosine-weighted visibility): SSAO's own estimator
// evaluated exactly (SsaoDefinition) stands between the two.
TEST(GpuAgreesWithReference, SsaoErrorSplitsIntoItsDefinitionAndItsScreenSpaceApproximation) {
    for (const std::string sceneName : {"default", "spheres"}) {
        const int w = 96, h = 54;
        RunConfig run;
        run.scene = sceneName;
        run.width = w;
        run.height = h;
        auto session = test::makeSession(w, h);
        session->loadScene(sceneName, run);
        FrameRequest request;
        request.outputs = {"ao.filtered"};
        session->render(request);
        const FloatImage gpu = session->readRaw("ao.filtered");
        const Scene& scene = session->scene();
        reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(session->knobs(), scene);
        model.aoRays = 256;
        reference::ReferenceRequest r;
        r.camera = session->camera();
        r.width = w;
        r.height = h;
        const auto ref = reference::renderReference(scene, model, r);
        const FloatImage def =
            reference::ssaoDefinitionAo(scene, r, reference::SsaoDefinitionSettings::fromKnobs(session->knobs(), scene));
        double total = 0, definition = 0, screen = 0;
        int n = 0;
        for (size_t p = 0; p < ref.background.size(); ++p) {
            if (ref.background[p]) continue;
            const double g = gpu.pixels[p * gpu.channels], a = ref.ao.pixels[p], d = def.pixels[p];
            total += std::abs(g - a);
            definition += std::abs(d - a);
            screen += std::abs(g - d);
            ++n;
        }
        total /= n;
        definition /= n;
        screen /= n;
        std::printf("%s: SSAO (default knobs) vs ray-traced AO: mean |error| %.4f; its definition's part (exact SSAO vs "
                    "ray-traced) %.4f; the screen-space part (GPU SSAO vs exact SSAO) %.4f; AO standard error %.4f\n",
                    sceneName.c_str(), total, definition, screen, ref.stats.aoStandardErrorMean);
        // The triangle inequality holds by construction; the test is that each part is measured and finite.
        EXPECT_LE(total, definition + screen + 1e-9);
        EXPECT_GT(definition, 0.0);
        EXPECT_GT(screen, 0.0);
        EXPECT_LT(total, 0.5);
    }
}

}  // namespace
}  // namespace dw
