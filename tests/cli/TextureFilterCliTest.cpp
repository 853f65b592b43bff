// gbuffer.texture_filter as a trade (issue 35 part 3), from the command line:
// every value renders a textured glTF with finite values; on the oblique
// checker plane (scenes/oblique-checker.json) the base level keeps the
// checker's full contrast (it aliases) and mip-mapping blurs it to grey
// towards the horizon; where the device filters anisotropically each level
// keeps more of it than the one before, so each differs from mipmap; on
// llvmpipe every aniso level is capped to mipmap's image with the reason in
// one line, and the case that spun for minutes there (a grazing angle over a
// texture repeated thousands of times) renders in bounded time; a level above
// the device's GL_MAX_TEXTURE_MAX_ANISOTROPY is capped and said.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "renderer/io/ImageIO.h"
#include "renderer/passes/GeometryPass.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

const char* const kFilters[] = {"base_level", "mipmap", "aniso2", "aniso4", "aniso8", "aniso16"};

fs::path dir() {
    const fs::path d = test::tempDir() / "texture-filter-cli";
    fs::create_directories(d);
    return d;
}

// `render` of `scene`'s buffer with gbuffer.texture_filter = `filter`, checked finite; its image.
FloatImage rendered(const std::string& scene, const std::string& filter, const std::string& buffer,
                    const std::string& size = "160x90", const std::string& prefix = "") {
    const fs::path out = dir() / (fs::path(scene).stem().string() + "-" + filter + "-" + buffer + ".exr");
    const test::CommandResult r = test::runCommand(prefix + DW_WORKBENCH_BINARY + std::string(" render --scene ") + scene +
                                                   " --size " + size + " --set gbuffer.texture_filter=" + filter +
                                                   " --buffer " + buffer + " --check-finite --out " + out.string());
    EXPECT_EQ(r.code, 0) << filter << ": " << r.err << r.out;
    EXPECT_NE(r.out.find("no NaN or infinity"), std::string::npos) << filter << ": " << r.out;
    return r.code == 0 ? loadImageFloat(out.string()) : FloatImage{};
}

// The standard deviation of the albedo's luminance over the surface pixels
// (alpha 1/255 and up): the checker's contrast left after filtering.
double contrast(const FloatImage& albedo) {
    double sum = 0.0, sumSq = 0.0;
    long n = 0;
    const size_t c = static_cast<size_t>(albedo.channels);
    for (size_t p = 0; c >= 4 && p * c + 3 < albedo.pixels.size(); ++p) {
        const float* px = &albedo.pixels[p * c];
        if (px[3] <= 0.0f) continue;  // the background
        const double l = 0.2126 * px[0] + 0.7152 * px[1] + 0.0722 * px[2];
        sum += l;
        sumSq += l * l;
        ++n;
    }
    if (n < 2) return 0.0;
    const double mean = sum / n;
    return std::sqrt(std::max(0.0, sumSq / n - mean * mean));
}

// Whether the GL renderer the CLI gets is llvmpipe (render --verbose names it).
bool onLlvmpipe() {
    static const bool llvmpipe = [] {
        const test::CommandResult r =
            test::runWorkbench("render --scene default --size 8x8 --verbose --out " + (dir() / "verbose.png").string());
        return (r.out + r.err).find("llvmpipe") != std::string::npos;
    }();
    return llvmpipe;
}

const std::string kLlvmpipeCap =
    " is capped to 1x (mipmap) on llvmpipe: its anisotropic lookups spin for minutes at a grazing angle over a texture "
    "repeated thousands of times (Mesa 22.3)";

double meanDifference(const FloatImage& a, const FloatImage& b) {
    if (a.pixels.size() != b.pixels.size() || a.pixels.empty()) return 0.0;
    double d = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) d += std::abs(a.pixels[i] - b.pixels[i]);
    return d / static_cast<double>(a.pixels.size());
}

}  // namespace

TEST(TextureFilterCli, EveryValueRendersATexturedGltfWithFiniteValues) {
    const fs::path gltf = test::dataDir() / "gltf" / "BoxTextured" / "BoxTextured.gltf";
    if (!fs::exists(gltf)) GTEST_SKIP() << gltf << " is not here (../shared/data)";
    std::map<std::string, FloatImage> images;
    for (const char* f : kFilters) {
        images[f] = rendered(gltf.string(), f, "final", "96x54");
        ASSERT_EQ(images[f].width, 96) << f;
        for (float v : images[f].pixels) ASSERT_TRUE(std::isfinite(v)) << f;
    }
    // A box of one texture seen square on: the filters are all near one another, but not all the same.
    EXPECT_GT(meanDifference(images["base_level"], images["mipmap"]), 0.0);
}

TEST(TextureFilterCli, AnisotropicLevelsKeepTheObliqueCheckersContrast) {
    const std::string scene = (test::scenesDir() / "oblique-checker.json").string();
    std::map<std::string, double> c;
    std::map<std::string, FloatImage> albedo;
    for (const char* f : kFilters) {
        albedo[f] = rendered(scene, f, "gbuffer.albedo");
        c[f] = contrast(albedo[f]);
    }
    // The base level reads one texel at each pixel's centre: the full
    // checker, aliased; mip-mapping takes the footprint as a square, so the
    // long, thin footprints towards the horizon average rows of squares to grey.
    EXPECT_LT(c["mipmap"], c["base_level"]);
    EXPECT_GT(meanDifference(albedo["base_level"], albedo["mipmap"]), 1e-3);
    if (onLlvmpipe()) {
        // Capped to mipmap (the reason is TheLlvmpipeCapIsSaidAndBoundsTheCaseThatSpun's): the same image.
        for (const char* f : {"aniso2", "aniso4", "aniso8", "aniso16"})
            EXPECT_EQ(albedo[f].pixels, albedo["mipmap"].pixels) << f;
        return;
    }
    // Each anisotropic level takes more lookups along the long axis and keeps more of the checker.
    EXPECT_LT(c["mipmap"], c["aniso2"]);
    EXPECT_LT(c["aniso2"], c["aniso4"]);
    EXPECT_LT(c["aniso4"], c["aniso8"]);
    EXPECT_LE(c["aniso8"], c["aniso16"]);
    EXPECT_LT(c["aniso16"], c["base_level"]);
    for (const char* f : {"aniso2", "aniso4", "aniso8", "aniso16"})
        EXPECT_GT(meanDifference(albedo[f], albedo["mipmap"]), 1e-3) << f << " draws what mipmap draws";
}

// A plane whose texture repeats 2500 times a unit (coordinates up to 1e5),
// seen at a grazing angle: Mesa 22.3's llvmpipe spun for minutes in such
// anisotropic lookups (even aniso2). On llvmpipe the level is capped, said in
// one line, and the frame renders in bounded time (`timeout`); elsewhere the
// device filters it.
TEST(TextureFilterCli, TheLlvmpipeCapIsSaidAndBoundsTheCaseThatSpun) {
    const fs::path scene = dir() / "huge-uv.json";
    std::ofstream(scene) << R"({"name": "huge-uv",
      "camera": {"pos": [0, 0.5, 20], "look-at": [0, 0, -20], "up": [0, 1, 0], "fov": 60, "near": 0.05, "far": 100},
      "lighting": {"ambient": [1, 1, 1], "lights": []},
      "materials": {"checker": {"diffuse": [1, 1, 1], "specular": [0, 0, 0], "shininess": 1,
                                "diffuse-map": ")" + (test::scenesDir() / "textures" / "checker.png").string() + R"("}},
      "objects": [{"shape": "plane", "size": [40, 0, 40], "material": "checker", "uv-scale": 2500}]})";
    const fs::path out = dir() / "huge-uv.exr";
    const test::CommandResult r = test::runCommand(std::string("timeout 120 ") + DW_WORKBENCH_BINARY + " render --scene " +
                                                   scene.string() + " --size 64x36 --set gbuffer.texture_filter=aniso2 "
                                                   "--buffer gbuffer.albedo --check-finite --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("no NaN or infinity"), std::string::npos) << r.out;
    if (onLlvmpipe()) {
        EXPECT_NE(r.err.find("warning: geometry: gbuffer.texture_filter=aniso2" + kLlvmpipeCap + "\n"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    } else {
        EXPECT_EQ(r.err.find("capped"), std::string::npos) << r.err;
    }
}

TEST(TextureFilterCli, ALevelAboveTheDevicesIsCappedAndSaid) {
    EXPECT_EQ(GeometryPass::anisotropyCapLine("aniso16", 8.0f, false),
              "gbuffer.texture_filter=aniso16 is capped to 8x: the device's GL_MAX_TEXTURE_MAX_ANISOTROPY is 8");
    EXPECT_EQ(GeometryPass::anisotropyCapLine("aniso2", 1.0f, false),
              "gbuffer.texture_filter=aniso2 is capped to 1x: the device's GL_MAX_TEXTURE_MAX_ANISOTROPY is 1");
    EXPECT_EQ(GeometryPass::anisotropyCapLine("aniso4", 16.0f, true), "gbuffer.texture_filter=aniso4" + kLlvmpipeCap);
    EXPECT_EQ(GeometryPass::anisotropyCapLine("aniso8", 8.0f, false), "");
    EXPECT_EQ(GeometryPass::anisotropyCapLine("mipmap", 1.0f, true), "");
    EXPECT_EQ(GeometryPass::anisotropyCapLine("base_level", 1.0f, true), "");
    EXPECT_EQ(GeometryPass::requestedAnisotropy("aniso4"), 4.0f);
    EXPECT_EQ(GeometryPass::requestedAnisotropy("mipmap"), 1.0f);
    // The pass's line says the level set and the most it can be here; the
    // warning line says why, once a frame, on render's stderr.
    const test::CommandResult r = test::runWorkbench("render --scene default --size 32x18 --set gbuffer.texture_filter=aniso16 "
                                                     "--timings --out " + (dir() / "cap.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    const auto at = r.out.find("textures aniso16 (anisotropy ");
    ASSERT_NE(at, std::string::npos) << r.out;
    const auto most = r.out.find("up to ", at);
    ASSERT_NE(most, std::string::npos) << r.out;
    const float here = std::stof(r.out.substr(most + 6));
    if (onLlvmpipe()) {
        EXPECT_EQ(here, 1.0f);
        EXPECT_NE(r.out.find("textures aniso16 (anisotropy 1x; up to 1x here)"), std::string::npos) << r.out;
        EXPECT_NE(r.err.find("warning: geometry: gbuffer.texture_filter=aniso16" + kLlvmpipeCap + "\n"), std::string::npos) << r.err;
    } else if (here < 16.0f) {
        EXPECT_NE(r.err.find("warning: geometry: " + GeometryPass::anisotropyCapLine("aniso16", here, false) + "\n"), std::string::npos)
            << r.err;
    } else {
        EXPECT_EQ(r.err.find("capped"), std::string::npos) << r.err;
        EXPECT_NE(r.out.find("textures aniso16 (anisotropy 16x;"), std::string::npos) << r.out;
    }
}
