// `bench` as a user runs it, end to end in a small grid: every row in the
// CSV, the JSON and the Markdown table, the plot a PNG of the size asked
// for, and shards that merge back into the grid. Timings are never asserted.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <tuple>

#include "renderer/io/ImageIO.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

using Result = test::CommandResult;
Result run(const std::string& args) { return test::runWorkbench(args); }

std::vector<std::vector<std::string>> readCsv(const fs::path& path) {
    std::ifstream f(path);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(f, line)) {
        std::vector<std::string> fields;
        std::stringstream s(line);
        std::string field;
        while (std::getline(s, field, ',')) fields.push_back(field);
        if (!line.empty() && line.back() == ',') fields.emplace_back();
        rows.push_back(fields);
    }
    return rows;
}

// (size, lights, strategy) -> the (sample, pass) pairs of its rows.
using Key = std::tuple<std::string, std::string, std::string>;
std::map<Key, std::set<std::pair<std::string, std::string>>> rowsByConfig(const std::vector<std::vector<std::string>>& csv) {
    std::map<Key, std::set<std::pair<std::string, std::string>>> out;
    for (size_t i = 1; i < csv.size(); ++i) {
        const auto& r = csv[i];
        out[{r[1], r[2], r[3]}].insert({r[6], r[9]});
    }
    return out;
}

const char* const kSizes[] = {"64x36", "96x54"};
const char* const kLights[] = {"1", "10"};
const char* const kStrategies[] = {"stencil_volumes", "fullscreen"};

const std::string kGrid =
    "bench --scene default --size 64x36,96x54 --lights 1,10 --sweep lighting.strategy=stencil_volumes,fullscreen "
    "--frames 2 --warmup 1 --resamples 200";

}  // namespace

TEST(BenchCli, SmallGridEndToEndAndShardsMergeIntoIt) {
    const fs::path dir = test::tempDir() / "bench";
    fs::create_directories(dir);
    const fs::path csv = dir / "all.csv", json = dir / "all.json", png = dir / "all.png";
    const Result r = run(kGrid + " --csv " + csv.string() + " --json " + json.string() + " --plot " + png.string() +
                         " --plot-size 320x200");
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_NE(r.err.find("bench: done"), std::string::npos) << "progress goes to stderr: " << r.err;

    // CSV: the header, and every configuration with both counted frames of the whole frame and of the lighting pass.
    const auto rows = readCsv(csv);
    ASSERT_GT(rows.size(), 1u);
    EXPECT_EQ(rows[0], (std::vector<std::string>{"config", "size", "lights", "lighting.strategy", "lpp", "lpp_lit", "sample",
                                                 "seq", "frame", "pass", "gpu_ms", "cpu_ms", "gpu_mem_peak_mib", "fragments", "samples",
                                                 "primitives", "vertices", "compute", "bytes"}));
    const auto byConfig = rowsByConfig(rows);
    EXPECT_EQ(byConfig.size(), 8u);
    for (const char* size : kSizes)
        for (const char* lights : kLights)
            for (const char* strategy : kStrategies) {
                const auto it = byConfig.find({size, lights, strategy});
                ASSERT_NE(it, byConfig.end()) << size << " " << lights << " " << strategy;
                for (const char* sample : {"0", "1"})
                    for (const char* pass : {"frame", "lighting", "geometry"})
                        EXPECT_TRUE(it->second.count({sample, pass})) << size << " " << lights << " " << strategy << " "
                                                                      << sample << " " << pass;
            }
    for (size_t i = 1; i < rows.size(); ++i) {
        ASSERT_EQ(rows[i].size(), rows[0].size()) << "line " << i + 1;
        EXPECT_GE(std::stod(rows[i][10]), 0.0) << "gpu_ms, line " << i + 1;
    }

    // JSON: the machine, every configuration with its samples and lights per pixel.
    std::ifstream jf(json);
    const nlohmann::json j = nlohmann::json::parse(jf)["results"];
    EXPECT_FALSE(j["machine"]["gl_renderer"].get<std::string>().empty());
    EXPECT_FALSE(j["machine"]["cpu"].get<std::string>().empty());
    EXPECT_EQ(j["baseline"]["axis"], "lighting.strategy");
    EXPECT_EQ(j["baseline"]["value"], "stencil_volumes");
    ASSERT_EQ(j["configs"].size(), 8u);
    std::set<Key> seen;
    for (const auto& c : j["configs"]) {
        const std::string strategy = c["knobs"]["lighting.strategy"];
        seen.insert({c["size"], std::to_string(c["lights"].get<int>()), strategy});
        EXPECT_EQ(c["frames"], 2);
        ASSERT_EQ(c["samples"].size(), 2u);
        EXPECT_TRUE(c["samples"][0]["gpu_ms"].contains("frame"));
        EXPECT_TRUE(c["samples"][0]["gpu_ms"].contains("lighting"));
        EXPECT_TRUE(c["series"].contains("lighting"));
        ASSERT_TRUE(c["lpp"].is_number()) << c.dump();
        // The lighting pass's own line: which strategy lit, and how many lights.
        ASSERT_TRUE(c["stats"].contains("lighting")) << c.dump();
        EXPECT_NE(c["stats"]["lighting"].get<std::string>().find(strategy), std::string::npos) << c["stats"].dump();
        // The full-screen strategy shades every light on every pixel it lights.
        if (strategy == "fullscreen") {
            EXPECT_NEAR(c["lpp_lit"].get<double>(), c["lights"].get<double>(), 1e-3) << c["size"];
        }
        ASSERT_TRUE(c["ratio"].is_number());
        if (c["baseline_config"] == c["config"]) {
            // The baseline against itself: 1 and no interval, as the table shows.
            EXPECT_EQ(c["ratio"].get<double>(), 1.0);
            EXPECT_TRUE(c["ci95"].is_null());
            continue;
        }
        ASSERT_TRUE(c["ci95"].is_array());
        EXPECT_LE(c["ci95"][0].get<double>(), c["ratio"].get<double>());
        EXPECT_GE(c["ci95"][1].get<double>(), c["ratio"].get<double>());
    }
    EXPECT_EQ(seen.size(), 8u);
    // Light volumes reach fewer pixels than full-screen quads: fewer lights per pixel, same lights.
    for (const auto& c : j["configs"])
        if (c["knobs"]["lighting.strategy"] == "stencil_volumes") {
            const auto& full = j["configs"][c["config"].get<int>() + 1];
            EXPECT_LE(c["lpp"].get<double>(), full["lpp"].get<double>() + 1e-6) << c["size"] << " " << c["lights"];
        }

    // The Markdown table: a row per configuration and a CI column.
    EXPECT_NE(r.out.find("95% CI"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("| ratio to lighting.strategy=stencil_volumes |"), std::string::npos) << r.out;
    for (const char* size : kSizes)
        for (const char* lights : kLights)
            for (const char* strategy : kStrategies)
                EXPECT_NE(r.out.find(std::string("| ") + size + " | " + lights + " | " + strategy + " | "), std::string::npos)
                    << size << " " << lights << " " << strategy << "\n" << r.out;

    // The plot: a PNG of the size asked for.
    ASSERT_TRUE(fs::exists(png)) << r.err;
    std::ifstream pf(png, std::ios::binary);
    char magic[8] = {};
    pf.read(magic, 8);
    EXPECT_EQ(std::string(magic + 1, 3), "PNG");
    const FloatImage plot = loadImageFloat(png.string());
    EXPECT_EQ(plot.width, 320);
    EXPECT_EQ(plot.height, 200);

    // Shards 0/2 and 1/2, merged, have the full grid's rows.
    std::string shardCsvs;
    for (int i = 0; i < 2; ++i) {
        const fs::path part = dir / ("shard" + std::to_string(i) + ".csv");
        const Result s = run(kGrid + " --quiet --shard " + std::to_string(i) + "/2 --csv " + part.string() + " --json " +
                             (dir / ("shard" + std::to_string(i) + ".json")).string());
        ASSERT_EQ(s.code, 0) << s.err;
        EXPECT_EQ(rowsByConfig(readCsv(part)).size(), 4u);
        // A shard runs whole comparison groups: each configuration's baseline ran beside it.
        std::ifstream sj(dir / ("shard" + std::to_string(i) + ".json"));
        const nlohmann::json shard = nlohmann::json::parse(sj)["results"];  // the loop below iterates into it
        for (const auto& c : shard["configs"]) EXPECT_TRUE(c["ratio"].is_number()) << c["config"];
        shardCsvs += " " + part.string();
    }
    const fs::path merged = dir / "merged.csv", mergedJson = dir / "merged.json";
    const Result m = run("bench merge" + shardCsvs + " --out " + merged.string() + " --json " + mergedJson.string());
    ASSERT_EQ(m.code, 0) << m.err;
    EXPECT_EQ(rowsByConfig(readCsv(merged)), byConfig);
    const auto mergedRows = readCsv(merged);
    for (size_t i = 1; i < mergedRows.size(); ++i)
        ASSERT_EQ(mergedRows[i][0], rows[i][0]) << "merged rows keep the grid's order, line " << i + 1;
    std::ifstream mj(mergedJson);
    const nlohmann::json mjson = nlohmann::json::parse(mj)["results"];
    EXPECT_EQ(mjson["configs"].size(), 8u);
    EXPECT_EQ(mjson["machine"]["gl_renderer"], j["machine"]["gl_renderer"]);
    EXPECT_NE(m.out.find("95% CI"), std::string::npos);
    EXPECT_EQ(j["baseline"]["series"], "frame");

    // bench merge over the run's own CSV (its JSON beside it) gives the run's
    // ratios exactly: both are made from the samples as the CSV holds them.
    const fs::path againJson = dir / "again.json";
    const Result again = run("bench merge " + csv.string() + " --out " + (dir / "again.csv").string() + " --json " +
                             againJson.string() + " --resamples 200");
    ASSERT_EQ(again.code, 0) << again.err;
    {
        std::ifstream aj(againJson);
        const nlohmann::json a = nlohmann::json::parse(aj)["results"];
        ASSERT_EQ(a["configs"].size(), j["configs"].size());
        for (std::size_t i = 0; i < a["configs"].size(); ++i) {
            EXPECT_EQ(a["configs"][i]["ratio"], j["configs"][i]["ratio"]) << i;
            EXPECT_EQ(a["configs"][i]["ci95"], j["configs"][i]["ci95"]) << i;
        }
    }

    // --ratio-of lighting: the ratios are those of the lighting pass's
    // medians; a series no shard recorded is refused.
    const fs::path litJson = dir / "lit.json";
    const Result lit = run("bench merge" + shardCsvs + " --out " + (dir / "lit.csv").string() + " --json " +
                           litJson.string() + " --ratio-of lighting");
    ASSERT_EQ(lit.code, 0) << lit.err;
    EXPECT_NE(lit.out.find("| lighting ratio to lighting.strategy=stencil_volumes | 95% CI |"), std::string::npos)
        << lit.out;
    std::ifstream lj(litJson);
    const nlohmann::json ljson = nlohmann::json::parse(lj)["results"];
    EXPECT_EQ(ljson["baseline"]["series"], "lighting");
    int compared = 0;
    for (const auto& c : ljson["configs"]) {
        const auto& base = ljson["configs"][c["baseline_config"].get<int>()];
        const double expected = c["series"]["lighting"]["gpu_ms"]["median"].get<double>() /
                                base["series"]["lighting"]["gpu_ms"]["median"].get<double>();
        ASSERT_TRUE(c["ratio"].is_number()) << c["config"];
        EXPECT_NEAR(c["ratio"].get<double>(), expected, 2e-3 * expected + 1e-3) << c["config"];
        compared += c["config"] != base["config"];
    }
    EXPECT_EQ(compared, 4);
    const Result noSeries = run("bench merge" + shardCsvs + " --out " + (dir / "none.csv").string() +
                                " --ratio-of lighting/nope");
    EXPECT_EQ(noSeries.code, 1);
    EXPECT_NE(noSeries.err.find("--ratio-of: no configuration of these shards has samples of 'lighting/nope'"),
              std::string::npos)
        << noSeries.err;

    // Merging a shard twice is refused, naming the configuration.
    const Result twice = run("bench merge " + (dir / "shard0.csv").string() + " " + (dir / "shard0.csv").string() +
                             " --out " + (dir / "twice.csv").string());
    EXPECT_EQ(twice.code, 1);
    EXPECT_NE(twice.err.find("configuration 0 is in both"), std::string::npos) << twice.err;
}

TEST(BenchCli, BadInputFailsBeforeRendering) {
    const Result knob = run("bench --sweep lighting.nope=a,b --csv /dev/null --json /dev/null");
    EXPECT_EQ(knob.code, 1);
    EXPECT_NE(knob.err.find("unknown knob 'lighting.nope'"), std::string::npos) << knob.err;
    const Result value = run("bench --sweep lighting.strategy=volumes,nope --csv /dev/null --json /dev/null");
    EXPECT_EQ(value.code, 1);
    EXPECT_NE(value.err.find("nope"), std::string::npos) << value.err;
    const Result shard = run("bench --shard 2/2");
    EXPECT_EQ(shard.code, 2);
    EXPECT_NE(shard.err.find("--shard expects i/n"), std::string::npos) << shard.err;
    const Result baseline = run("bench --sweep lighting.strategy=volumes,fullscreen --baseline lighting.strategy=forwardx");
    EXPECT_EQ(baseline.code, 1);
    EXPECT_NE(baseline.err.find("--baseline"), std::string::npos) << baseline.err;
    const Result ratioOf = run("bench --sweep lighting.strategy=volumes,fullscreen --ratio-of lightning");
    EXPECT_EQ(ratioOf.code, 1);
    EXPECT_NE(ratioOf.err.find("--ratio-of: 'lightning' is not frame, a pass (geometry,"), std::string::npos)
        << ratioOf.err;
    EXPECT_EQ(ratioOf.err.find("bench: frame"), std::string::npos) << ratioOf.err;
    // A pass that runs in some configurations only: no baseline has it, so
    // no ratio, an error after the run.
    const Result partly = run("bench --scene default --size 32x18 --lights 1 --frames 1 --quiet --sweep "
                              "dof.enabled=false,true --ratio-of dof --csv /dev/null --json /dev/null");
    EXPECT_EQ(partly.code, 1);
    EXPECT_NE(partly.err.find("no configuration has a ratio: 'dof' is not in every configuration and its baseline"),
              std::string::npos)
        << partly.err;
    // One output failing (a full disk) does not cost the others.
    const fs::path kept = test::tempDir() / "bench-full" / "kept.json";
    fs::create_directories(kept.parent_path());
    const Result full = run("bench --scene default --size 32x18 --lights 1 --frames 1 --quiet --csv /dev/full --json " +
                            kept.string());
    EXPECT_EQ(full.code, 1);
    EXPECT_NE(full.err.find("/dev/full: writing the bench CSV failed"), std::string::npos) << full.err;
    EXPECT_TRUE(fs::exists(kept)) << "the JSON was not written after the CSV failed";
    // A pass that exists but does not run (depth of field is off): the run's
    // files are written, then the ratio it could not make is an error.
    const fs::path offDir = test::tempDir() / "bench-ratio-of";
    fs::create_directories(offDir);
    const Result off = run("bench --scene default --size 32x18 --lights 1 --frames 1 --quiet --ratio-of dof --csv " +
                           (offDir / "dof.csv").string() + " --json " + (offDir / "dof.json").string());
    EXPECT_EQ(off.code, 1);
    EXPECT_NE(off.err.find("--ratio-of: no configuration recorded 'dof'"), std::string::npos) << off.err;
    EXPECT_TRUE(fs::exists(offDir / "dof.csv") && fs::exists(offDir / "dof.json"));
    EXPECT_NE(off.out.find("| 0 | 32x18 | 1 |"), std::string::npos) << off.out;
    // Two spellings of one value are one configuration: refused like a value given twice.
    const Result spelt = run("bench --scene default --size 32x18 --lights 1 --frames 1 --sweep "
                             "lighting.tile_coarse=true,TRUE --csv /dev/null --json /dev/null");
    EXPECT_EQ(spelt.code, 1);
    EXPECT_NE(spelt.err.find("'TRUE' is 'true', which is given before"), std::string::npos) << spelt.err;
    EXPECT_EQ(spelt.err.find("bench: frame"), std::string::npos) << spelt.err;
    const Result walk = run("bench --scene default --walkthrough");
    EXPECT_EQ(walk.code, 1);
    EXPECT_NE(walk.err.find("camera.path"), std::string::npos) << walk.err;
    const Result help = run("help bench");
    EXPECT_EQ(help.code, 0);
    EXPECT_NE(help.out.find("--shard i/n"), std::string::npos);

    // Usage errors exit 2: a malformed sweep, a value given twice, a plot
    // that is not a PNG or too small for the script.
    for (const char* args : {"--sweep lighting.strategy", "--sweep lighting.strategy=,tiled", "--lights 10,10",
                             "--size 64x36,64x36", "--plot p.jpg", "--plot p.png --plot-size 10x10"}) {
        const Result usage = run(std::string("bench --scene default --size 32x18 --lights 1 --frames 1 ") + args);
        EXPECT_EQ(usage.code, 2) << args << ": " << usage.err;
        EXPECT_NE(usage.err.find("deferred-workbench: "), std::string::npos) << args;
    }
    // Two outputs naming one file: one would replace the other.
    for (const char* args : {"--csv same.x --json same.x", "--json same.png --plot same.png",
                             "--csv ./same.png --plot same.png"}) {
        const Result same = run(std::string("bench --scene default --size 32x18 --lights 1 --frames 1 ") + args);
        EXPECT_EQ(same.code, 2) << args << ": " << same.err;
        EXPECT_NE(same.err.find("are the same file"), std::string::npos) << args << ": " << same.err;
        EXPECT_EQ(same.err.find("bench: frame"), std::string::npos) << args;
    }
    // A folder that is there and writable to access() but takes no new
    // file (/proc): refused before the first frame too.
    const Result proc = run("bench --scene default --size 32x18 --lights 1 --frames 1 --json /proc/dw-bench.json");
    EXPECT_EQ(proc.code, 1);
    EXPECT_NE(proc.err.find("/proc/dw-bench.json: cannot write the bench JSON"), std::string::npos) << proc.err;
    EXPECT_EQ(proc.err.find("bench: frame"), std::string::npos) << proc.err;
    // Outputs that could not be written at the end are refused before the
    // first frame (no progress line), naming the path.
    for (const char* flag : {"--csv", "--json", "--plot"}) {
        const std::string path = std::string("/nonexistent-dw-folder/out") + (std::string(flag) == "--plot" ? ".png" : ".x");
        const Result bad = run(std::string("bench --scene default --size 32x18 --lights 1 --frames 1 ") + flag + " " + path);
        EXPECT_EQ(bad.code, 1) << flag;
        EXPECT_NE(bad.err.find(path + ": cannot write"), std::string::npos) << bad.err;
        EXPECT_EQ(bad.err.find("bench: frame"), std::string::npos) << flag << " ran before failing:\n" << bad.err;
    }
}

// LPP lit averages over the surface pixels a light reached: in the fire
// scene a directional light runs over every pixel, sky included, so LPP
// (over all pixels) counts the sky's invocations and LPP lit, without the
// sky, is larger. When sky pixels counted as lit the two were equal.
TEST(BenchCli, LppLitLeavesOutPixelsWithoutASurface) {
    const fs::path dir = test::tempDir() / "bench-lpp";
    fs::create_directories(dir);
    const Result r = run("bench --scene fire --size 64x36 --frames 1 --warmup 0 --quiet --csv " + (dir / "f.csv").string() +
                         " --json " + (dir / "f.json").string());
    ASSERT_EQ(r.code, 0) << r.err;
    std::ifstream f(dir / "f.json");
    const nlohmann::json j = nlohmann::json::parse(f)["results"];
    const double lpp = j["configs"][0]["lpp"].get<double>(), lit = j["configs"][0]["lpp_lit"].get<double>();
    EXPECT_GT(lpp, 1.0);
    EXPECT_GT(lit, lpp * 1.1) << "LPP " << lpp << ", LPP lit " << lit;
}

// --keep-scene-lights: the lights column counts the generated lights, and
// the title and settings.lights say how many of the scene's own are added.
TEST(BenchCli, KeptSceneLightsAreCountedInTheTitleAndSettings) {
    const fs::path dir = test::tempDir() / "bench-keep";
    fs::create_directories(dir);
    const Result r = run("bench --scene fire --size 32x18 --lights 5 --keep-scene-lights --frames 1 --warmup 0 --no-lpp "
                         "--quiet --csv " + (dir / "k.csv").string() + " --json " + (dir / "k.json").string());
    ASSERT_EQ(r.code, 0) << r.err;
    std::ifstream f(dir / "k.json");
    const nlohmann::json j = nlohmann::json::parse(f)["results"];
    const std::string lights = j["settings"]["lights"].get<std::string>();
    const std::string prefix = "generated, added to the scene's ";
    ASSERT_EQ(lights.rfind(prefix, 0), 0u) << lights;
    EXPECT_GT(std::stoi(lights.substr(prefix.size())), 100) << lights;  // the fire's flame lights
    EXPECT_NE(r.out.find("the lights column: " + lights), std::string::npos) << r.out;
    EXPECT_EQ(j["configs"][0]["lights"].get<int>(), 5);
}

// bench merge refuses what is not one grid's shards: shards of two runs
// with different grids, and a CSV cut short; a missing shard is named.
TEST(BenchCli, MergeRefusesShardsOfDifferentRunsAndCutFiles) {
    const fs::path dir = test::tempDir() / "bench-merge";
    fs::create_directories(dir / "other");
    const std::string common = "bench --scene default --size 32x18 --frames 1 --warmup 0 --no-lpp --quiet ";
    auto shard = [&](const fs::path& base, const std::string& grid, int i) {
        const Result r = run(common + grid + " --shard " + std::to_string(i) + "/2 --csv " + (base.string() + ".csv") +
                             " --json " + (base.string() + ".json"));
        EXPECT_EQ(r.code, 0) << r.err;
    };
    shard(dir / "a0", "--lights 1,2 --sweep lighting.strategy=stencil_volumes,tiled", 0);
    shard(dir / "a1", "--lights 1,2 --sweep lighting.strategy=stencil_volumes,tiled", 1);
    shard(dir / "other" / "b0", "--lights 3,4 --sweep lighting.strategy=volumes,clustered", 0);

    const Result mixed = run("bench merge " + (dir / "a1.csv").string() + " " + (dir / "other" / "b0.csv").string() +
                             " --out " + (dir / "m.csv").string());
    EXPECT_EQ(mixed.code, 1);
    EXPECT_NE(mixed.err.find("comes from another bench run"), std::string::npos) << mixed.err;
    EXPECT_FALSE(fs::exists(dir / "m.csv"));

    const Result missing = run("bench merge " + (dir / "a0.csv").string() + " --out " + (dir / "m.csv").string());
    EXPECT_EQ(missing.code, 0) << missing.err;
    EXPECT_NE(missing.err.find("shard(s) 1 of 2 are not among the inputs"), std::string::npos) << missing.err;

    // The first two lines of a shard: a configuration without its frame rows.
    {
        std::ifstream in(dir / "a1.csv");
        std::ofstream cut(dir / "cut.csv");
        std::string line;
        for (int i = 0; i < 2 && std::getline(in, line); ++i) cut << line << "\n";
    }
    const Result cut = run("bench merge " + (dir / "cut.csv").string() + " --out " + (dir / "m2.csv").string());
    EXPECT_EQ(cut.code, 1);
    EXPECT_NE(cut.err.find("has no frame samples"), std::string::npos) << cut.err;

    // Cut at the end of a line, its JSON beside it: a configuration with
    // fewer frames than the run counted (3 here).
    shard(dir / "f0", "--lights 1,2 --sweep lighting.strategy=stencil_volumes,tiled --frames 3", 0);
    std::vector<std::string> lines;
    {
        std::ifstream in(dir / "f0.csv");
        for (std::string line; std::getline(in, line);) lines.push_back(line);
    }
    fs::create_directories(dir / "short");
    {
        std::ofstream part(dir / "short" / "f0.csv");
        for (std::size_t i = 0; i + 3 < lines.size(); ++i) part << lines[i] << "\n";
    }
    fs::copy_file(dir / "f0.json", dir / "short" / "f0.json", fs::copy_options::overwrite_existing);
    const Result lineCut = run("bench merge " + (dir / "short" / "f0.csv").string() + " --out " + (dir / "m3.csv").string());
    EXPECT_EQ(lineCut.code, 1);
    EXPECT_NE(lineCut.err.find("frames, its JSON"), std::string::npos) << lineCut.err;
    EXPECT_NE(lineCut.err.find("says 3 (is the file cut short?)"), std::string::npos) << lineCut.err;
    EXPECT_FALSE(fs::exists(dir / "m3.csv"));

    // Cut so that its last configuration has no line left: its JSON lists it.
    {
        std::ofstream part(dir / "short" / "f0.csv");
        const std::string lastConfig = lines.back().substr(0, lines.back().find(','));
        for (const auto& line : lines)
            if (line.substr(0, line.find(',')) != lastConfig) part << line << "\n";
    }
    const Result gone = run("bench merge " + (dir / "short" / "f0.csv").string() + " --out " + (dir / "m3.csv").string());
    EXPECT_EQ(gone.code, 1);
    EXPECT_NE(gone.err.find("has no samples (is the file cut short?)"), std::string::npos) << gone.err;

    // Shards that differ only in how their tables were made merge.
    shard(dir / "g1", "--lights 1,2 --sweep lighting.strategy=stencil_volumes,tiled --baseline lighting.strategy=tiled "
                      "--ratio-of lighting",
          1);
    const Result reporting = run("bench merge " + (dir / "a0.csv").string() + " " + (dir / "g1.csv").string() +
                                 " --out " + (dir / "m5.csv").string());
    EXPECT_EQ(reporting.code, 0) << reporting.err;
    // Where their JSONs agree on the ratio's series and baseline, merge takes them.
    shard(dir / "g0", "--lights 1,2 --sweep lighting.strategy=stencil_volumes,tiled --baseline lighting.strategy=tiled "
                      "--ratio-of lighting",
          0);
    const Result agreed = run("bench merge " + (dir / "g0.csv").string() + " " + (dir / "g1.csv").string() + " --out " +
                              (dir / "m6.csv").string());
    EXPECT_EQ(agreed.code, 0) << agreed.err;
    EXPECT_NE(agreed.out.find("| lighting ratio to lighting.strategy=tiled |"), std::string::npos) << agreed.out;

    // Cut inside its last line (no newline at the end), rows joined twice,
    // and times that are no times: each refused naming the line.
    auto variant = [&](const std::string& name, const std::string& text) {
        fs::create_directories(dir / name);
        std::ofstream(dir / name / "f0.csv") << text;
        return run("bench merge " + (dir / name / "f0.csv").string() + " --out " + (dir / (name + ".csv")).string());
    };
    std::string whole;
    for (const auto& line : lines) whole += line + "\n";
    const Result midLine = variant("midline", whole.substr(0, whole.size() - 4));
    EXPECT_EQ(midLine.code, 1);
    EXPECT_NE(midLine.err.find("the last line has no end (is the file cut short?)"), std::string::npos) << midLine.err;
    std::string twice = whole;
    for (std::size_t i = 1; i < lines.size(); ++i) twice += lines[i] + "\n";
    const Result joined = variant("twice", twice);
    EXPECT_EQ(joined.code, 1);
    EXPECT_NE(joined.err.find("is there twice"), std::string::npos) << joined.err;
    for (const char* bad : {"inf", "-5", "nan", ""}) {
        std::string text = whole;
        const std::size_t lineEnd = text.find('\n', text.find('\n') + 1);  // the first sample's line
        // gpu_ms is the 9th field from the end when the run counted (gpu_mem_peak_mib and six counter columns after cpu_ms).
        std::size_t lastComma = text.rfind(',', lineEnd);
        for (int k = 0; k < 7; ++k) lastComma = text.rfind(',', lastComma - 1);
        const std::size_t gpuComma = text.rfind(',', lastComma - 1);
        text.replace(gpuComma + 1, lastComma - gpuComma - 1, bad);
        const Result r = variant(std::string("time") + (bad[0] ? bad : "empty"), text);
        EXPECT_EQ(r.code, 1) << bad;
        EXPECT_NE(r.err.find("gpu_ms: expected milliseconds"), std::string::npos) << bad << ": " << r.err;
    }

    // Options in another order are the same run; a ratio along another axis
    // than the shards' groups is said to compare shards.
    shard(dir / "o1", "--sweep lighting.strategy=stencil_volumes,tiled --lights 1,2", 1);
    const Result order = run("bench merge " + (dir / "a0.csv").string() + " " + (dir / "o1.csv").string() + " --out " +
                             (dir / "m7.csv").string() + " --baseline lights=1");
    EXPECT_EQ(order.code, 0) << order.err;
    EXPECT_NE(order.err.find("the shards were grouped along lighting.strategy, the ratios are along lights"),
              std::string::npos)
        << order.err;

    // Writing over an input (a shard or its JSON) is refused before anything is read.
    const Result over = run("bench merge " + (dir / "a0.csv").string() + " " + (dir / "a1.csv").string() + " --out " +
                            (dir / "a0.csv").string());
    EXPECT_EQ(over.code, 2);
    EXPECT_NE(over.err.find("are the same file"), std::string::npos) << over.err;
    const Result overJson = run("bench merge " + (dir / "a0.csv").string() + " --out " + (dir / "m4.csv").string() +
                                " --json " + (dir / "a0.json").string());
    EXPECT_EQ(overJson.code, 2);
    EXPECT_NE(overJson.err.find("are the same file"), std::string::npos) << overJson.err;
}

// A grid of 0 lights has nothing for the log-log plot: one line says so
// (no Python traceback), and the CSV and JSON are still written.
TEST(BenchCli, APlotWithOnlyZeroLightsSaysSoInOneLine) {
    const fs::path dir = test::tempDir() / "bench-zero";
    fs::create_directories(dir);
    const Result r = run("bench --scene default --size 32x18 --lights 0 --frames 1 --warmup 0 --no-lpp --quiet --csv " +
                         (dir / "z.csv").string() + " --json " + (dir / "z.json").string() + " --plot " + (dir / "z.png").string());
    if (r.err.find("matplotlib is missing") != std::string::npos) GTEST_SKIP() << "python3-matplotlib is not installed";
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.err.find("nothing to plot"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("Traceback"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir / "z.csv"));
    EXPECT_FALSE(fs::exists(dir / "z.png"));
}

// With one light count the plot is a bar per configuration (a line over
// a single light count would be a column of points on one tick), of the size asked for.
TEST(BenchCli, APlotOfOneLightCountIsABarPerConfiguration) {
    const fs::path dir = test::tempDir() / "bench-bars";
    fs::create_directories(dir);
    const Result r = run("bench --scene default --size 32x18 --lights 5 --sweep lighting.strategy=stencil_volumes,tiled "
                         "--frames 1 --warmup 0 --no-lpp --quiet --csv " + (dir / "b.csv").string() + " --json " +
                         (dir / "b.json").string() + " --plot " + (dir / "b.png").string() + " --plot-size 300x200");
    if (r.err.find("matplotlib is missing") != std::string::npos) GTEST_SKIP() << "python3-matplotlib is not installed";
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("one light count (5): a bar per configuration"), std::string::npos) << r.err;
    const FloatImage plot = loadImageFloat((dir / "b.png").string());
    EXPECT_EQ(plot.width, 300);
    EXPECT_EQ(plot.height, 200);
}

TEST(BenchCli, OrbitAndWalkthroughAverageOverTheirPoses) {
    const fs::path dir = test::tempDir() / "bench-paths";
    fs::create_directories(dir);
    const fs::path scene = dir / "walk.json";
    std::ofstream(scene) << R"({"objects": [{"shape": "plane", "size": [20, 0, 20]}, {"shape": "box", "size": [2, 2, 2], "pos": [0, 1, 0]}],
        "camera": {"pos": [0, 4, 12], "look-at": [0, 0, 0],
                   "path": [{"time": 0, "pos": [0, 4, 12], "look-at": [0, 0, 0]},
                            {"time": 2, "pos": [12, 4, 0], "look-at": [0, 0, 0]}]}})";
    for (const std::string camera : {"--orbit 2", "--walkthrough"}) {
        const fs::path csv = dir / "p.csv", json = dir / "p.json";
        const Result r = run("bench --quiet --scene " + scene.string() + " --size 32x18 --lights 0,5 " + camera +
                             " --frames 2 --lpp-poses 2 --csv " + csv.string() + " --json " + json.string());
        ASSERT_EQ(r.code, 0) << camera << ": " << r.err;
        std::ifstream jf(json);
        const nlohmann::json record = nlohmann::json::parse(jf);
        const nlohmann::json& j = record["results"];
        // The record holds the camera path: the orbit's poses, or the walkthrough's keyframes.
        if (camera == "--orbit 2") {
            EXPECT_EQ(record["camera_path"], nlohmann::json({{"mode", "orbit"}, {"orbit_poses", 2}}));
        } else {
            EXPECT_EQ(record["camera_path"]["mode"], "walkthrough");
            ASSERT_EQ(record["camera_path"]["keyframes"].size(), 2u);
            EXPECT_EQ(record["camera_path"]["keyframes"][1]["position"], nlohmann::json({12.0, 4.0, 0.0}));
        }
        EXPECT_EQ(j["settings"]["camera"].get<std::string>().rfind(camera == "--orbit 2" ? "orbit 2" : "walkthrough", 0), 0u);
        EXPECT_EQ(j["settings"]["lpp_poses"], "2");
        EXPECT_EQ(j["baseline"]["axis"], "lights");
        ASSERT_EQ(j["configs"].size(), 2u);
        EXPECT_EQ(j["configs"][0]["lpp"], 0.0);  // no lights, no light-shader invocations
        EXPECT_GT(j["configs"][1]["lpp"].get<double>(), 0.0);
        for (const auto& c : j["configs"]) EXPECT_EQ(c["samples"].size(), 2u);
    }
}

// A killed run keeps what it measured (the CSV is written as frames are
// harvested) and --resume measures the rest: the resumed table has the same
// configurations and frames as an uninterrupted run, the kept rows as they
// were. --exclude leaves out exactly the configurations it names.
TEST(BenchCli, ResumeFromAPartialCsvAndExclude) {
    const fs::path dir = test::tempDir() / "bench-resume";
    fs::create_directories(dir);
    const std::string grid = "bench --scene default --size 64x36 --lights 1,10 "
                             "--sweep lighting.strategy=stencil_volumes,fullscreen --frames 3 --quiet --resamples 200";
    const fs::path full = dir / "full.csv", part = dir / "part.csv", resumed = dir / "resumed.csv";
    const Result whole = run(grid + " --csv " + full.string() + " --json " + (dir / "full.json").string());
    ASSERT_EQ(whole.code, 0) << whole.err;
    const auto fullRows = readCsv(full);
    {
        // Cut as a kill would: 40 whole lines, then half a line.
        std::ifstream in(full);
        std::ofstream out(part);
        std::string line;
        for (int i = 0; i < 41 && std::getline(in, line); ++i) out << line << "\n";
        std::getline(in, line);
        out << line.substr(0, line.size() / 2);
    }
    const Result r = run(grid + " --csv " + resumed.string() + " --json " + (dir / "resumed.json").string() +
                         " --resume " + part.string());
    ASSERT_EQ(r.code, 0) << r.err;
    const auto rows = readCsv(resumed);
    ASSERT_EQ(rows.size(), fullRows.size());
    EXPECT_EQ(rowsByConfig(rows), rowsByConfig(fullRows)) << "the same configurations, samples and passes";
    // The frames the partial CSV had whole (a "frame" row) are kept as they were.
    std::set<std::pair<std::string, std::string>> whole0;
    for (int i = 1; i <= 40; ++i)
        if (fullRows[i][9] == "frame") whole0.insert({fullRows[i][0], fullRows[i][6]});
    ASSERT_FALSE(whole0.empty());
    int kept = 0;
    for (int i = 1; i <= 40; ++i)
        if (whole0.count({fullRows[i][0], fullRows[i][6]})) {
            ++kept;
            EXPECT_NE(std::find(rows.begin(), rows.end(), fullRows[i]), rows.end()) << i;
        }
    EXPECT_GT(kept, 0);
    // Same table shape: every configuration's line in both tables.
    for (const char* c : {"| 0 | 64x36 | 1 | stencil_volumes |", "| 3 | 64x36 | 10 | fullscreen |"}) {
        EXPECT_NE(whole.out.find(c), std::string::npos);
        EXPECT_NE(r.out.find(c), std::string::npos);
    }

    // --exclude: one corner and one slice.
    const Result ex = run(grid + " --csv " + (dir / "ex.csv").string() + " --json " + (dir / "ex.json").string() +
                          " --exclude lighting.strategy=fullscreen,lights=10");
    ASSERT_EQ(ex.code, 0) << ex.err;
    const auto exRows = rowsByConfig(readCsv(dir / "ex.csv"));
    EXPECT_EQ(exRows.size(), 3u);
    EXPECT_EQ(exRows.count({"64x36", "10", "fullscreen"}), 0u);
    const Result empty = run(grid + " --csv /dev/null --json /dev/null --exclude lights=1,10");
    EXPECT_NE(empty.code, 0);
    EXPECT_NE(empty.err.find("the grid is empty after --exclude"), std::string::npos) << empty.err;
    const Result unknown = run(grid + " --csv /dev/null --json /dev/null --exclude ssao.samples=8");
    EXPECT_NE(unknown.code, 0);
    EXPECT_NE(unknown.err.find("'ssao.samples' is not an axis of this sweep"), std::string::npos) << unknown.err;
}

// A killed run keeps what it measured: the samples go to the CSV as frames
// are harvested, so a SIGKILL mid-run leaves whole frames (and maybe half a
// line) that --resume completes.
TEST(BenchCli, AKilledRunKeepsItsSamplesAndResumes) {
    const fs::path dir = test::tempDir() / "bench-killed";
    fs::create_directories(dir);
    const fs::path live = dir / "live.csv";
    fs::remove(live);
    const std::string grid = "bench --scene default --size 64x36 --lights 1,10 "
                             "--sweep lighting.strategy=stencil_volumes,fullscreen --frames 40 --quiet --resamples 200";
    const std::string start = std::string(DW_WORKBENCH_BINARY) + " " + grid + " --csv " + live.string() +
                              " --json " + (dir / "live.json").string() + " > /dev/null 2>&1 & echo $!";
    FILE* shell = popen(start.c_str(), "r");
    ASSERT_NE(shell, nullptr);
    int pid = 0;
    ASSERT_EQ(std::fscanf(shell, "%d", &pid), 1);
    pclose(shell);
    // Wait until some rounds are on disk, then kill it without warning.
    auto lines = [&] {
        std::ifstream f(live);
        return static_cast<int>(std::count(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>(), '\n'));
    };
    for (int i = 0; i < 600 && lines() < 60 && ::kill(pid, 0) == 0; ++i) usleep(100000);
    const bool running = ::kill(pid, SIGKILL) == 0;
    for (int i = 0; i < 100 && ::kill(pid, 0) == 0; ++i) usleep(50000);
    ASSERT_TRUE(running) << "the run ended before it could be killed (" << lines() << " lines)";
    const int kept = lines();
    EXPECT_GE(kept, 60);
    const auto partial = readCsv(live);
    int frames = 0;
    for (size_t i = 1; i < partial.size(); ++i) frames += partial[i].size() > 9 && partial[i][9] == "frame";
    EXPECT_GT(frames, 0) << "whole frames in the killed run's CSV";
    EXPECT_LT(frames, 160);

    const Result resumed = run(grid + " --csv " + (dir / "done.csv").string() + " --json " +
                               (dir / "done.json").string() + " --resume " + live.string());
    ASSERT_EQ(resumed.code, 0) << resumed.err;
    const auto done = readCsv(dir / "done.csv");
    int all = 0;
    for (size_t i = 1; i < done.size(); ++i) all += done[i][9] == "frame";
    EXPECT_EQ(all, 4 * 40);
}

// With shadows.reuse_map on the shadows pass draws no map: its cell in the
// per-pass table says where the maps were drawn instead; with it off, none.
TEST(BenchCli, ReusedShadowMapsAreMarkedInThePassTable) {
    const Result r = run("bench --scene spheres --size 32x18 --frames 1 --warmup 0 --no-lpp --set ao.enabled=false "
                         "--sweep shadows.reuse_map=true,false --csv /dev/null --json /dev/null --quiet");
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    const size_t reused = r.out.find("| 0 | 32x18 |", r.out.find("GPU median ms per pass"));
    ASSERT_NE(reused, std::string::npos) << r.out;
    const std::string row0 = r.out.substr(reused, r.out.find('\n', reused) - reused);
    const size_t kept = r.out.find("| 1 | 32x18 |", reused);
    ASSERT_NE(kept, std::string::npos) << r.out;
    const std::string row1 = r.out.substr(kept, r.out.find('\n', kept) - kept);
    EXPECT_NE(row0.find("(reused: maps in lighting/shadow maps)"), std::string::npos) << row0;
    EXPECT_EQ(row1.find("reused"), std::string::npos) << row1;
}

// docs/bench.md "Shadow-caster culling", at a small size: one bench run with
// culling off and on side by side; each configuration's shadows line (the
// record's stats) says casters D/N, all of them drawn without culling and
// fewer with it, and render --timings prints the same line.
TEST(BenchCli, ShadowCasterCullingSideBySide) {
    const fs::path dir = test::tempDir() / "bench-casters";
    fs::create_directories(dir);
    const fs::path json = dir / "casters.json";
    const Result r = run("bench --scene street --sweep shadows.cull_casters=false,true --size 64x36 --frames 1 --quiet "
                         "--ratio-of \"lighting/shadow maps\" --csv " + (dir / "casters.csv").string() + " --record " +
                         json.string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("lighting/shadow maps ratio to shadows.cull_casters=false"), std::string::npos) << r.out;
    std::ifstream f(json);
    const nlohmann::json configs = nlohmann::json::parse(f)["results"]["configs"];
    ASSERT_EQ(configs.size(), 2u);
    std::map<std::string, std::pair<long, long>> casters;
    for (const auto& c : configs) {
        const std::string line = c["stats"]["shadows"].get<std::string>();
        const auto at = line.find("casters ");
        ASSERT_NE(at, std::string::npos) << line;
        long drawn = 0, total = 0;
        ASSERT_EQ(std::sscanf(line.c_str() + at, "casters %ld/%ld", &drawn, &total), 2) << line;
        casters[c["knobs"]["shadows.cull_casters"].get<std::string>()] = {drawn, total};
    }
    EXPECT_EQ(casters["false"].first, casters["false"].second);
    EXPECT_EQ(casters["true"].second, casters["false"].second);
    EXPECT_LT(casters["true"].first, casters["true"].second);

    const Result t = run("render --scene street --size 64x36 --timings --out " + (dir / "street.png").string());
    ASSERT_EQ(t.code, 0) << t.err;
    EXPECT_NE((t.out + t.err).find(std::to_string(casters["true"].first) + "/" + std::to_string(casters["true"].second) +
                                   ", "),
              std::string::npos)
        << t.out << t.err;
}

// docs/bench.md "Seed 000 section 6.5", at a small size: the preset Overall
// loads the atrium with its knobs, the generated 20 and 25 point lights join
// its sun (--keep-scene-lights), and the per-pass table holds the passes the
// seed's whole system runs: SSAO and its filter, the A-buffer, the sun's map.
TEST(BenchCli, PresetOverallAsTheDocsRunIt) {
    const fs::path dir = test::tempDir() / "bench-overall";
    fs::create_directories(dir);
    const Result r = run("bench --preset Overall --size 64x36 --lights 20,25 --keep-scene-lights --frames 1 --quiet --csv " +
                         (dir / "overall.csv").string() + " --record " + (dir / "overall.json").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("## bench: atrium, 2 configuration(s)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("generated, added to the scene's 1"), std::string::npos) << r.out;
    for (const char* row : {"| 0 | 64x36 | 20 |", "| 1 | 64x36 | 25 |"}) EXPECT_NE(r.out.find(row), std::string::npos) << row;
    for (const char* column : {"| ao |", "| ao_filter |", "| oit |", "| lighting/shadow maps |", "| GPU MiB peak |"})
        EXPECT_NE(r.out.find(column), std::string::npos) << column << "\n" << r.out;
}

// docs/bench.md "Seed 002 table 1", at a small size: a quality preset with
// ao.enabled and oit.enabled swept, SSAO + SR, SSAO, SR and OFF.
TEST(BenchCli, Seed002Table1Grid) {
    const fs::path dir = test::tempDir() / "bench-table1";
    fs::create_directories(dir);
    const Result r = run("bench --scene glass --preset Low --size 64x36 --lights 6 --keep-scene-lights --sweep "
                         "ao.enabled=true,false --sweep oit.enabled=true,false --frames 1 --no-lpp --quiet --csv " +
                         (dir / "t1.csv").string() + " --record " + (dir / "t1.json").string());
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* row : {"| 0 | 64x36 | 6 | true | true |", "| 1 | 64x36 | 6 | true | false |",
                            "| 2 | 64x36 | 6 | false | true |", "| 3 | 64x36 | 6 | false | false |"})
        EXPECT_NE(r.out.find(row), std::string::npos) << row << "\n" << r.out;
}

// Peak GPU memory per configuration (issue 36): a column of the CSV and a
// field of the JSON, above 0 on every row, the same on every row of a frame,
// and larger where a configuration allocates more: the linked list's 4 Mi
// nodes (96 MiB) over the weighted blend, 2048^2 shadow maps over 512^2.
TEST(BenchCli, PeakGpuMemoryIsLargerForAConfigurationThatAllocatesMore) {
    const fs::path dir = test::tempDir() / "bench-memory";
    fs::create_directories(dir);
    const fs::path csv = dir / "m.csv", json = dir / "m.json";
    const Result r = run("bench --scene glass --size 48x27 --lights 0 --keep-scene-lights --frames 2 --warmup 1 --no-lpp "
                         "--quiet --resamples 200 --sweep oit.method=weighted,linked_list --sweep shadows.map_size=512,2048 "
                         "--csv " + csv.string() + " --json " + json.string());
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("| GPU MiB peak |"), std::string::npos) << r.out;
    const auto rows = readCsv(csv);
    ASSERT_GT(rows.size(), 1u);
    const auto at = [&](const char* name) {
        return static_cast<size_t>(std::find(rows[0].begin(), rows[0].end(), name) - rows[0].begin());
    };
    const size_t mem = at("gpu_mem_peak_mib"), oit = at("oit.method"), map = at("shadows.map_size"), frame = at("frame");
    ASSERT_LT(mem, rows[0].size());
    std::map<std::pair<std::string, std::string>, double> peak;
    const auto peakOf = [&](const std::string& method, const std::string& size) { return peak[std::make_pair(method, size)]; };
    std::map<std::string, std::string> perFrame;
    for (size_t i = 1; i < rows.size(); ++i) {
        const double mib = std::stod(rows[i][mem]);
        EXPECT_GT(mib, 0.0) << "line " << i + 1;
        double& p = peak[{rows[i][oit], rows[i][map]}];
        p = std::max(p, mib);
        auto [it, fresh] = perFrame.emplace(rows[i][frame] + "/" + rows[i][0], rows[i][mem]);
        if (!fresh) {
            EXPECT_EQ(it->second, rows[i][mem]) << "every row of a frame: line " << i + 1;
        }
    }
    ASSERT_EQ(peak.size(), 4u);
    for (const char* size : {"512", "2048"})
        EXPECT_GT(peakOf("linked_list", size), peakOf("weighted", size) + 90.0) << size;
    for (const char* method : {"weighted", "linked_list"})
        EXPECT_GT(peakOf(method, "2048"), peakOf(method, "512")) << method;
    // The JSON's per-configuration figure is the CSV's largest.
    std::ifstream jf(json);
    const nlohmann::json j = nlohmann::json::parse(jf)["results"];
    for (const auto& c : j["configs"]) {
        ASSERT_TRUE(c["gpu_mem_peak_mib"].is_number()) << c.dump();
        EXPECT_EQ(c["gpu_mem_peak_mib"].get<double>(),
                  peakOf(c["knobs"]["oit.method"].get<std::string>(), c["knobs"]["shadows.map_size"].get<std::string>()));
    }
    // replay runs the grid again: the same peaks, to the byte.
    const Result again = run("replay " + json.string());
    EXPECT_NE(again.out.find("gpu memory peak "), std::string::npos) << again.out << again.err;
    EXPECT_EQ(again.out.find("(differs)"), std::string::npos) << again.out;
    EXPECT_EQ(again.out.find("with another peak GPU memory"), std::string::npos) << again.out;
}
