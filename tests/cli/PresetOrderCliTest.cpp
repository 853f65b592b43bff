// Repeated --preset (issue 22: the GTAO and AOV presets cover only the AO
// knobs and combine with Low/Medium/High): the presets apply in the order
// given, a later one's knob over an earlier one's, in every subcommand (all
// read RunConfig), and a bad one is named.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

std::map<std::string, std::string> knobsAfter(const std::string& presets, const std::string& name) {
    const fs::path dir = test::tempDir() / "preset-order";
    fs::create_directories(dir);
    const fs::path dump = dir / (name + ".txt");
    const auto r = test::runWorkbench("render --scene spheres --size 16x9 " + presets + " --out " +
                                      (dir / (name + ".png")).string() + " --dump-knobs " + dump.string());
    EXPECT_EQ(r.code, 0) << r.err;
    return test::readKnobDump(dump);
}

}  // namespace

TEST(PresetOrderCli, RepeatedPresetsCombineInOrder) {
    // A GTAO level with a quality level, either way round: the GTAO knobs
    // from the one, the SSAO blur and shadow map from the other.
    auto k = knobsAfter("--preset 'GTAO ultra' --preset Low", "gtao-low");
    EXPECT_EQ(k["ao.method"], "gtao");
    EXPECT_EQ(k["gtao.slices"], "9");
    EXPECT_EQ(k["shadows.map_size"], "512");
    EXPECT_EQ(k["ssao.resolution"], "quarter");
    k = knobsAfter("--preset Low --preset 'GTAO ultra'", "low-gtao");
    EXPECT_EQ(k["ao.method"], "gtao");
    EXPECT_EQ(k["gtao.slices"], "9");
    EXPECT_EQ(k["shadows.map_size"], "512");
    // Both set ssao.samples and ssao_blur.width: the later one wins.
    k = knobsAfter("--preset SSAO1 --preset Low", "ssao1-low");
    EXPECT_EQ(k["ssao.samples"], "16");
    EXPECT_EQ(k["ssao_blur.width"], "21");
    k = knobsAfter("--preset Low --preset SSAO1", "low-ssao1");
    EXPECT_EQ(k["ssao.samples"], "8");
    EXPECT_EQ(k["ssao_blur.width"], "10");
    // --set still wins over every preset.
    k = knobsAfter("--preset Low --preset SSAO1 --set ssao.samples=4", "set");
    EXPECT_EQ(k["ssao.samples"], "4");
}

TEST(PresetOrderCli, EverySubcommandTakesRepeatedPresets) {
    const auto list = test::runWorkbench("list passes --scene spheres --preset Low --preset 'GTAO high'");
    EXPECT_EQ(list.code, 0) << list.err;
    const auto listBad = test::runWorkbench("list passes --scene spheres --preset Low --preset NoSuchPreset");
    EXPECT_NE(listBad.code, 0);
    EXPECT_NE(listBad.err.find("'NoSuchPreset'"), std::string::npos) << listBad.err;
    const fs::path dir = test::tempDir() / "preset-order";
    fs::create_directories(dir);
    const auto bench = test::runWorkbench("bench --scene spheres --size 16x9 --frames 1 --preset Low --preset 'GTAO low' "
                                          "--json " + (dir / "b.json").string());
    EXPECT_EQ(bench.code, 0) << bench.err;
    // A bad one among good ones is named, before anything renders.
    const auto bad = test::runWorkbench("render --scene spheres --size 16x9 --preset Low --preset NoSuchPreset --out " +
                                        (dir / "bad.png").string());
    EXPECT_NE(bad.code, 0);
    EXPECT_NE(bad.err.find("'NoSuchPreset'"), std::string::npos) << bad.err;
    const auto empty = test::runWorkbench("render --scene spheres --size 16x9 --preset Low --preset '' --out " +
                                          (dir / "e.png").string());
    EXPECT_NE(empty.code, 0);
    EXPECT_NE(empty.err.find("--preset needs"), std::string::npos) << empty.err;
}
