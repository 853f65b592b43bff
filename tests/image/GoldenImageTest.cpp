// Golden images of the built-in scenes and the example scene on llvmpipe, with
// max and mean error thresholds (OpenImageIO's comparison). Regenerate after an
// intended change with DW_UPDATE_GOLDENS=1 and look at the new images.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "renderer/io/ImageIO.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

struct Golden {
    std::string name;
    std::string scene;
    std::string buffer;
    std::vector<std::string> sets = {};
};

// How gtest names a failing case.
void PrintTo(const Golden& g, std::ostream* os) { *os << g.name << " (" << g.scene << ", " << g.buffer << ")"; }

void checkGolden(const Golden& g) {
    auto session = test::makeSession(192, 108);
    session->loadScene(g.scene);
    for (const auto& a : g.sets) session->knobs().applyAssignment(a);
    session->render({{g.buffer}});
    const FloatImage got = session->readDisplay(g.buffer);
    const fs::path golden = test::goldenDir() / (g.name + ".png");
    const char* update = std::getenv("DW_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        writeImage(golden.string(), got);
        GTEST_SKIP() << "wrote " << golden;
    }
    ASSERT_TRUE(fs::exists(golden)) << golden << " is missing; run with DW_UPDATE_GOLDENS=1 to create it";
    const FloatImage want = loadImageFloat(golden.string());
    const ImageDifference d = compareImages(got, want, 8.0f / 255.0f);
    const fs::path actual = test::tempDir() / (g.name + ".actual.png");
    writeImage(actual.string(), got);
    // llvmpipe is deterministic; the margins absorb rasteriser and libm changes
    // between Mesa versions, not changes in shading.
    EXPECT_LT(d.meanError, 2.0 / 255.0) << g.name << " (actual image: " << actual << ")";
    EXPECT_LT(static_cast<double>(d.failCount) / static_cast<double>(d.pixelCount), 0.01)
        << g.name << ": " << d.failCount << " pixels off by more than 8/255, worst " << d.maxError << " at (" << d.maxX
        << ", " << d.maxY << "); actual image: " << actual;
    EXPECT_LT(d.maxError, 0.5) << g.name;
}

}  // namespace

class GoldenImage : public ::testing::TestWithParam<Golden> {};

TEST_P(GoldenImage, MatchesTheStoredImage) { checkGolden(GetParam()); }

INSTANTIATE_TEST_SUITE_P(
    Scenes, GoldenImage,
    ::testing::Values(Golden{"default", "default", "final"}, Golden{"street", "street", "final"},
                      Golden{"spheres", "spheres", "final"},
                      Golden{"spotlights", std::string(DW_TEST_SCENES_DIR) + "/spotlights.json", "final"},
                      Golden{"default-normals", "default", "gbuffer.normal"},
                      Golden{"default-depth", "default", "gbuffer.depth"},
                      Golden{"default-ssao", "default", "ao.filtered"},
                      Golden{"default-overlap", "default", "lighting.overlap"},
                      Golden{"spheres-cube-shadow-map", "spheres", "shadow.cubes", {"shadows.map_size=128"}},
                      Golden{"street-bloom", "street", "bloom.result"}),
    [](const ::testing::TestParamInfo<Golden>& param) {
        std::string n = param.param.name;
        for (char& c : n)
            if (c == '-') c = '_';
        return n;
    });
