// Positional words keep their order whatever flags stand between them, in
// every subcommand (issue 32): a bare flag such as compare's --hdr took the
// next word as its value and handed it back at the end of the positionals,
// so `compare --hdr REF TEST` took TEST as the reference. Each subcommand is
// run with its flags first, between its words and last.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "renderer/io/ImageIO.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

using Result = test::CommandResult;

// A small HDR image: a ramp scaled by `scale` (HDR-FLIP takes its exposures from the reference's values).
fs::path ramp(const std::string& name, float scale) {
    FloatImage img;
    img.width = 16;
    img.height = 12;
    img.channels = 3;
    img.pixels.resize(16 * 12 * 3);
    for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = scale * static_cast<float>(i % 48) / 8.0f;
    const fs::path p = test::tempDir() / name;
    writeImage(p.string(), img);
    return p;
}

nlohmann::json readJson(const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

// "A B" with `flags` first, between A and B, and last.
std::vector<std::string> orders(const std::string& a, const std::string& b, const std::string& flags) {
    return {flags + " " + a + " " + b, a + " " + flags + " " + b, a + " " + b + " " + flags};
}

}  // namespace

TEST(PositionalOrderCli, CompareKeepsTheReferenceFirstWhereverHdrOrLdrStands) {
    const fs::path ref = ramp("order-reference.exr", 1.0f), tst = ramp("order-test.exr", 4.0f);
    const fs::path json = test::tempDir() / "order.json";
    double exposureStart = 0;
    bool first = true;
    for (const std::string flag : {"--hdr", "--ldr", "--fail 0.5 --hdr"})
        for (const std::string& args : orders(ref.string(), tst.string(), flag + " --json " + json.string())) {
            const Result r = test::runWorkbench("compare " + args);
            SCOPED_TRACE("compare " + args);
            ASSERT_TRUE(r.code == 0 || r.code == 1 || r.code == 2) << r.err;
            const nlohmann::json j = readJson(json);
            EXPECT_EQ(j["reference"]["path"], ref.string());
            EXPECT_EQ(j["test"]["path"], tst.string());
            if (flag.rfind("--hdr", 0) == 0) {
                // HDR-FLIP's exposures come from the reference: the same in every order.
                ASSERT_TRUE(j.contains("flip_exposures")) << j.dump();
                const double start = j["flip_exposures"]["start"].get<double>();
                if (first) exposureStart = start;
                first = false;
                EXPECT_EQ(start, exposureStart);
            }
        }
}

TEST(PositionalOrderCli, ABareFlagTakesNoValueWithEquals) {
    const Result r = test::runWorkbench("compare a.pfm b.pfm --hdr=yes");
    EXPECT_EQ(r.code, 5);
    EXPECT_NE(r.err.find("--hdr takes no value, got '--hdr=yes'"), std::string::npos) << r.err;
}

TEST(PositionalOrderCli, MergeReadsItsShardsInTheOrderGiven) {
    // The first shard named is the first read: its error names it, whatever flags stand around.
    const fs::path out = test::tempDir() / "merged.csv";
    for (const std::string command : {"bench merge", "tradeoff merge"})
        for (const std::string& args : orders("first-missing.csv", "second-missing.csv", "--out " + out.string())) {
            const Result r = test::runWorkbench(command + " " + args);
            SCOPED_TRACE(command + " " + args);
            EXPECT_NE(r.code, 0);
            EXPECT_NE(r.err.find("first-missing.csv"), std::string::npos) << r.err;
            EXPECT_EQ(r.err.find("second-missing.csv"), std::string::npos) << r.err;
        }
}

TEST(PositionalOrderCli, ReplayAndListTakeTheirWordWhereverTheFlagsStand) {
    const fs::path record = test::tempDir() / "new-record.json";
    for (const std::string& args : {"--record " + record.string() + " missing-record.json",
                                    "missing-record.json --record " + record.string()}) {
        const Result r = test::runWorkbench("replay " + args);
        EXPECT_NE(r.code, 0) << args;
        EXPECT_NE(r.err.find("missing-record.json"), std::string::npos) << r.err;
    }
    std::string expected;
    for (const std::string args : {"--scene default --size 64x36 passes", "passes --scene default --size 64x36",
                                    "--scene default passes --size 64x36"}) {
        const Result r = test::runWorkbench("list " + args);
        ASSERT_EQ(r.code, 0) << args << ": " << r.err;
        if (expected.empty()) expected = r.out;
        EXPECT_EQ(r.out, expected) << args;
    }
}

TEST(PositionalOrderCli, AStrayWordIsNamedInItsPlaceByCommandsThatTakeNone) {
    // The first stray word on the command line is the one named, also when a bare flag took it first.
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"render", "--timings first-stray --size 8x8 second-stray"},
        {"render", "first-stray --check-finite second-stray"},
        {"reference", "--quiet first-stray second-stray --no-cache"},
        {"bench", "--walkthrough first-stray --quiet second-stray"},
        {"tradeoff", "first-stray --quiet second-stray"},
        {"gui", "--record first-stray --renderdoc second-stray"},
    };
    for (const auto& [command, args] : cases) {
        const Result r = test::runWorkbench(command + " " + args);
        SCOPED_TRACE(command + " " + args);
        EXPECT_EQ(r.code, 2) << r.err;
        EXPECT_NE(r.err.find("unexpected argument 'first-stray'"), std::string::npos) << r.err;
    }
}
