// Real glTF files nobody here made render as plausibly lit images: the model
// covers part of the frame, is neither black nor blown out, and no buffer
// holds NaN. They skip when the data is absent.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "renderer/gl/DepthConvention.h"
#include "renderer/reference/LuminanceReference.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

void checkPlausible(const fs::path& file) {
    auto session = test::makeSession(160, 120);
    session->loadScene(file.string());
    session->render({{"final", "gbuffer.depth"}});
    const FloatImage final = session->readRaw("final");
    const FloatImage L = session->readRaw("lbuffer");
    const FloatImage depth = session->readRaw("gbuffer.depth");
    long long covered = 0, clipped = 0;
    double lumSum = 0.0, lumSq = 0.0;
    for (int y = 0; y < final.height; ++y)
        for (int x = 0; x < final.width; ++x) {
            for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(L.at(x, y, c))) << file << " NaN/Inf in the L-buffer";
            if (DepthConvention().isFar(depth.at(x, y, 0))) continue;
            ++covered;
            const double l = reference::luminance(final.at(x, y, 0), final.at(x, y, 1), final.at(x, y, 2));
            lumSum += l;
            lumSq += l * l;
            if (final.at(x, y, 0) > 0.995f && final.at(x, y, 1) > 0.995f && final.at(x, y, 2) > 0.995f) ++clipped;
        }
    const double coverage = static_cast<double>(covered) / (final.width * final.height);
    const double n = std::max(static_cast<double>(covered), 1.0);
    const double meanLum = lumSum / n;
    const double spread = std::sqrt(std::max(lumSq / n - meanLum * meanLum, 0.0));
    const double clippedFraction = static_cast<double>(clipped) / n;
    std::printf("%s: coverage %.2f, displayed luminance mean %.3f, spread %.3f, clipped %.3f\n",
                file.filename().c_str(), coverage, meanLum, spread, clippedFraction);
    EXPECT_GT(coverage, 0.02) << file << ": the default camera should frame the model";
    EXPECT_GT(meanLum, 0.08) << file << ": model is nearly black";
    EXPECT_GT(spread, 0.03) << file << ": no shading variation (unlit or flat)";
    EXPECT_LT(clippedFraction, 0.2) << file << ": model is blown out";
}

}  // namespace

TEST(RealScenes, SharedSampleModels) {
    const fs::path dir = test::dataDir() / "gltf";
    if (!fs::exists(dir)) GTEST_SKIP() << "no shared data at " << dir;
    for (const char* f : {"Duck/Duck.gltf", "BoxTextured/BoxTextured.gltf", "NormalTangentTest/NormalTangentTest.gltf",
                          "Suzanne/Suzanne.gltf", "TwoSidedPlane/TwoSidedPlane.gltf", "AlphaBlendModeTest/AlphaBlendModeTest.gltf",
                          "bunny/bunny.gltf", "dragon_res2.glb"})
        checkPlausible(dir / f);
}

TEST(RealScenes, AssimpSampleModels) {
    const fs::path dir = "/usr/share/assimp/models/glTF2";
    if (!fs::exists(dir)) GTEST_SKIP() << "assimp-testmodels is not installed";
    for (const char* f : {"BoxTextured-glTF-Binary/BoxTextured.glb", "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf",
                          "2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "ClearCoat-glTF/ClearCoatTest.gltf"})
        checkPlausible(dir / f);
}
