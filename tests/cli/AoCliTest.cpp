// The AO methods from the command line (issue 22): the renamed knob warns
// and works, --buffer ao compares the filtered AO against the ray-traced AO,
// and list knobs names every method.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "renderer/io/ImageIO.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {
test::CommandResult run(const std::string& args) { return test::runWorkbench(args); }
}  // namespace

TEST(AoCli, TheOldKnobNameWorksWithAWarning) {
    const fs::path dir = test::tempDir() / "ao-cli";
    fs::create_directories(dir);
    const auto r = run("render --scene spheres --size 32x18 --set ssao.enabled=false --set lighting.ambient_occlusion=ssao "
                       "--timings --out " + (dir / "a.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("warning: knob 'ssao.enabled' is now 'ao.enabled'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("warning: knob 'lighting.ambient_occlusion': value 'ssao' is now 'screen'"), std::string::npos)
        << r.err;
    // Once each, although the settings are applied more than once.
    EXPECT_EQ(r.err.find("ssao.enabled", r.err.find("ssao.enabled") + 1), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("skipped: switched off (ao.enabled = false)"), std::string::npos) << r.out;
}

TEST(AoCli, ComparesEachMethodsAoAgainstTheRayTracedAo) {
    const fs::path dir = test::tempDir() / "ao-cli";
    fs::create_directories(dir);
    for (const char* method : {"ssao", "gtao"}) {
        const fs::path json = dir / (std::string(method) + ".json");
        const auto r = test::runCommand("DW_REFERENCE_CACHE=" + (dir / "cache").string() + " " + DW_WORKBENCH_BINARY +
                                        std::string(" compare --against reference --scene spheres --size 48x27 --ao-rays 16 "
                                                    "--buffer ao --warn 1 --fail 1 --json ") +
                                        json.string() + " --b ao.method=" + method);
        ASSERT_EQ(r.code, 0) << method << r.err;
        EXPECT_NE(r.out.find("ao.filtered"), std::string::npos) << r.out;
        std::ifstream jf(json);
        const auto j = nlohmann::json::parse(jf);
        // The AO of spheres on a floor: near the truth, not equal to it.
        EXPECT_GT(j["rms"].get<double>(), 0.0) << method;
        EXPECT_LT(j["rms"].get<double>(), 0.25) << method;
    }
    const auto knobs = run("list knobs");
    for (const char* k : {"ao.method", "ao.enabled", "gtao.slices", "gtao.steps", "gtao.radius", "gtao.thickness"})
        EXPECT_NE(knobs.out.find(k), std::string::npos) << k;
}

TEST(AoCli, AMethodsOwnBufferIsWrittenOnlyUnderItsKnobs) {
    const fs::path dir = test::tempDir() / "ao-cli";
    fs::create_directories(dir);
    const std::string common = "render --scene spheres --size 32x18 --buffer gtao.noisy --out " + (dir / "n.exr").string();
    auto r = run(common);
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.err.find("gtao.noisy is written only with ao.method=gtao (now ssao)"), std::string::npos) << r.err;
    r = run(common + " --set ao.method=gtao");
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.err.find("gtao.noisy is not written under the current knobs"), std::string::npos) << r.err;
    r = run(common + " --set ao.method=gtao --set gtao.denoise=edge_aware");
    ASSERT_EQ(r.code, 0) << r.err;
    const FloatImage noisy = loadImageFloat((dir / "n.exr").string());
    EXPECT_EQ(noisy.width, 32);  // gtao.resolution = full
    EXPECT_GT(test::stats(noisy, 0).max, 0.0);
}

// Issue 22: render, bench and tradeoff estimate AOV's volume fragments per
// pixel from the triangles before the first frame and warn, naming the knob,
// above AovCostEstimate's limits. At aov.radius 20 every volume of the
// courtyard covers most of the screen (about 34 a pixel at the default 1: no
// warning). An 8x4 accessibility buffer keeps the frames short.
TEST(AoCli, AovWarnsAboutAFrameThatWouldTakeMinutes) {
    const fs::path dir = test::tempDir() / "ao-cli";
    fs::create_directories(dir);
    const std::string common = "--scene default --size 32x18 --set ao.method=aov --set aov.resolution=quarter ";
    auto r = run("render " + common + "--set aov.radius=20 --out " + (dir / "aov.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("warning: aov: about "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("lower aov.radius"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("at aov.radius 20 world units"), std::string::npos) << r.err;
    r = run("render " + common + "--out " + (dir / "aov1.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning: aov"), std::string::npos) << r.err;
    // bench names the configuration over the limit, not the one under it.
    r = run("bench " + common + "--sweep aov.radius=1,20 --frames 1 --warmup 0 --no-lpp --csv " +
            (dir / "aov.csv").string() + " --json " + (dir / "aov.json").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("bench: warning: configuration 1 (32x18): aov: about "), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("bench: warning: configuration 0"), std::string::npos) << r.err;
    // compare warns for the rendered side over the limit (--b), not for the one under it.
    r = run("compare --scene default --size 32x18 --a ao.method=aov,aov.resolution=quarter "
            "--b ao.method=aov,aov.resolution=quarter,aov.radius=20");
    EXPECT_NE(r.err.find("compare: warning: side --b: aov: about "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("a frame on llvmpipe"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("side --a:"), std::string::npos) << r.err;
}

TEST(AoCli, TheOldBufferNamesSayWhatTheyAreCalledNow) {
    const fs::path dir = test::tempDir() / "ao-cli";
    fs::create_directories(dir);
    for (const auto& [was, is] : {std::pair{"ssao.raw", "ao.raw"}, std::pair{"ssao.blurred", "ao.filtered"}}) {
        const auto r = run(std::string("render --scene spheres --size 32x18 --buffer ") + was + " --out " +
                           (dir / "old.exr").string());
        EXPECT_NE(r.code, 0) << was;
        EXPECT_NE(r.err.find(std::string("unknown buffer '") + was + "': renamed to '" + is + "'"), std::string::npos)
            << r.err;
    }
    // Any other unknown name is only unknown.
    const auto r = run("render --scene spheres --size 32x18 --buffer ssao.nothing --out " + (dir / "old.exr").string());
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.err.find("unknown buffer 'ssao.nothing'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("renamed"), std::string::npos) << r.err;
}
