// `tradeoff` as a user runs it, end to end on small grids (160x90, two
// frames): the CSV's rows and columns, the JSON, the table, the plot a PNG;
// the error falling where theory says (the AO's RMS against the ray-traced
// AO from 4 to 64 samples, blur off); shards merging to one run's table; bad
// input refused in one message. Timings are never asserted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "renderer/bench/TradeoffRunner.h"
#include "renderer/bench/TradeoffTable.h"
#include "renderer/io/ImageIO.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

using Result = test::CommandResult;

fs::path dir() {
    static const fs::path d = [] {
        fs::path p = test::tempDir() / "tradeoff";
        fs::create_directories(p);
        return p;
    }();
    return d;
}

// The reference cache of these tests: each reference rendered once for all of them.
Result run(const std::string& args) {
    return test::runCommand("DW_REFERENCE_CACHE=" + (dir() / "cache").string() + " " + DW_WORKBENCH_BINARY + " " + args);
}

std::string files(const std::string& name) {
    const fs::path d = dir();
    return " --csv " + (d / (name + ".csv")).string() + " --json " + (d / (name + ".json")).string() + " --plot " +
           (d / (name + ".png")).string() + " --plot-size 320x240";
}

const std::string kAoGrid =
    "tradeoff --scene default --size 160x90 --set ssao_blur.mode=off --sweep ssao.samples=4,16,64 "
    "--sweep ssao.resolution=full,half --metric rms --buffer ao --frames 2 --warmup 1 --resamples 200 --quiet";

const TradeoffRow* rowOf(const TradeoffTable& t, const std::string& samples, const std::string& resolution) {
    for (const auto& r : t.rows)
        if (t.axisValue(r, "ssao.samples") == samples && t.axisValue(r, "ssao.resolution") == resolution) return &r;
    return nullptr;
}

// A study file of this text in the tests' folder; its path.
std::string studyFile(const std::string& name, const std::string& text) {
    const fs::path file = dir() / (name + ".json");
    std::ofstream(file) << text;
    return file.string();
}

double row0Error(const nlohmann::json& record) { return record["results"]["rows"][0]["error"].get<double>(); }

}  // namespace

TEST(TradeoffCli, SmallGridEndToEndAndAoErrorFallsWithSamples) {
    const Result r = run(kAoGrid + files("grid"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "grid.csv").string());
    EXPECT_EQ(t.axes, (std::vector<std::string>{"ssao.samples", "ssao.resolution"}));
    ASSERT_EQ(t.rows.size(), 6u);
    int onFront = 0;
    for (const auto& row : t.rows) {
        EXPECT_EQ(row.camera, "0");
        EXPECT_EQ(row.metric, "rms");
        EXPECT_EQ(row.buffer, "ao");
        EXPECT_EQ(row.frames, 2);
        EXPECT_TRUE(std::isfinite(row.error) && row.error > 0.0) << row.point;
        EXPECT_LE(row.errorLo, row.error);
        EXPECT_GE(row.errorHi, row.error);
        EXPECT_TRUE(std::isfinite(row.frameGpuMs) && row.frameGpuMs > 0.0);
        EXPECT_FALSE(std::isnan(t.passGpuMs(row, "ao")));  // the AO pass (ao.method)
        EXPECT_TRUE(std::isfinite(row.gpuMemPeakMib) && row.gpuMemPeakMib > 0.0) << row.point;
        onFront += row.pareto ? 1 : 0;
    }
    EXPECT_GE(onFront, 1);
    // Peak GPU memory (issue 36): a full-size raw AO buffer holds more than a half-size one.
    for (const char* samples : {"4", "64"})
        EXPECT_GT(rowOf(t, samples, "full")->gpuMemPeakMib, rowOf(t, samples, "half")->gpuMemPeakMib) << samples;
    // The error falls as theory says: more kernel samples, less noise against the ray-traced AO.
    for (const char* res : {"full", "half"}) {
        const TradeoffRow *few = rowOf(t, "4", res), *many = rowOf(t, "64", res);
        ASSERT_TRUE(few && many);
        EXPECT_LT(many->error, few->error) << res;
    }
    // The same point numbering as the grid: samples outer, resolution inner.
    EXPECT_EQ(rowOf(t, "16", "half")->point, 3);

    // The table on stdout says what its numbers are and marks the front.
    // "ao" is the AO buffer the lighting pass reads (ao.filtered).
    const std::string ao = TradeoffRunner::gpuOutput("ao");
    EXPECT_NE(r.out.find("rms of ao (" + ao + ") against the CPU reference"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("**front**"), std::string::npos);
    EXPECT_NE(r.out.find("| point | ssao.samples | ssao.resolution |"), std::string::npos) << r.out;

    // --json is an experiment record (docs/records.md), not a format of its own.
    std::ifstream jf(dir() / "grid.json");
    const nlohmann::json rec = nlohmann::json::parse(jf);
    EXPECT_EQ(rec["format"], "deferred-workbench record");
    EXPECT_EQ(rec["version"], 2);
    EXPECT_EQ(rec["command"], "tradeoff");
    EXPECT_EQ(rec["size"], nlohmann::json::array({160, 90}));
    EXPECT_EQ(rec["frames"], 2);
    EXPECT_EQ(rec["knobs"]["ssao_blur.mode"], "off");  // the knobs every point starts from
    EXPECT_EQ(rec["grid"]["axes"][0]["name"], "ssao.samples");
    EXPECT_EQ(rec["grid"]["axes"][0]["values"], nlohmann::json::array({"4", "16", "64"}));
    EXPECT_EQ(rec["grid"]["metric"], "rms");
    EXPECT_EQ(rec["grid"]["buffer"], "ao");
    EXPECT_FALSE(rec["gl"]["renderer"].get<std::string>().empty());
    EXPECT_FALSE(rec["host"]["cpu"].get<std::string>().empty());
    EXPECT_EQ(rec["seeds"]["bootstrap"], "12345");
    const nlohmann::json& j = rec["results"];
    ASSERT_EQ(j["rows"].size(), 6u);
    ASSERT_EQ(j["metrics"].size(), 6u);
    for (size_t i = 0; i < 6; ++i) {
        const TradeoffRow& row = t.rows[i];
        const nlohmann::json& m = j["metrics"][i];
        EXPECT_EQ(m["point"], row.point);
        EXPECT_EQ(m["metric"], "rms");
        EXPECT_EQ(m["buffer"], "ao");
        EXPECT_EQ(m["against"], "reference");
        EXPECT_EQ(m["value"].get<double>(), row.error) << "the record's error is the CSV's";
        EXPECT_EQ(j["rows"][i]["values"]["ssao.samples"], row.axisValues[0]);
        EXPECT_EQ(j["rows"][i]["frame_gpu_ms"].get<double>(), row.frameGpuMs);
    }
    EXPECT_EQ(static_cast<int>(j["front"].size()), onFront);
    EXPECT_EQ(j["settings"]["against"], "reference");
    EXPECT_EQ(j["settings"]["buffer"], "ao (" + ao + ")");
    EXPECT_EQ(j["settings"]["references_rendered"].get<std::string>() == "1" ||
                  j["settings"]["references_from_cache"].get<std::string>() == "1",
              true)
        << "one reference for the one camera";

    // replay runs the same sweep again: every error the same (deterministic on
    // one machine), each time old -> new with the interval of the difference.
    const Result again = run("replay " + (dir() / "grid.json").string() + " --record " + (dir() / "again.json").string());
    ASSERT_TRUE(again.code == 0 || again.code == 1) << again.err << again.out;
    EXPECT_EQ(again.out.find("(differs)"), std::string::npos) << again.out;
    EXPECT_EQ(again.out.find(": not in the record"), std::string::npos) << again.out;
    EXPECT_EQ(again.out.find("not run again"), std::string::npos) << again.out;
    EXPECT_EQ(again.out.find("knob not in this build"), std::string::npos) << again.out;
    EXPECT_NE(again.out.find("point 3 camera 0, ssao.samples=16, ssao.resolution=half: rms "), std::string::npos) << again.out;
    EXPECT_NE(again.out.find("(same); frame gpu median"), std::string::npos) << again.out;
    // Exit 1 on a busy machine only for a frame time moved beyond the band, never for an error.
    if (again.code == 1) EXPECT_NE(again.out.find("(0 row(s) with another error"), std::string::npos) << again.out;
    else EXPECT_NE(again.out.find("tradeoff: the same (6 rows"), std::string::npos) << again.out;
    // A changed error is "differs" (exit 1).
    nlohmann::json changed = rec;
    changed["results"]["rows"][0]["error"] = row0Error(changed) * 2.0;
    std::ofstream((dir() / "changed.json").string()) << changed.dump(2);
    const Result differs = run("replay " + (dir() / "changed.json").string());
    EXPECT_EQ(differs.code, 1) << differs.err << differs.out;
    EXPECT_NE(differs.out.find("point 0 camera 0, ssao.samples=4, ssao.resolution=full: rms "), std::string::npos);
    EXPECT_NE(differs.out.find("(differs)"), std::string::npos) << differs.out;
    EXPECT_NE(differs.out.find("1 row(s) with another error"), std::string::npos) << differs.out;

    const FloatImage png = loadImageFloat((dir() / "grid.png").string());
    EXPECT_EQ(png.width, 320);
    EXPECT_EQ(png.height, 240);
}

TEST(TradeoffCli, ShardsMergeToOneRunsTable) {
    const std::string grid = "tradeoff --scene default --size 160x90 --set ssao_blur.mode=off --sweep ssao.samples=4,64 "
                             "--sweep ssao.resolution=full,half --metric rms --buffer ao --frames 1 --warmup 0 "
                             "--resamples 200 --quiet";
    const Result whole = run(grid + files("whole"));
    ASSERT_EQ(whole.code, 0) << whole.err;
    for (int i = 0; i < 2; ++i) {
        const std::string name = "shard" + std::to_string(i);
        const Result s = run(grid + " --shard " + std::to_string(i) + "/2" + files(name));
        ASSERT_EQ(s.code, 0) << s.err;
    }
    const Result m = run("tradeoff merge " + (dir() / "shard0.csv").string() + " " + (dir() / "shard1.csv").string() +
                         " --out " + (dir() / "merged.csv").string());
    ASSERT_EQ(m.code, 0) << m.err;
    const TradeoffTable a = TradeoffTable::readCsv((dir() / "whole.csv").string());
    const TradeoffTable b = TradeoffTable::readCsv((dir() / "merged.csv").string());
    EXPECT_EQ(a.axes, b.axes);
    ASSERT_EQ(a.rows.size(), b.rows.size());
    for (size_t i = 0; i < a.rows.size(); ++i) {
        EXPECT_EQ(a.rows[i].point, b.rows[i].point);
        EXPECT_EQ(a.rows[i].axisValues, b.rows[i].axisValues);
        EXPECT_EQ(a.rows[i].camera, b.rows[i].camera);
        // Errors are deterministic (the same frames, the same reference); times are not.
        EXPECT_EQ(a.rows[i].error, b.rows[i].error) << i;
        EXPECT_EQ(a.rows[i].errorLo, b.rows[i].errorLo) << i;
    }
    // The shards' records (tradeoff --json) merge to the same table, and the merged record holds it.
    const Result mj = run("tradeoff merge " + (dir() / "shard0.json").string() + " " + (dir() / "shard1.json").string() +
                          " --out " + (dir() / "merged-records.csv").string() + " --json " +
                          (dir() / "merged-records.json").string());
    ASSERT_EQ(mj.code, 0) << mj.err;
    const TradeoffTable c = TradeoffTable::readCsv((dir() / "merged-records.csv").string());
    ASSERT_EQ(c.rows.size(), a.rows.size());
    for (size_t i = 0; i < a.rows.size(); ++i) {
        EXPECT_EQ(c.rows[i].point, a.rows[i].point);
        EXPECT_EQ(c.rows[i].axisValues, a.rows[i].axisValues);
        EXPECT_EQ(c.rows[i].error, a.rows[i].error) << i;
        EXPECT_EQ(c.rows[i].frameGpuMs, b.rows[i].frameGpuMs) << i;  // the shards' own times, as the CSV merge
    }
    std::ifstream mf(dir() / "merged-records.json");
    const nlohmann::json merged = nlohmann::json::parse(mf);
    EXPECT_EQ(merged["command"], "tradeoff");
    EXPECT_EQ(merged["grid"]["merged"], true);
    EXPECT_EQ(merged["results"]["rows"].size(), a.rows.size());
    EXPECT_EQ(merged["size"], nlohmann::json::array({160, 90}));
    // A merged record has no sweep to run again: replay refuses it (exit 2).
    const Result refused = run("replay " + (dir() / "merged-records.json").string());
    EXPECT_EQ(refused.code, 2) << refused.out;
    EXPECT_NE(refused.err.find("no sweep to run again"), std::string::npos) << refused.err;

    // A missing shard is said (the shards' records beside their CSVs say which they are).
    const Result one = run("tradeoff merge " + (dir() / "shard0.csv").string() + " --out " + (dir() / "one.csv").string());
    ASSERT_EQ(one.code, 0) << one.err;
    EXPECT_NE(one.err.find("tradeoff merge: warning: shard(s) 1 of 2 are not among the inputs"), std::string::npos)
        << one.err;
    EXPECT_EQ(m.err.find("warning"), std::string::npos) << m.err;
    // A shard of another run (here: another metric) is refused, naming both files and the field.
    {
        std::ifstream in(dir() / "shard1.csv");
        std::stringstream text;
        text << in.rdbuf();
        std::string csv = text.str();
        for (size_t at = csv.find(",rms,"); at != std::string::npos; at = csv.find(",rms,", at)) csv.replace(at, 5, ",flip,");
        std::ofstream(dir() / "other-run.csv") << csv;
    }
    const Result other = run("tradeoff merge " + (dir() / "shard0.csv").string() + " " +
                             (dir() / "other-run.csv").string() + " --out " + (dir() / "other.csv").string());
    EXPECT_NE(other.code, 0);
    EXPECT_NE(other.err.find("other-run.csv: comes from another tradeoff run than " + (dir() / "shard0.csv").string() +
                             " (metric 'flip' against 'rms')"),
              std::string::npos)
        << other.err;

    // Merging a shard twice is refused, naming both.
    const Result twice = run("tradeoff merge " + (dir() / "shard0.csv").string() + " " + (dir() / "shard0.csv").string() +
                             " --out " + (dir() / "twice.csv").string());
    EXPECT_NE(twice.code, 0);
}

TEST(TradeoffCli, ExcludeAndOrbitAndAgainstAConfiguration) {
    // Against a named configuration (blur on) with two orbit cameras: rows per camera and over all.
    const Result r = run("tradeoff --scene default --size 160x90 --sweep ssao.samples=4,16,64 "
                         "--exclude ssao.samples=16 --against ssao_blur.mode=bilateral --set ssao_blur.mode=off "
                         "--buffer ao --metric rms --orbit 2 --frames 2 --warmup 0 --resamples 200 --quiet" +
                         files("orbit"));
    ASSERT_EQ(r.code, 0) << r.err;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "orbit.csv").string());
    ASSERT_EQ(t.rows.size(), 6u);  // 2 points x (2 cameras + all)
    EXPECT_EQ(t.rows[0].point, 0);
    EXPECT_EQ(t.rows[3].point, 2);  // point 1 (16 samples) left out; the numbers stay the grid's
    EXPECT_EQ(t.rows[2].camera, "all");
    EXPECT_NEAR(t.rows[2].error, 0.5 * (t.rows[0].error + t.rows[1].error), 1e-12);
    EXPECT_EQ(t.rows[2].frames, 4);
}

// Issue 23's shadow check: with the error restricted to the pixels near the
// reference's shadow edges, a larger shadow map has the smaller error.
TEST(TradeoffCli, ShadowEdgeErrorFallsAsTheMapGrows) {
    const Result r = run("tradeoff --scene spheres --size 160x90 --set shadows.pcf_radius=0 --sweep "
                         "shadows.map_size=128,1024 --buffer shadow --mask shadow_edges --metric rms --frames 1 "
                         "--warmup 0 --resamples 200 --time lighting --quiet" + files("shadow"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "shadow.csv").string());
    ASSERT_EQ(t.rows.size(), 2u);
    for (const auto& row : t.rows) {
        EXPECT_EQ(row.buffer, "shadow:shadow_edges");
        EXPECT_TRUE(std::isfinite(row.error) && row.error > 0.0) << row.point;
    }
    // Measured: 0.168 (128) and 0.075 (1024) at pcf_radius 1, 160x90.
    EXPECT_LT(t.rows[1].error, 0.75 * t.rows[0].error);
    EXPECT_NE(r.out.find("rms of shadow (lighting.shadow)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("| Pareto (lighting ms) |"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("within 2 px of an edge of the reference's shadow buffer"), std::string::npos) << r.out;
}

// Issue 23's normal-encoding check, on normals the view actually shows near
// -z (Kircher-Lawrance's worst case): scenes/normals-minus-z.json's floor
// seen from a steep, 178-degree camera, its view-space normal 10, 7, 4 and
// 2 degrees from -z along the path. The octahedral encoding's L-buffer error
// is a fraction of KL's over the cameras.
TEST(TradeoffCli, OctahedralNormalsBeatKircherLawranceNearMinusZ) {
    const Result r = run("tradeoff --scene " + (test::scenesDir() / "normals-minus-z.json").string() +
                         " --size 160x90 --walkthrough --set ao.enabled=false --set shadows.enabled=false "
                         "--set gbuffer.texture_filter=base_level --sweep gbuffer.normal_encoding=kl16,oct16 "
                         "--buffer lbuffer --metric rms --frames 1 --warmup 0 --resamples 200 --quiet" +
                         files("normals-minus-z"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "normals-minus-z.csv").string());
    ASSERT_EQ(t.rows.size(), 10u);  // 2 points x (4 cameras + all)
    auto error = [&](const std::string& encoding, const std::string& camera) {
        for (const auto& row : t.rows)
            if (t.axisValue(row, "gbuffer.normal_encoding") == encoding && row.camera == camera) return row.error;
        return std::nan("");
    };
    // Measured at 160x90: kl16 4.6e-5, oct16 6.7e-6 over the cameras; at
    // the first camera (10 degrees from -z) 1.1e-4 against 7.4e-6.
    EXPECT_GT(error("kl16", "all"), 0.0);
    EXPECT_LT(error("oct16", "all"), 0.5 * error("kl16", "all"));
    EXPECT_LT(error("oct16", "0"), 0.25 * error("kl16", "0"));
}

// With shadows.reuse_map on, the shadows pass draws no map (each is drawn
// just before its light is shaded, in the lighting pass): its ~0 ms is true.
// The maps' time is the column gpu_ms.lighting/shadow maps, and --time
// shadows marks the rows where the maps were reused.
TEST(TradeoffCli, ReusedShadowMapsAreTimedInTheLightingPassAndMarked) {
    const Result r = run("tradeoff --scene spheres --size 64x36 --set ao.enabled=false --sweep shadows.reuse_map=true,false "
                         "--buffer lbuffer --metric rms --time shadows --frames 1 --warmup 0 --resamples 200 --quiet" +
                         files("reuse"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "reuse.csv").string());
    ASSERT_EQ(t.rows.size(), 2u);
    ASSERT_NE(std::find(t.passes.begin(), t.passes.end(), "lighting/shadow maps"), t.passes.end());
    EXPECT_EQ(std::find(t.passes.begin(), t.passes.end(), "shadows/shadow maps"), t.passes.end());
    EXPECT_TRUE(std::isfinite(t.passGpuMs(t.rows[0], "lighting/shadow maps")));  // reused: drawn while lighting
    EXPECT_FALSE(std::isfinite(t.passGpuMs(t.rows[1], "lighting/shadow maps")));  // kept: drawn by the shadows pass
    EXPECT_NE(r.out.find("(reused: maps in lighting/shadow maps, "), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("(reused"), r.out.rfind("(reused")) << "only the reused row is marked\n" << r.out;
    // A span is a valid --time (the early check of the pass's name takes PASS/NAME).
    const Result span = run("tradeoff --scene spheres --size 64x36 --set ao.enabled=false --sweep shadows.pcf_radius=0,1 "
                            "--buffer lbuffer --metric rms --time \"lighting/shadow maps\" --frames 1 --warmup 0 "
                            "--resamples 200 --quiet" + files("span"));
    EXPECT_EQ(span.code, 0) << span.err;
    EXPECT_NE(span.out.find("Pareto (lighting/shadow maps ms)"), std::string::npos) << span.out;
}

// Issue 23: --mask shadow_edges on a scene without a shadow edge (the
// normals-minus-z floor, lit by point lights that cast none) leaves every
// camera without an error: the run fails with the reason, even with --quiet,
// instead of writing an empty plot.
TEST(TradeoffCli, NoErrorOnAnyCameraFailsClearly) {
    const Result r = run("tradeoff --scene " + (test::scenesDir() / "normals-minus-z.json").string() +
                         " --size 64x36 --orbit 2 --sweep ssao.samples=4,8 --mask shadow_edges --buffer shadow "
                         "--metric rms --frames 1 --warmup 0 --resamples 100 --quiet" +
                         files("no-error"));
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.err.find("no camera of any point has an error, so there is no front to plot (point 0, camera 0: the "
                         "mask selects no pixel; and 3 more like it)"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir() / "no-error.png"));
}

// compare --against reference --buffer shadow: lighting.shadow against the
// reference's shadow rays, one channel, close but not equal (the map's edges).
TEST(TradeoffCli, CompareAgainstTheReferenceShadowBuffer) {
    const fs::path json = dir() / "compare-shadow.json";
    const Result r = run("compare --against reference --scene spheres --size 160x90 --buffer shadow --fail 2 --warn 2 --json " +
                         json.string());
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    std::ifstream jf(json);
    const nlohmann::json j = nlohmann::json::parse(jf);
    EXPECT_EQ(j["channels"].get<int>(), 1);
    // Measured: RMS 0.042 (map 1024, PCF 1, 160x90); 1.0 everywhere would miss the shadows by far more.
    EXPECT_GT(j["rms"].get<double>(), 0.0);
    EXPECT_LT(j["rms"].get<double>(), 0.08);
}

TEST(TradeoffCli, BadInputIsOneClearMessage) {
    struct Case {
        std::string args, message;
    };
    const std::string base = "tradeoff --scene default --size 160x90 --frames 1 --quiet --csv " +
                             (dir() / "bad.csv").string() + " --json " + (dir() / "bad.json").string() + " --plot " +
                             (dir() / "bad.png").string();
    const Case cases[] = {
        {" --sweep ssao.nonsense=1,2", "unknown knob 'ssao.nonsense'"},
        {" --sweep ssao.samples=4,many", "ssao.samples"},
        {" --sweep ssao.samples=4,8 --exclude ssao.samples=4,8", "the sweep is empty after --exclude"},
        {" --sweep ssao.samples=4,8 --exclude ssao.radius=1", "'ssao.radius' is not an axis of this sweep"},
        {" --sweep ssao.samples=4,8 --metric mse", "--metric: expected flip, rms, psnr, ssim or temporal, got 'mse'"},
        {" --sweep ssao.samples=4,8 --buffer shade", "--buffer: expected final, lbuffer, ao or shadow, got 'shade'"},
        {" --sweep ssao.samples=4,8 --mask edges", "--mask: expected shadow_edges, got 'edges'"},
        {" --sweep ssao.samples=4 --time bogus", "--time bogus: the pipeline has no pass of that name (expected frame or one of: "},
        {" --sweep ssao.samples=4,8 --cost pixels",
         "--cost: expected one of gpu_ms, fragments, samples, primitives, vertices, compute, bytes, got 'pixels'"},
        {" --sweep ssao.samples=4,8 --cost fragments --no-counters", "--cost fragments needs the counters"},
        {" --presets SSAO1,NOPE", "NOPE"},
        {"", "tradeoff needs axes"},
    };
    for (const auto& c : cases) {
        const Result r = run(base + c.args);
        EXPECT_NE(r.code, 0) << c.args;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
        // One message: a single line on stderr (a usage error adds where the options are listed).
        std::istringstream lines(r.err);
        int messages = 0;
        for (std::string line; std::getline(lines, line);)
            messages += !line.empty() && line.rfind("(deferred-workbench help", 0) != 0;
        EXPECT_EQ(messages, 1) << c.args << "\n" << r.err;
    }
}

// Issue 34's case: the four SSAO sample counts' AO errors lie within each
// other's noise, so the output says they cannot be told apart in error (the
// table's line, each row's tied_with, no row dominated), whatever their
// times; the budget's pick names the points it cannot be told apart from.
TEST(TradeoffCli, SsaoSampleCountsCannotBeToldApartInError) {
    const Result r = run("tradeoff --scene default --size 160x90 --sweep ssao.samples=4,8,16,32 --metric rms "
                         "--buffer ao --frames 6 --warmup 1 --resamples 500 --time ao --budget-ms 1000 --quiet" +
                         files("ssao-noise"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("front: error: points 0, 1, 2 and 3 cannot be told apart"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Holm's step-down over 12 comparison(s)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("front: dominated: none"), std::string::npos) << r.out;
    // Fewer than 6 rounds: time is not tested, and the rule line says so.
    const Result few = run("tradeoff --scene default --size 64x36 --sweep ssao.samples=4,32 --metric rms --buffer ao "
                           "--frames 3 --warmup 0 --resamples 200 --quiet --plot none --csv " +
                           (dir() / "few.csv").string() + " --json " + (dir() / "few.json").string());
    ASSERT_EQ(few.code, 0) << few.err;
    EXPECT_NE(few.out.find("time not tested for 1 pair(s) (no resamples: fewer than 6 rounds"), std::string::npos)
        << few.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "ssao-noise.csv").string());
    ASSERT_EQ(t.rows.size(), 4u);
    EXPECT_EQ(t.time, "ao");
    int picks = 0;
    for (const auto& row : t.rows) {
        EXPECT_NE(row.front, "dominated") << row.point;
        EXPECT_TRUE(row.front == "pareto" || row.front == "indistinguishable") << row.front;
        EXPECT_EQ(row.tiedWith.size(), 3u) << row.point;  // every other point, on error at least
        for (const auto& [point, axes] : row.tiedWith) EXPECT_NE(axes, "time") << row.point << " " << point;
        EXPECT_EQ(row.timeMs, t.passGpuMs(row, "ao"));  // one pass: its median, now with an interval
        EXPECT_LE(row.timeMsLo, row.timeMs);
        picks += row.pick == "pick" ? 1 : 0;
    }
    EXPECT_EQ(picks, 1);
    EXPECT_NE(r.out.find("pick: point "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("cannot be told apart in error from point(s) "), std::string::npos) << r.out;
    // The record carries the front and the pick.
    std::ifstream jf(dir() / "ssao-noise.json");
    const nlohmann::json rec = nlohmann::json::parse(jf);
    EXPECT_EQ(rec["results"]["rows"][0]["tied_with"].size(), 3u);
    EXPECT_EQ(rec["results"]["settings"]["budget_ms"], "1000");
    EXPECT_TRUE(rec["results"]["settings"]["pick"].is_array());
}

// --time takes a sum of passes: the table names it, the CSV carries the
// per-frame sums' median and interval, merge keeps it and refuses another sum;
// an unknown term is refused before the timed rounds; a budget nothing fits
// says the cheapest point's time.
TEST(TradeoffCli, TimeSumsOfPassesAndABudgetNothingFits) {
    const std::string sweep = "tradeoff --scene default --size 64x36 --sweep ssao.samples=4,32 --metric rms --buffer ao "
                              "--frames 2 --warmup 0 --resamples 200 --quiet ";
    const Result r = run(sweep + "--time lighting+ao+ao_filter --budget-ms 0.001" + files("sum"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("| lighting+ao+ao_filter GPU ms median | 95% CI | Pareto (lighting+ao+ao_filter ms) |"),
              std::string::npos) << r.out;
    EXPECT_NE(r.out.find("pick: none fits the budget of 0.001 ms"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("the cheapest, point "), std::string::npos) << r.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "sum.csv").string());
    EXPECT_EQ(t.time, "lighting+ao+ao_filter");
    for (const auto& row : t.rows) {
        // Two frames: the median of the per-frame sums is their mean, within the terms' medians' sum's reach.
        EXPECT_GT(row.timeMs, t.passGpuMs(row, "lighting"));
        EXPECT_EQ(row.pick, "over");
    }
    const std::string csv = (dir() / "sum.csv").string(), out = (dir() / "sum-merged.csv").string();
    const Result same = run("tradeoff merge " + csv + " --out " + out + " --plot none --time lighting+ao+ao_filter");
    EXPECT_EQ(same.code, 0) << same.err;
    EXPECT_NE(same.out.find("front: from the rows' 95% intervals"), std::string::npos) << same.out;
    const Result other = run("tradeoff merge " + csv + " --out " + out + " --plot none --time lighting+ao");
    EXPECT_EQ(other.code, 2);  // a usage error, as every bad --time
    EXPECT_NE(other.err.find("the rows carry time lighting+ao+ao_filter, not this sum"), std::string::npos) << other.err;
    // Without --time a merge ranks by the CSV's time column (the run's), and keeps it.
    const Result kept = run("tradeoff merge " + csv + " --out " + out + " --plot none --budget-ms 0.001");
    ASSERT_EQ(kept.code, 0) << kept.err;
    EXPECT_NE(kept.out.find("Pareto (lighting+ao+ao_filter ms)"), std::string::npos) << kept.out;
    EXPECT_EQ(TradeoffTable::readCsv(out).time, "lighting+ao+ao_filter");
    // Another --time than the shards' is said, then used.
    const Result frame = run("tradeoff merge " + csv + " --out " + out + " --plot none --time frame");
    ASSERT_EQ(frame.code, 0) << frame.err;
    EXPECT_NE(frame.err.find("tradeoff merge: note: --time frame ranks by another time than the shards' (their time "
                             "column is lighting+ao+ao_filter)"),
              std::string::npos)
        << frame.err;
    EXPECT_EQ(TradeoffTable::readCsv(out).time, "frame");
    // A budget on one pass's median (no interval in the CSV) could never fit: refused in one line.
    const Result noInterval = run("tradeoff merge " + csv + " --out " + out + " --plot none --time ao --budget-ms 25");
    EXPECT_EQ(noInterval.code, 2);
    EXPECT_NE(noInterval.err.find("--budget-ms: the time ao has no interval in these shards"), std::string::npos)
        << noInterval.err;
    EXPECT_EQ(noInterval.out, "");
    for (const char* spec : {"ao+", "frame+ao", "ao+ao"}) {
        const Result syntax = run(sweep + "--time " + spec + files("sum-bad"));
        EXPECT_EQ(syntax.code, 2) << spec << syntax.err;
        EXPECT_NE(syntax.err.find(std::string("--time ") + spec + ":"), std::string::npos) << syntax.err;
    }
    const Result bad = run(sweep + "--time lighting+aox" + files("sum-bad"));
    EXPECT_EQ(bad.code, 2);
    EXPECT_NE(bad.err.find("--time lighting+aox: the pipeline has no pass 'aox'"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(dir() / "sum-bad.csv"));
}

// The cost counters: two runs of the same sweep give the same counter
// columns, bit for bit (times differ); --cost fragments ranks the front by
// the frame's fragment shader invocations, and the table says so.
TEST(TradeoffCli, CountersRepeatBitForBitAndChooseTheCostAxis) {
    const std::string sweep =
        "tradeoff --scene default --size 96x54 --set ssao_blur.mode=off --sweep ssao.samples=4,16 "
        "--sweep ssao.resolution=full,half --against ssao.samples=64 --metric rms --buffer ao --frames 2 --warmup 1 "
        "--resamples 100 --quiet --plot none";
    const Result a = run(sweep + " --csv " + (dir() / "counted-a.csv").string() + " --json " +
                         (dir() / "counted-a.json").string());
    ASSERT_EQ(a.code, 0) << a.err;
    const Result b = run(sweep + " --cost fragments --time ao --csv " + (dir() / "counted-b.csv").string() + " --json " +
                         (dir() / "counted-b.json").string());
    ASSERT_EQ(b.code, 0) << b.err;
    const TradeoffTable ta = TradeoffTable::readCsv((dir() / "counted-a.csv").string());
    const TradeoffTable tb = TradeoffTable::readCsv((dir() / "counted-b.csv").string());
    ASSERT_TRUE(ta.counted);
    ASSERT_EQ(ta.passes, tb.passes);
    ASSERT_EQ(ta.rows.size(), 4u);
    for (size_t r = 0; r < ta.rows.size(); ++r) {
        for (size_t i = 0; i < PassCounts::kCount; ++i) {
            EXPECT_FALSE(std::isnan(ta.rows[r].frameCounts[i])) << PassCounts::name(static_cast<int>(i));
            EXPECT_EQ(ta.rows[r].frameCounts[i], tb.rows[r].frameCounts[i]) << "row " << r << " " << PassCounts::name(static_cast<int>(i));
        }
        for (size_t p = 0; p < ta.passes.size(); ++p)
            for (size_t i = 0; i < PassCounts::kCount; ++i) {
                const double x = ta.rows[r].passCounts[p][i], y = tb.rows[r].passCounts[p][i];
                EXPECT_TRUE((std::isnan(x) && std::isnan(y)) || x == y) << ta.passes[p] << " " << PassCounts::name(static_cast<int>(i));
            }
    }
    // A half-resolution AO shades fewer fragments than a full one, at either sample count.
    const TradeoffRow* full = rowOf(ta, "16", "full");
    const TradeoffRow* half = rowOf(ta, "16", "half");
    ASSERT_TRUE(full && half);
    EXPECT_LT(ta.passCount(*half, "ao", PassCounts::Fragments), ta.passCount(*full, "ao", PassCounts::Fragments));
    // The front of b is the front by fragments.ao against the error.
    TradeoffTable check = tb;
    check.markParetoFront("ao", "fragments");
    for (size_t r = 0; r < tb.rows.size(); ++r) EXPECT_EQ(tb.rows[r].pareto, check.rows[r].pareto) << r;
    EXPECT_NE(b.out.find("| fragments.ao (exact) | Pareto (fragments.ao) |"), std::string::npos) << b.out;
    // The summary names the cost axis, exact and untested, and the rule says only the error was tested;
    // a's time (2 frames: no paired resamples) is not tested, not "cannot be told apart".
    EXPECT_NE(b.out.find("front: fragments.ao (an exact counter, compared by value, not tested): "), std::string::npos)
        << b.out;
    EXPECT_EQ(b.out.find("front: time:"), std::string::npos) << b.out;
    EXPECT_NE(b.out.find("pair(s) on error only; the cost, an exact counter, compared by value)"), std::string::npos)
        << b.out;
    EXPECT_NE(a.out.find("front: time: not tested (no paired resamples: fewer than 6 rounds"), std::string::npos)
        << a.out;
    // The record keeps the counters and the cost axis.
    std::ifstream in(dir() / "counted-b.json");
    const nlohmann::json record = nlohmann::json::parse(in);
    EXPECT_EQ(record["grid"]["cost"], "fragments");
    EXPECT_EQ(record["results"]["rows"][0]["counters"]["frame"]["fragments"].get<double>(), tb.rows[0].frameCounts[0]);
}

// --cost fragments --budget N: the pick is the least-error point whose
// fragments (of the --time span, exact) are under N; every other row fits or
// is over by its count. --budget with --budget-ms, --budget without a
// counter --cost, and a budget of 0 or NaN are refused in one line before anything renders.
TEST(TradeoffCli, CounterBudgetPicksTheLeastErrorUnderIt) {
    const std::string sweep =
        "tradeoff --scene default --size 96x54 --set ssao_blur.mode=off --sweep ssao.samples=4,16 "
        "--sweep ssao.resolution=full,half --against ssao.samples=64 --metric rms --buffer ao --frames 2 --warmup 1 "
        "--resamples 100 --quiet --plot none --cost fragments --time ao";
    const Result first = run(sweep + files("budget-n"));
    ASSERT_EQ(first.code, 0) << first.err;
    const TradeoffTable counted = TradeoffTable::readCsv((dir() / "budget-n.csv").string());
    ASSERT_EQ(counted.rows.size(), 4u);
    // The budget: just above the half-resolution points' count, under the full ones'.
    double half = 0.0, full = std::numeric_limits<double>::infinity();
    for (const auto& row : counted.rows) {
        const double f = counted.costOf(row, "ao", "fragments");
        ASSERT_FALSE(std::isnan(f));
        if (counted.axisValue(row, "ssao.resolution") == "half") half = std::max(half, f);
        else full = std::min(full, f);
    }
    ASSERT_LT(half, full);
    const double budget = half + 1.0;
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", budget);
    const Result r = run(sweep + " --budget " + text + files("budget-pick"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "budget-pick.csv").string());
    const TradeoffRow* best = nullptr;
    for (const auto& row : t.rows) {
        const bool fits = t.costOf(row, "ao", "fragments") < budget;
        EXPECT_EQ(fits, t.axisValue(row, "ssao.resolution") == "half") << row.point;
        EXPECT_EQ(row.pick == "over", !fits) << row.point << " " << row.pick;
        if (fits && (!best || row.error < best->error)) best = &row;
    }
    ASSERT_TRUE(best);
    EXPECT_EQ(best->pick, "pick");
    EXPECT_NE(r.out.find("pick: point " + std::to_string(best->point)), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("fragments ends under the budget of"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("(exact)"), std::string::npos) << r.out;
    // Refused, one line each, no files.
    const std::string plain = "tradeoff --scene default --size 64x36 --sweep ssao.samples=4,32 --metric rms --buffer ao "
                              "--frames 2 --warmup 0 --resamples 200 --quiet ";
    struct Bad {
        std::string args, says;
    };
    for (const Bad& b : {Bad{"--cost fragments --budget 1000 --budget-ms 5", "--budget-ms and --budget: give one"},
                         Bad{"--budget 1000", "--budget bounds a counter: give --cost"},
                         Bad{"--cost fragments --budget 0", "--budget must be"},
                         Bad{"--cost fragments --budget nan", "--budget"}}) {
        const Result bad = run(plain + b.args + files("budget-bad"));
        EXPECT_EQ(bad.code, 2) << b.args;  // a usage error: the line, then where the options are listed
        const std::string line = bad.err.substr(0, bad.err.find('\n'));
        EXPECT_NE(line.find(b.says), std::string::npos) << b.args << ": " << bad.err;
        EXPECT_NE(bad.err.find("(deferred-workbench help tradeoff lists its options)"), std::string::npos) << bad.err;
        EXPECT_FALSE(fs::exists(dir() / "budget-bad.csv")) << b.args;
    }
}

// Issue 34 part 5: three AO methods, each a study of its own knobs, in one
// run: one CSV (the column study names each point's), one front across every
// point, one record; replay of it says "the same" (errors, their intervals
// and the counters are exact; two frames give no time interval to move); a
// record edited in a counter and an error makes replay name those numbers.
TEST(TradeoffCli, ThreeAoMethodStudiesAreOneRecordThatReplaysTheSame) {
    const std::string studies =
        "tradeoff --scene default --size 48x27 --frames 2 --warmup 0 --resamples 100 --metric rms --buffer ao --quiet "
        "--study ao.method=ssao:ssao.samples=4,8 --study ao.method=gtao:gtao.slices=1,2 "
        "--study ao.method=aov:aov.resolution=half,full";
    const Result r = run(studies + files("studies"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("| point | study | ao.method | ssao.samples | gtao.slices | aov.resolution |"), std::string::npos)
        << r.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "studies.csv").string());
    ASSERT_EQ(t.axes.front(), "study");
    ASSERT_EQ(t.rows.size(), 6u);
    std::map<std::string, int> perStudy;
    int onFront = 0;
    for (const auto& row : t.rows) {
        const std::string study = t.axisValue(row, "study");
        ++perStudy[study];
        EXPECT_EQ(t.axisValue(row, "ao.method"), study) << "a study's fixed knob names it";
        EXPECT_FALSE(std::isnan(row.error)) << row.point;
        onFront += row.front == "pareto";
        // One front across the studies: a dominated point is dominated by points of any study.
        EXPECT_TRUE(row.front == "pareto" || row.front == "indistinguishable" || row.front == "dominated") << row.front;
    }
    EXPECT_EQ(perStudy, (std::map<std::string, int>{{"aov", 2}, {"gtao", 2}, {"ssao", 2}}));
    EXPECT_GE(onFront, 1);
    // The knobs a study does not name hold the run's values: one value in the other studies.
    std::set<std::string> samplesOutsideSsao;
    for (const auto& row : t.rows)
        if (t.axisValue(row, "study") != "ssao") samplesOutsideSsao.insert(t.axisValue(row, "ssao.samples"));
    EXPECT_EQ(samplesOutsideSsao.size(), 1u);
    // One record: its grid lists the points and what the front used.
    std::ifstream in(dir() / "studies.json");
    const nlohmann::json rec = nlohmann::json::parse(in);
    EXPECT_EQ(rec["grid"]["points"].size(), 6u);
    EXPECT_EQ(rec["grid"]["time"], "frame");
    EXPECT_EQ(rec["results"]["rows"].size(), 6u);
    EXPECT_EQ(rec["results"]["rows"][5]["values"]["study"], "aov");

    const Result again = run("replay " + (dir() / "studies.json").string());
    EXPECT_EQ(again.code, 0) << again.err << again.out;
    EXPECT_NE(again.out.find("tradeoff: the same (6 rows, every error equal"), std::string::npos) << again.out;
    EXPECT_NE(again.out.find("every error interval equal"), std::string::npos) << again.out;
    EXPECT_NE(again.out.find("every counter equal"), std::string::npos) << again.out;
    EXPECT_NE(again.out.find("point 2 camera 0, study=gtao, ao.method=gtao,"), std::string::npos) << again.out;

    // Edited: a counter of row 1 and the error interval of row 3; replay names each number.
    nlohmann::json edited = rec;
    nlohmann::json& counted = edited["results"]["rows"][1]["counters"]["frame"]["fragments"];
    const double fragments = counted.get<double>();
    counted = fragments + 1.0;
    edited["results"]["rows"][3]["error_ci95"][1] = edited["results"]["rows"][3]["error_ci95"][1].get<double>() * 2.0;
    std::ofstream((dir() / "studies-edited.json").string()) << edited.dump(2);
    const Result moved = run("replay " + (dir() / "studies-edited.json").string());
    EXPECT_EQ(moved.code, 1) << moved.err << moved.out;
    char counter[96];
    std::snprintf(counter, sizeof counter, "counters moved: fragments %.17g -> %.17g", fragments + 1.0, fragments);
    EXPECT_NE(moved.out.find(counter), std::string::npos) << moved.out;
    EXPECT_NE(moved.out.find("point 3 camera 0, study=gtao"), std::string::npos) << moved.out;
    EXPECT_NE(moved.out.find(": error_ci95 ["), std::string::npos) << moved.out;
    EXPECT_NE(moved.out.find("(moved; rule: equal to 1e-9 relative, as the error)"), std::string::npos) << moved.out;
    EXPECT_NE(moved.out.find("1 with a counter moved"), std::string::npos) << moved.out;
    EXPECT_NE(moved.out.find("1 with another error interval"), std::string::npos) << moved.out;
    EXPECT_NE(moved.out.find("record edited: its results"), std::string::npos) << moved.out;
}

// A study file names its studies; bad --study input is one line, exit 2, nothing written.
TEST(TradeoffCli, StudyFileAndBadStudiesAreOneClearLine) {
    const fs::path file = dir() / "studies-file.json";
    std::ofstream(file) << R"({"fast": {"ao.method": "ssao", "ssao.samples": [4]},
                               "ground": {"ao.method": "gtao", "gtao.slices": 2}})";
    const std::string base = "tradeoff --scene default --size 48x27 --frames 1 --warmup 0 --resamples 100 --metric rms "
                             "--buffer ao --quiet --plot none";
    const Result r = run(base + " --study-file " + file.string() + " --csv " + (dir() / "file.csv").string() +
                         " --json " + (dir() / "file.json").string());
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "file.csv").string());
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.axisValue(t.rows[0], "study"), "fast");
    EXPECT_EQ(t.axisValue(t.rows[1], "study"), "ground");
    EXPECT_EQ(t.axisValue(t.rows[1], "gtao.slices"), "2");

    struct Bad {
        std::string args, says;
    };
    const Bad cases[] = {
        {"--study ao.method=ssao --sweep ssao.samples=4,8", "--study makes its own grids: give it without --sweep"},
        {"--study ao.method=ssao --knobs speed/quality", "--study makes its own grids"},
        {"--study ssao:", "an empty study or part"},
        {"--study ao.method=ssao:ssao.nonsense=1,2", "unknown knob 'ssao.nonsense'"},
        {"--study ao.method=nope", "--study: study 'nope'"},
        {"--study ssao.samples=4,8 --study ssao.samples=8,16",
         "the point ssao.samples=8 is given twice (in studies 'study 1' and 'study 2')"},
        {"--study ssao.samples=4,8,4", "is given twice (in study 'study 1')"},
        {"--study a:ssao.samples=4 --study a:ssao.samples=8", "two studies are named 'a'"},
        {"--study ao.method=ssao:ao.method=gtao", "ao.method is given twice"},
        {"--sweep study=a,b", "--sweep study: 'study' names each point's study"},
        // A study file: a key JSON gives twice is refused as --study refuses it (not the last kept); not JSON: exit 2.
        {"--study-file " + studyFile("dup-studies", R"({"a": {"ssao.samples": [4]}, "a": {"ssao.samples": [8]}})"),
         "two studies are named 'a'"},
        {"--study-file " + studyFile("dup-knob", R"({"a": {"ssao.samples": [4], "ssao.samples": [8]}})"),
         "study 'a': ssao.samples is given twice"},
        {"--study-file " + studyFile("dup-knob-list", R"([{"ssao.samples": 4}, {"ssao.samples": 8, "ssao.samples": 16}])"),
         "study 2: ssao.samples is given twice"},
        {"--study-file " + studyFile("not-json", R"({"a": {"ssao.samples": [4]})"), "not-json.json"},
    };
    for (const Bad& b : cases) {
        const Result bad = run(base + " " + b.args + " --csv " + (dir() / "study-bad.csv").string() + " --json " +
                               (dir() / "study-bad.json").string());
        EXPECT_EQ(bad.code, 2) << b.args << "\n" << bad.err;
        const std::string line = bad.err.substr(0, bad.err.find('\n'));
        EXPECT_NE(line.find(b.says), std::string::npos) << b.args << ": " << bad.err;
        std::istringstream lines(bad.err);
        int messages = 0;
        for (std::string l; std::getline(lines, l);) messages += !l.empty() && l.rfind("(deferred-workbench help", 0) != 0;
        EXPECT_EQ(messages, 1) << b.args << "\n" << bad.err;
        EXPECT_FALSE(fs::exists(dir() / "study-bad.csv")) << b.args;
    }
}

// Replay checks the numbers the front and the pick used beyond the error:
// --time's span with its interval (a recorded time far from the new one is
// "(moved)") and, with a counter --cost (exact inputs), each row's front.
TEST(TradeoffCli, ReplayChecksTheTimeAndTheFrontThePickUsed) {
    const Result r = run("tradeoff --scene default --size 48x27 --frames 6 --warmup 0 --resamples 100 --metric rms "
                         "--buffer ao --quiet --time ao --cost fragments --study ao.method=ssao:ssao.samples=4,8 "
                         "--study ao.method=gtao:gtao.slices=1,2" + files("study-front"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    std::ifstream in(dir() / "study-front.json");
    nlohmann::json rec = nlohmann::json::parse(in);
    EXPECT_EQ(rec["grid"]["time"], "ao");
    EXPECT_EQ(rec["grid"]["cost"], "fragments");
    nlohmann::json& row = rec["results"]["rows"][0];
    const std::string front = row["front"].get<std::string>(), edited = front == "pareto" ? "dominated" : "pareto";
    row["front"] = edited;
    row["time_ms"] = 1000.0;
    row["time_ms_ci95"] = {1000.0, 1001.0};
    std::ofstream((dir() / "study-front-edited.json").string()) << rec.dump(2);
    const Result again = run("replay " + (dir() / "study-front-edited.json").string());
    EXPECT_EQ(again.code, 1) << again.err << again.out;
    const std::string label = "point 0 camera 0, study=ssao, ao.method=ssao, ssao.samples=4, gtao.slices=";
    const size_t time = again.out.find(": time_ms (ao) median 1000.000 -> ");
    ASSERT_NE(time, std::string::npos) << again.out;
    EXPECT_EQ(again.out.rfind(label, time), again.out.rfind('\n', time) + 1) << again.out;
    EXPECT_NE(again.out.find("95% CI [1000, 1001] -> ", time), std::string::npos) << again.out;
    EXPECT_LT(again.out.find(" (moved)", time), again.out.find('\n', time)) << again.out;
    EXPECT_NE(again.out.find(": front " + edited + " -> " + front), std::string::npos) << again.out;
    EXPECT_NE(again.out.find("(moved; rule: exact, the front's cost is a counter)"), std::string::npos) << again.out;
    EXPECT_NE(again.out.find("1 with another front or pick;"), std::string::npos) << again.out;
}

// Replay's verdict agrees with its exit code and counts every number the
// front and the pick used: a moved pick is counted in "tradeoff: differs";
// counters measured on one side only are named ("missing in the record",
// "not measured here"), never "every counter equal"; a term of a --time sum
// moved is named; a median outside its own recorded interval is said to be
// an edited record. Each exits 1.
TEST(TradeoffCli, ReplayCountsThePickCountersAndTimeTermsItChecks) {
    const Result r = run("tradeoff --scene default --size 48x27 --frames 6 --warmup 1 --resamples 100 --metric rms "
                         "--buffer ao --quiet --sweep ssao.samples=4,32 --time lighting+ao+ao_filter --budget-ms 100000" +
                         files("replay-counts"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    std::ifstream in(dir() / "replay-counts.json");
    const nlohmann::json rec = nlohmann::json::parse(in);
    ASSERT_EQ(rec["results"]["rows"].size(), 2u);
    auto replayEdited = [&](const std::string& name, const std::function<void(nlohmann::json&)>& edit,
                            const std::string& env = "") {
        nlohmann::json edited = rec;
        edit(edited["results"]["rows"]);
        const fs::path file = dir() / (name + ".json");
        std::ofstream(file.string()) << edited.dump(2);
        return test::runCommand(env + "DW_REFERENCE_CACHE=" + (dir() / "cache").string() + " " + DW_WORKBENCH_BINARY +
                                " replay " + file.string());
    };

    // The pick moved: the summary counts it (it said "the same" with exit 1).
    const Result pick = replayEdited("replay-pick", [](nlohmann::json& rows) {
        const bool first = rows[0]["pick"] == "pick";
        rows[first ? 0 : 1]["pick"] = "fits";
        rows[first ? 1 : 0]["pick"] = "pick";
    });
    EXPECT_EQ(pick.code, 1) << pick.err << pick.out;
    EXPECT_NE(pick.out.find("pick: moved: "), std::string::npos) << pick.out;
    EXPECT_NE(pick.out.find("tradeoff: differs ("), std::string::npos) << pick.out;
    EXPECT_NE(pick.out.find("the pick moved)"), std::string::npos) << pick.out;
    EXPECT_EQ(pick.out.find("tradeoff: the same"), std::string::npos) << pick.out;

    // A row's counters emptied: missing in the record, never "equal".
    const Result empty = replayEdited("replay-no-counters", [](nlohmann::json& rows) { rows[1]["counters"] = nlohmann::json::object(); });
    EXPECT_EQ(empty.code, 1) << empty.err << empty.out;
    EXPECT_NE(empty.out.find("counters missing in the record: fragments"), std::string::npos) << empty.out;
    EXPECT_NE(empty.out.find("1 with a counter measured on one side only"), std::string::npos) << empty.out;
    EXPECT_EQ(empty.out.find("every counter equal"), std::string::npos) << empty.out;

    // A driver without the pipeline statistics query: those counters are not measured here.
    const Result driver = replayEdited("replay-unedited", [](nlohmann::json&) {},
                                       "MESA_EXTENSION_OVERRIDE=-GL_ARB_pipeline_statistics_query ");
    EXPECT_EQ(driver.code, 1) << driver.err << driver.out;
    EXPECT_NE(driver.out.find("counters not measured here: "), std::string::npos) << driver.out;
    EXPECT_NE(driver.out.find("fragments"), std::string::npos) << driver.out;
    EXPECT_EQ(driver.out.find("every counter equal"), std::string::npos) << driver.out;

    // A term of the --time sum x50: named, counted.
    const Result term = replayEdited("replay-term", [](nlohmann::json& rows) {
        rows[0]["gpu_ms"]["ao"] = rows[0]["gpu_ms"]["ao"].get<double>() * 50.0 + 50.0;
    });
    EXPECT_EQ(term.code, 1) << term.err << term.out;
    EXPECT_NE(term.out.find(": time term moved: gpu_ms.ao median "), std::string::npos) << term.out;
    EXPECT_NE(term.out.find("1 with a term of it moved"), std::string::npos) << term.out;

    // The time's median x5 with its interval left: an edited record, said so.
    const Result median = replayEdited("replay-median", [](nlohmann::json& rows) {
        rows[0]["time_ms"] = rows[0]["time_ms"].get<double>() * 5.0;
    });
    EXPECT_EQ(median.code, 1) << median.err << median.out;
    EXPECT_NE(median.out.find(": record inconsistent: time_ms median "), std::string::npos) << median.out;
    EXPECT_NE(median.out.find("1 inconsistent in the record"), std::string::npos) << median.out;
}

// Issue 35: --ref-spp N traces the sweep's reference at N samples per pixel
// (--ref-filter box|tent), with N and the filter in the cache key (two N never
// share an entry); the record keeps both and replay traces the same
// reference (a record without them reads as 1 sample, box); bad values are
// one line, exit 2, as reference --spp's.
TEST(TradeoffCli, RefSppTracesTheReferenceAtNSamplesAndKeysTheCache) {
    const fs::path d = dir() / "ref-spp";
    fs::remove_all(d);
    fs::create_directories(d);
    const auto runHere = [&](const std::string& args) {
        return test::runCommand("DW_REFERENCE_CACHE=" + (d / "cache").string() + " " + DW_WORKBENCH_BINARY + " " + args);
    };
    const std::string grid = "tradeoff --scene default --size 40x24 --sweep gbuffer.texture_filter=mipmap,base_level "
                             "--metric rms --ao-rays 2 --frames 1 --warmup 0 --resamples 100 --quiet --plot none";
    const auto sweep = [&](const std::string& name, const std::string& flags) {
        const Result r = runHere(grid + flags + " --csv " + (d / (name + ".csv")).string() + " --json " +
                                 (d / (name + ".json")).string());
        EXPECT_EQ(r.code, 0) << name << ": " << r.err << r.out;
        std::ifstream f(d / (name + ".json"));
        return nlohmann::json::parse(f);
    };
    const auto errors = [](const nlohmann::json& rec) {
        std::vector<double> e;
        for (const auto& row : rec["results"]["rows"]) e.push_back(row["error"].get<double>());
        return e;
    };
    const auto settings = [](const nlohmann::json& rec, const char* key) {
        return rec["results"]["settings"][key].get<std::string>();
    };
    const nlohmann::json four = sweep("four", " --ref-spp 4");
    EXPECT_EQ(four["grid"]["ref_spp"], 4);
    EXPECT_EQ(four["grid"]["ref_filter"], "box");
    EXPECT_EQ(settings(four, "references_rendered"), "1");
    const nlohmann::json one = sweep("one", "");
    EXPECT_EQ(one["grid"]["ref_spp"], 1);
    EXPECT_EQ(settings(one, "references_rendered"), "1") << "1 sample must not read 4 samples' entry";
    EXPECT_NE(errors(one), errors(four)) << "the pixel's area is not its centre on a textured floor";
    const nlohmann::json again = sweep("again", " --ref-spp 4");
    EXPECT_EQ(settings(again, "references_from_cache"), "1");
    EXPECT_EQ(settings(again, "references_rendered"), "0");
    EXPECT_EQ(errors(again), errors(four));
    const nlohmann::json tent = sweep("tent", " --ref-spp 4 --ref-filter tent");
    EXPECT_EQ(tent["grid"]["ref_filter"], "tent");
    EXPECT_EQ(settings(tent, "references_rendered"), "1") << "tent must not read box's entry";

    // replay traces at the record's N: the same errors.
    Result r = runHere("replay " + (d / "four.json").string());
    ASSERT_TRUE(r.code == 0 || r.code == 1) << r.err << r.out;
    EXPECT_EQ(r.out.find("(differs)"), std::string::npos) << r.out;
    // A record from before --ref-spp: 1 sample, so 4 samples' errors now differ.
    nlohmann::json old = four;
    old["grid"].erase("ref_spp");
    old["grid"].erase("ref_filter");
    std::ofstream((d / "old.json").string()) << old.dump(2);
    r = runHere("replay " + (d / "old.json").string());
    EXPECT_EQ(r.code, 1) << r.err << r.out;
    EXPECT_NE(r.out.find("(differs)"), std::string::npos) << r.out;

    // Bad values: reference --spp's line, named for --ref-spp; exit 2, nothing written.
    for (const std::string bad : {"0", "1e9", "70000"}) {
        const Result ref = runHere("reference --scene default --size 40x24 --spp " + bad + " --out " + (d / "x.exr").string());
        r = runHere(grid + " --ref-spp " + bad + " --csv " + (d / "x.csv").string());
        EXPECT_EQ(r.code, 2) << bad;
        // The refusal's first line (the second says where the command's options are listed).
        const std::string line = r.err.substr(0, r.err.find('\n'));
        std::string expected = ref.err.substr(0, ref.err.find('\n'));
        expected.replace(expected.find("--spp"), 5, "--ref-spp");
        EXPECT_EQ(line, expected) << bad;
    }
    r = runHere(grid + " --ref-spp 4 --ref-filter gauss --csv " + (d / "x.csv").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--ref-filter: expected box or tent, got 'gauss'"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(d / "x.csv"));
}

// Issue 35 part 4: --metric temporal along an orbit of small steps (16
// degrees over 9 cameras, 1.8 degrees a step), each point rendering the
// cameras in order, against the footprint truth of the same cameras
// (--ref-spp 16; 4 AO rays): the pixel centres flicker more than TAA
// (measured: 0.0356 [0.0303, 0.0427] against 0.0300 [0.0274, 0.0327]); the
// error is on the all-cameras row with its interval, a camera's row has
// none. Without a camera path it is refused in one line, exit 2.
TEST(TradeoffCli, TemporalErrorAlongASmallOrbitIsLargerWithoutAntialiasingThanWithTaa) {
    const std::string args = "tradeoff --scene default --size 64x36 --sweep aa.method=none,taa --metric temporal "
                             "--ref-spp 16 --ao-rays 4 --frames 1 --warmup 0 --resamples 200 --quiet";
    const Result r = run(args + " --orbit 9 --orbit-degrees 16" + files("temporal"));
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    const TradeoffTable t = TradeoffTable::readCsv((dir() / "temporal.csv").string());
    ASSERT_EQ(t.rows.size(), 20u);  // 2 points x (9 cameras + all)
    std::map<std::string, const TradeoffRow*> all;
    for (const auto& row : t.rows) {
        EXPECT_EQ(row.metric, "temporal");
        if (row.camera == "all") all[t.axisValue(row, "aa.method")] = &row;
        else EXPECT_TRUE(std::isnan(row.error)) << "camera " << row.camera;
    }
    ASSERT_EQ(all.size(), 2u);
    for (const auto& [method, row] : all) {
        EXPECT_GT(row->error, 0.0) << method;
        EXPECT_LE(row->errorLo, row->error) << method;
        EXPECT_GE(row->errorHi, row->error) << method;
    }
    std::printf("default 64x36, --orbit 9 --orbit-degrees 16, against reference --spp 16: temporal error none %.5f [%.5f, %.5f], "
                "taa %.5f [%.5f, %.5f]\n", all["none"]->error, all["none"]->errorLo, all["none"]->errorHi,
                all["taa"]->error, all["taa"]->errorLo, all["taa"]->errorHi);
    EXPECT_GT(all["none"]->error, all["taa"]->error);
    const Result still = run(args + files("temporal-bad"));
    EXPECT_EQ(still.code, 2);
    EXPECT_NE(still.err.substr(0, still.err.find('\n'))
                  .find("--metric temporal measures the change from frame to frame along a camera path"),
              std::string::npos) << still.err;
    EXPECT_FALSE(fs::exists(dir() / "temporal-bad.csv"));
    const Result arc = run(args + " --orbit-degrees 2" + files("temporal-bad"));
    EXPECT_EQ(arc.code, 2);
    EXPECT_NE(arc.err.find("--orbit-degrees is the arc of --orbit N's cameras"), std::string::npos) << arc.err;
}
