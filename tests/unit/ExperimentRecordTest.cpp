// Experiment records without GL: the median's bootstrap interval, a bench
// record through JSON and back (grid, seeds, camera path), version 1
// migration from text, refusals, and the files a scene reads.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "renderer/Error.h"
#include "renderer/bench/BenchSummary.h"
#include "renderer/bench/Bootstrap.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/record/SceneFiles.h"
#include "renderer/scene/SceneLoader.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

void writeFile(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

}  // namespace

TEST(Bootstrap, MedianIntervalHoldsTheMedianWithinTheSamples) {
    const std::vector<double> v = {1, 2, 3, 4, 100};
    const MedianInterval m = bootstrapMedian(v);
    ASSERT_TRUE(m.valid());
    EXPECT_EQ(m.median, 3.0);
    EXPECT_LE(m.low, 3.0);
    EXPECT_GE(m.high, 3.0);
    EXPECT_GE(m.low, 1.0);
    EXPECT_LE(m.high, 100.0);
    // Of 21 samples one outlier: a resample's median is it only when 11 of 21 draws are (p ~ 1e-11).
    std::vector<double> w;
    for (int i = 1; i <= 20; ++i) w.push_back(i);
    w.push_back(1000.0);
    const MedianInterval mw = bootstrapMedian(w);
    EXPECT_EQ(mw.median, 11.0);
    EXPECT_LT(mw.high, 1000.0);
    EXPECT_GT(mw.low, 1.0);
    // Seeded: the same samples give the same interval.
    const MedianInterval again = bootstrapMedian(v);
    EXPECT_EQ(again.low, m.low);
    EXPECT_EQ(again.high, m.high);
    // No spread, no width; nothing, no interval.
    const MedianInterval flat = bootstrapMedian({2.5, 2.5, 2.5});
    EXPECT_EQ(flat.low, 2.5);
    EXPECT_EQ(flat.high, 2.5);
    EXPECT_FALSE(bootstrapMedian({}).valid());
}

TEST(ExperimentRecord, ABenchRecordKeepsItsGridSeedsAndCameraPathThroughJson) {
    ExperimentRecord r;
    r.command = "bench";
    r.sceneSpec = "street";
    r.sceneSource = "builtin:street";
    r.camera.position = {1, 2, 3};
    r.cameraPath.mode = "walkthrough";
    r.cameraPath.keyframes = {{0.0f, {0, 4, 12}, {0, 0, 0}}, {2.0f, {12, 4, 0}, {0, 0, 0}}};
    r.knobs = {{"ssao.samples", "16"}, {"lighting.strategy", "tiled"}};
    r.seeds = {{"lights", "7"}, {"bootstrap", "12345"}};
    r.width = 64;
    r.height = 36;
    r.frames = 5;
    r.warmup = 2;
    RecordedBench b;
    b.options.grid.sizes = {{64, 36}, {128, 72}};
    b.options.grid.lights = {1, 100};
    b.options.grid.knobAxes = {BenchGrid::parseSweep("lighting.strategy=tiled,clustered")};
    b.options.block = 3;
    b.options.walkthrough = true;
    b.options.lppPoses = 2;
    b.options.shard = BenchShard::parse("1/3");
    b.ratioOf = "lighting";
    b.resamples = 500;
    r.bench = b;
    r.benchResults = {{"configs", nlohmann::ordered_json::array()}};

    const ExperimentRecord back = ExperimentRecord::parse(r.json(), "bench.json");
    EXPECT_EQ(back.readVersion, 2);
    EXPECT_EQ(back.command, "bench");
    ASSERT_TRUE(back.bench.has_value());
    const BenchOptions& o = back.bench->options;
    EXPECT_EQ(o.grid.sizes, b.options.grid.sizes);
    EXPECT_EQ(o.grid.lights, b.options.grid.lights);
    ASSERT_EQ(o.grid.knobAxes.size(), 1u);
    EXPECT_EQ(o.grid.knobAxes[0].values, (std::vector<std::string>{"tiled", "clustered"}));
    EXPECT_EQ(o.block, 3);
    EXPECT_TRUE(o.walkthrough);
    EXPECT_EQ(o.lppPoses, 2);
    EXPECT_EQ(o.shard.index, 1);
    EXPECT_EQ(o.shard.count, 3);
    EXPECT_EQ(o.seed, 7u);
    EXPECT_EQ(o.frames, 5);
    EXPECT_EQ(o.warmup, 2);
    EXPECT_EQ(o.run.scene, "street");
    std::vector<std::string> sets = o.run.sets;  // every knob, in the JSON's key order
    std::sort(sets.begin(), sets.end());
    EXPECT_EQ(sets, (std::vector<std::string>{"lighting.strategy=tiled", "ssao.samples=16"}));
    EXPECT_EQ(back.bench->ratioOf, "lighting");
    EXPECT_EQ(back.bench->resamples, 500);
    EXPECT_EQ(back.cameraPath.mode, "walkthrough");
    ASSERT_EQ(back.cameraPath.keyframes.size(), 2u);
    EXPECT_EQ(back.cameraPath.keyframes[1].position, glm::vec3(12, 4, 0));
    EXPECT_EQ(back.cameraPath.keyframes[1].time, 2.0f);
    EXPECT_EQ(back.camera.position, glm::vec3(1, 2, 3));
    EXPECT_TRUE(back.benchResults.contains("configs"));
}

TEST(ExperimentRecord, VersionOneReadsWithTheFieldsItLacked) {
    const std::string v1 = R"({"format": "deferred-workbench record", "version": 1, "command": "render",
        "scene": {"spec": "default", "source": "builtin:default", "files": []},
        "camera": {"position": [0, 2, 8], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_degrees": 60, "near": 0.1, "far": 100},
        "knobs": {"ssao.samples": "8"}, "size": [32, 18], "frames": 2, "warmup": 0, "buffer": "final",
        "build": {"version": "0.1.0", "commit": "abc", "compiler": "gcc 12.2.0", "build_type": "Release"},
        "gl": {}, "host": {},
        "results": {"timings": [{"name": "frame", "gpu_ms": [1.0, 3.0], "cpu_ms": [0.5, 0.5]}],
                    "image": {"buffer": "final", "sha256": "00", "width": 32, "height": 18, "channels": 4}}})";
    const ExperimentRecord r = ExperimentRecord::parse(v1, "v1.json");
    EXPECT_EQ(r.readVersion, 1);
    EXPECT_EQ(r.cameraPath.mode, "fixed");
    EXPECT_TRUE(r.seeds.empty());
    EXPECT_TRUE(r.metrics.empty());
    ASSERT_EQ(r.timings.size(), 1u);
    EXPECT_EQ(r.timings[0].gpuMs, (std::vector<double>{1.0, 3.0}));
    // Written again it is version 2, with the median and interval the frames give.
    const nlohmann::json j = nlohmann::json::parse(r.json());
    EXPECT_EQ(j["version"], 2);
    EXPECT_EQ(j["results"]["timings"][0]["gpu"]["median"], 2.0);
    EXPECT_EQ(j["camera_path"]["mode"], "fixed");
}

TEST(ExperimentRecord, RefusesNewerVersionsOtherFormatsAndBadFieldsByName) {
    auto refusal = [](const std::string& text) {
        try {
            ExperimentRecord::parse(text, "r.json");
        } catch (const FileError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(refusal(R"({"format": "deferred-workbench record", "version": 3})").find(
                  "record version 3 is newer than this build reads (2)"),
              std::string::npos);
    EXPECT_NE(refusal(R"({"tool": "deferred-workbench bench"})").find("not a deferred-workbench record"), std::string::npos);
    EXPECT_NE(refusal(R"({"format": "deferred-workbench record", "version": "2"})").find("no integer \"version\""),
              std::string::npos);
    const std::string missing = refusal(R"({"format": "deferred-workbench record", "version": 2, "command": "render",
        "scene": {"spec": "default"}})");
    EXPECT_NE(missing.find("r.json"), std::string::npos) << missing;
    EXPECT_NE(missing.find("record version 2"), std::string::npos) << missing;
}

TEST(SceneFiles, AGltfNamedByASceneJsonBringsItsBuffersAndImages) {
    const fs::path dir = test::tempDir() / "scene-files";
    fs::create_directories(dir / "model");
    writeFile(dir / "model" / "a.bin", std::string(36, '\0'));
    writeFile(dir / "model" / "t.png", "not read here");
    writeFile(dir / "model" / "a.gltf", R"({"asset": {"version": "2.0"},
        "buffers": [{"uri": "a.bin", "byteLength": 36}, {"uri": "data:application/octet-stream;base64,AAAA", "byteLength": 3}],
        "images": [{"uri": "t.png"}, {"uri": "missing.png"}]})");
    writeFile(dir / "scene.json", R"({"objects": [{"gltf": "model/a.gltf"}, {"gltf": "model/../model/a.gltf"}],
        "sky": {"type": "environment", "file": "sky.hdr"}})");
    Scene scene;
    scene.source = (dir / "scene.json").string();
    const std::vector<RecordedFile> files = sceneFilesOf(scene);
    std::vector<std::string> names;
    for (const auto& f : files) names.push_back(fs::path(f.path).lexically_relative(dir).string());
    // Each once; data: URIs and files that are not there are not listed.
    EXPECT_EQ(names, (std::vector<std::string>{"scene.json", "model/a.gltf", "model/a.bin", "model/t.png"}));
    EXPECT_EQ(files[2].sha256, sha256Hex(std::string(36, '\0').data(), 36));
    EXPECT_EQ(sha256Hex("abc", 3), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(ExperimentRecord, BenchMergeReadsTheSummaryOfARecordAndOfAnOlderJson) {
    const nlohmann::json record = {{"format", "deferred-workbench record"}, {"results", {{"configs", {1, 2}}}}};
    EXPECT_EQ(benchSummaryOf(record)["configs"].size(), 2u);
    const nlohmann::json older = {{"tool", "deferred-workbench bench"}, {"configs", {1}}};
    EXPECT_EQ(&benchSummaryOf(older), &older);
}
