// Experiment records without GL: the median's bootstrap interval, a bench
// record through JSON and back (grid, seeds, camera path), version 1
// migration from text, refusals, and the files a scene reads.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>

#include "renderer/Error.h"
#include "renderer/bench/BenchSummary.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/metrics/Bootstrap.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/record/SceneContent.h"
#include "renderer/record/SceneFiles.h"
#include "renderer/record/ShaderFiles.h"
#include "renderer/scene/BuiltinScenes.h"
#include "renderer/scene/FlameParticles.h"
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
    r.sceneTime = 0.5;  // --scene-time (issue 36)
    r.animation = "run";  // --animation
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
    EXPECT_EQ(back.sceneTime, 0.5);
    EXPECT_EQ(o.run.sceneTime, 0.5);  // what replay runs the grid at
    EXPECT_EQ(back.animation, "run");
    EXPECT_EQ(o.run.animation, "run");  // the clip replay plays
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
    // Two frames give a median but no interval: said, not printed as numbers.
    EXPECT_TRUE(j["results"]["timings"][0]["gpu"]["ci95"].is_null());
    EXPECT_EQ(j["results"]["timings"][0]["gpu"]["interval"], "too few frames for an interval (2 counted, 6 needed)");
}

namespace {

// A render record as text, with `change` applied to its JSON.
std::string renderRecord(const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json j = nlohmann::json::parse(R"({"format": "deferred-workbench record", "version": 2, "command": "render",
        "scene": {"spec": "default", "source": "builtin:default", "files": []},
        "camera": {"position": [0, 2, 8], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_degrees": 60, "near": 0.1, "far": 100},
        "knobs": {"ssao.samples": "8"}, "size": [32, 18], "frames": 6, "warmup": 1, "buffer": "final",
        "results": {"timings": [], "image": {"buffer": "final", "sha256": "00"}}})");
    change(j);
    return j.dump();
}

std::string refusal(const std::string& text) {
    try {
        ExperimentRecord::parse(text, "r.json");
    } catch (const FileError& e) {
        return e.what();
    }
    return "accepted";
}

}  // namespace

TEST(ExperimentRecord, FieldsAreHeldToTheRangesOfTheOptionsTheyStandFor) {
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json&) {})), "accepted");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["frames"] = 100000; })), "accepted");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["frames"] = 100001; })),
              "r.json: frames: 100001 is outside --frames's range 1..100000");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["frames"] = 4294967297LL; })),
              "r.json: frames: 4294967297 is outside --frames's range 1..100000");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["frames"] = 2.5; })),
              "r.json: frames: expects a whole number (as --frames does), got 2.5");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["warmup"] = -1; })),
              "r.json: warmup: -1 is outside --warmup's range 0..100000");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["scene_time"] = 2.5; })), "accepted");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["animation"] = "walk"; })), "accepted");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["animation"] = 2; })),
              "r.json: animation: expected a clip's name or index, or \"none\" (--animation), got 2");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["scene_time"] = -1; })),
              "r.json: scene_time: -1 is outside --scene-time's range 0..1000000 (seconds)");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["size"] = {16385, 18}; })),
              "r.json: size width: 16385 is outside --size's range 1..16384");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["size"] = {32, 0}; })),
              "r.json: size height: 0 is outside --size's range 1..16384");
    // A bench record's grid: its sizes, light counts, block, orbit.
    auto bench = [](nlohmann::json& j) {
        j["command"] = "bench";
        j["grid"] = {{"sizes", {"32x18"}}, {"lights", {0, 10}}, {"sweep", nlohmann::json::array()}, {"block", 1}, {"orbit", 0}};
        j["results"] = nlohmann::json::object();
    };
    EXPECT_EQ(refusal(renderRecord(bench)), "accepted");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { bench(j); j["grid"]["sizes"] = {"32x99999"}; })),
              "r.json: grid.sizes[0] height: 99999 is outside --size's range 1..16384");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { bench(j); j["grid"]["lights"] = {-3}; })),
              "r.json: grid.lights[0]: -3 is outside --lights's range 0..1000000");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { bench(j); j["grid"]["block"] = 0; })),
              "r.json: grid.block: 0 is outside --block's range 1..100000");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { bench(j); j["grid"]["orbit"] = 200000; })),
              "r.json: grid.orbit: 200000 is outside --orbit's range 1..100000");
}

TEST(ExperimentRecord, ACameraCameraCheckRefusesIsRefusedWithItsField) {
    const std::string up = refusal(renderRecord([](nlohmann::json& j) { j["camera"]["up"] = {0, 0, 0}; }));
    EXPECT_EQ(up.rfind("r.json: camera.up: ", 0), 0u) << up;
    const std::string fov = refusal(renderRecord([](nlohmann::json& j) { j["camera"]["fov_y_degrees"] = 0; }));
    EXPECT_EQ(fov.rfind("r.json: camera.fov_y_degrees: ", 0), 0u) << fov;
    const std::string at = refusal(renderRecord([](nlohmann::json& j) { j["camera"]["target"] = {0, 2, 8}; }));
    EXPECT_EQ(at.rfind("r.json: camera.", 0), 0u) << at;
    const std::string far = refusal(renderRecord([](nlohmann::json& j) { j["camera"]["far"] = 0.05; }));
    EXPECT_EQ(far.rfind("r.json: camera.far: ", 0), 0u) << far;
}

// Paths in a record are relative to its folder: written so, read so (then
// the working directory, for records written before).
TEST(ExperimentRecord, ScenePathsAreRelativeToTheRecordsFolder) {
    const fs::path dir = test::tempDir() / "record-paths";
    fs::remove_all(dir);
    fs::create_directories(dir / "scenes");
    fs::create_directories(dir / "out");
    writeFile(dir / "scenes" / "s.json", R"({"objects": [{"shape": "box"}]})");
    ExperimentRecord r;
    r.sceneSpec = (dir / "scenes" / "s.json").lexically_relative(fs::current_path()).string();
    ASSERT_FALSE(fs::path(r.sceneSpec).is_absolute());
    r.sceneSource = r.sceneSpec;
    r.sceneFiles = {{r.sceneSpec, "ab"}};
    r.width = 32;
    r.height = 18;
    const nlohmann::json j = nlohmann::json::parse(r.json((dir / "out" / "r.json").string()));
    EXPECT_EQ(j["scene"]["spec"], "../scenes/s.json");
    EXPECT_EQ(j["scene"]["source"], "../scenes/s.json");
    EXPECT_EQ(j["scene"]["files"][0]["path"], "../scenes/s.json");
    // Built-in scenes and absolute paths stay as they are; without a destination nothing moves.
    ExperimentRecord b = r;
    b.sceneSpec = "street";
    b.sceneSource = "builtin:street";
    b.sceneFiles = {{(dir / "scenes" / "s.json").string(), "ab"}};
    const nlohmann::json jb = nlohmann::json::parse(b.json((dir / "out" / "r.json").string()));
    EXPECT_EQ(jb["scene"]["spec"], "street");
    EXPECT_EQ(jb["scene"]["source"], "builtin:street");
    EXPECT_EQ(jb["scene"]["files"][0]["path"], (dir / "scenes" / "s.json").string());
    EXPECT_EQ(nlohmann::json::parse(r.json())["scene"]["spec"], r.sceneSpec);

    // Read back from wherever the record is: against its folder.
    r.write((dir / "out" / "r.json").string());
    const ExperimentRecord back = ExperimentRecord::read((dir / "out" / "r.json").string());
    EXPECT_TRUE(fs::equivalent(back.sceneSpec, dir / "scenes" / "s.json")) << back.sceneSpec;
    EXPECT_TRUE(fs::equivalent(back.sceneFiles[0].path, dir / "scenes" / "s.json")) << back.sceneFiles[0].path;
    // A record whose relative path only makes sense from the working directory still finds it there.
    fs::create_directories(dir / "out" / "a" / "b");
    std::ofstream(dir / "out" / "a" / "b" / "legacy.json") << r.json();
    const ExperimentRecord old = ExperimentRecord::read((dir / "out" / "a" / "b" / "legacy.json").string());
    EXPECT_EQ(old.sceneSpec, r.sceneSpec);
    EXPECT_TRUE(fs::equivalent(old.sceneSpec, dir / "scenes" / "s.json"));
}

TEST(SceneFiles, TheRecordsListIsComparedWithTheLoadersByNameWithoutReadingIt) {
    const std::vector<RecordedFile> recorded = {
        {"/old/place/scene.json", "s1"}, {"/old/place/model/a.bin", "b1"}, {"/etc/not-a-scene-file", "x1"}};
    const std::vector<RecordedFile> now = {
        {"/new/place/scene.json", "s1"}, {"/new/place/model/a.bin", "b2"}, {"/new/place/model/t.png", "t2"}};
    const std::vector<SceneFileChange> c =
        compareSceneFiles(recorded, "/old/place/scene.json", now, "/new/place/scene.json");
    ASSERT_EQ(c.size(), 3u);
    EXPECT_EQ(c[0].kind, SceneFileChange::Kind::Changed);
    EXPECT_EQ(c[0].path, "/new/place/model/a.bin");
    EXPECT_EQ(c[0].oldSha256, "b1");
    EXPECT_EQ(c[0].newSha256, "b2");
    EXPECT_EQ(c[1].kind, SceneFileChange::Kind::Removed);
    EXPECT_EQ(c[1].path, "/etc/not-a-scene-file");
    EXPECT_EQ(c[1].newSha256, "");
    EXPECT_EQ(c[2].kind, SceneFileChange::Kind::Added);
    EXPECT_EQ(c[2].path, "/new/place/model/t.png");
    EXPECT_TRUE(compareSceneFiles(now, "/new/place/scene.json", now, "/new/place/scene.json").empty());
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
    EXPECT_EQ(refusal(R"({"format": "deferred-workbench record", "version": "2"})"),
              "r.json: version: expects a whole number (1..2), got \"2\"");
    const std::string missing = refusal(R"({"format": "deferred-workbench record", "version": 2, "command": "render",
        "scene": {"spec": "default"}})");
    EXPECT_EQ(missing, "r.json: camera: missing");
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

// Issue 33, "a scene read once": the record lists a loaded glTF's buffers
// from the loader's parse of its JSON (Scene::gltfExternalUris), not a parse
// of its own; the list is the one a parse of the file gives.
TEST(SceneFiles, ALoadedGltfsJsonIsParsedOnceForTheLoadAndTheRecord) {
    const fs::path dir = test::tempDir() / "scene-files-once";
    fs::create_directories(dir / "model");
    const float triangle[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    writeFile(dir / "model" / "a.bin", std::string(reinterpret_cast<const char*>(triangle), sizeof triangle));
    writeFile(dir / "model" / "a.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "buffers": [{"uri": "a.bin", "byteLength": 36}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}]})");
    const std::string path = (dir / "model" / "a.gltf").string();
    const long long before = jsonParseCount();
    const Scene scene = loadScene(path);
    EXPECT_EQ(jsonParseCount() - before, 1);  // the loader's checks (tinygltf reads its own copy of the text)
    const std::vector<RecordedFile> files = sceneFilesOf(scene);
    EXPECT_EQ(jsonParseCount() - before, 1);  // the record parsed nothing
    std::vector<std::string> names;
    for (const auto& f : files) names.push_back(fs::path(f.path).lexically_relative(dir).string());
    EXPECT_EQ(names, (std::vector<std::string>{"model/a.gltf", "model/a.bin"}));
    EXPECT_EQ(files[1].sha256, sha256Hex(triangle, sizeof triangle));
    // The same list as the record's own parse gives, for a scene the loader did not read.
    Scene unread;
    unread.source = path;
    const std::vector<RecordedFile> parsed = sceneFilesOf(unread);
    ASSERT_EQ(parsed.size(), files.size());
    for (size_t i = 0; i < files.size(); ++i) {
        EXPECT_EQ(parsed[i].path, files[i].path);
        EXPECT_EQ(parsed[i].sha256, files[i].sha256);
    }
    EXPECT_EQ(jsonParseCount() - before, 2);
}

TEST(ExperimentRecord, BenchMergeReadsTheSummaryOfARecordAndOfAnOlderJson) {
    const nlohmann::json record = {{"format", "deferred-workbench record"}, {"results", {{"configs", {1, 2}}}}};
    EXPECT_EQ(benchSummaryOf(record)["configs"].size(), 2u);
    const nlohmann::json older = {{"tool", "deferred-workbench bench"}, {"configs", {1}}};
    EXPECT_EQ(&benchSummaryOf(older), &older);
}

// Issue 24's leftovers: every refusal names the field path it is about, the
// wrong type of every top-level field included.
TEST(ExperimentRecord, EveryRefusalNamesTheFieldPath) {
    auto startsWith = [](const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; };
    // A tradeoff record whose axis values are numbers, not strings.
    auto tradeoff = [](nlohmann::json& j) {
        j["command"] = "tradeoff";
        j["grid"] = {{"axes", {{{"name", "ssao.samples"}, {"values", {"4", "8", "16"}}}}}, {"metric", "flip"}, {"buffer", "final"}};
        j["results"] = {{"axes", {"ssao.samples"}}, {"passes", nlohmann::json::array()}, {"rows", nlohmann::json::array()}};
    };
    EXPECT_EQ(refusal(renderRecord(tradeoff)), "accepted");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { tradeoff(j); j["grid"]["axes"][0]["values"] = {4, 8, 16}; })),
              "r.json: grid.axes[0].values[0]: expects a string, got 4");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { tradeoff(j); j["grid"]["axes"][0]["values"][2] = 16; })),
              "r.json: grid.axes[0].values[2]: expects a string, got 16");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { tradeoff(j); j["results"]["axes"] = {3}; })),
              "r.json: results.axes[0]: expects a string, got 3");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) {
                  tradeoff(j);
                  j["results"]["rows"] = {{{"point", 0}, {"values", {{"ssao.samples", "4"}}}, {"camera", "0"},
                                           {"metric", "flip"}, {"buffer", "final"}, {"error", "small"}}};
              })),
              "r.json: results.rows[0].error: expects a number or null, got \"small\"");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { tradeoff(j); j["grid"]["shard"] = "5/2"; })),
              "r.json: grid.shard: --shard expects i/n with 0 <= i < n (e.g. 0/4), n from 1 to 100000, got '5/2'");
    // tradeoff --study's listed points: a value position per axis, each on its axis; the budget above 0 (readTradeoffGrid).
    auto listed = [&](const nlohmann::json& points) {
        return [&, points](nlohmann::json& j) {
            tradeoff(j);
            j["grid"]["points"] = points;
        };
    };
    EXPECT_EQ(refusal(renderRecord(listed({{0}, {2}}))), "accepted");
    EXPECT_TRUE(startsWith(refusal(renderRecord(listed({{0}, {3}}))), "r.json: grid.points[1][0]: "))
        << refusal(renderRecord(listed({{0}, {3}})));
    EXPECT_EQ(refusal(renderRecord(listed({{0, 1}}))), "r.json: grid.points[0]: more positions than the grid's axes");
    EXPECT_EQ(refusal(renderRecord(listed(nlohmann::json::array({nlohmann::json::array()})))), "r.json: grid.points[0]: expected a position per axis");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { tradeoff(j); j["grid"]["budget_ms"] = 0; })),
              "r.json: grid.budget_ms: expects --budget-ms's value (above 0), got 0");
    // A bench record's sweep values, seed and sizes.
    auto bench = [](nlohmann::json& j) {
        j["command"] = "bench";
        j["grid"] = {{"sizes", {"32x18"}}, {"lights", {0}}, {"sweep", {{{"knob", "ssao.samples"}, {"values", {"4", "8"}}}}}};
        j["results"] = nlohmann::json::object();
    };
    EXPECT_EQ(refusal(renderRecord(bench)), "accepted");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { bench(j); j["grid"]["sweep"][0]["values"][1] = 8; })),
              "r.json: grid.sweep[0].values[1]: expects a string, got 8");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { bench(j); j["seeds"] = {{"lights", "seven"}}; })),
              "r.json: seeds.lights: expects a whole number 0..4294967295 (as --seed takes), got 'seven'");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { bench(j); j["grid"]["sizes"] = {32}; })),
              "r.json: grid.sizes[0]: expects a string, got 32");
    EXPECT_EQ(refusal(renderRecord([&](nlohmann::json& j) { bench(j); j["grid"]["lpp"] = "yes"; })),
              "r.json: grid.lpp: expects true or false, got \"yes\"");
    // The version: 2**70 is beyond 64-bit integers (it parses as floating point); 2**40 overflowed an int.
    auto withVersion = [](const std::string& v) {
        std::string text = renderRecord([](nlohmann::json&) {});
        const std::string two = "\"version\":2";
        return text.replace(text.find(two), two.size(), "\"version\":" + v);
    };
    const std::string huge = refusal(withVersion("1180591620717411303424"));
    EXPECT_TRUE(startsWith(huge, "r.json: version: record version 1.1805916207174113e+21 is newer than this build reads (2)")) << huge;
    EXPECT_EQ(refusal(withVersion("1099511627776")),
              "r.json: version: record version 1099511627776 is newer than this build reads (2); replay it with a newer "
              "deferred-workbench");
    EXPECT_EQ(refusal(withVersion("-4294967295")), "r.json: version: record version -4294967295 does not exist");
    EXPECT_EQ(refusal(withVersion("1.5")), "r.json: version: expects a whole number (1..2), got 1.5");
    // Render fields below the top level.
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["results"]["timings"] = {{{"name", "frame"}, {"gpu_ms", {1.0, "fast"}}, {"cpu_ms", {1.0, 1.0}}}}; })),
              "r.json: results.timings[0].gpu_ms[1]: expects a number (milliseconds), got \"fast\"");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["scene"]["files"] = {{{"path", "a.json"}, {"sha256", 3}}}; })),
              "r.json: scene.files[0].sha256: expects a string, got 3");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["camera"]["near"] = "close"; })),
              "r.json: camera.near: expects a number, got \"close\"");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["camera"]["position"][1] = 1e300; })),
              "r.json: camera.position[1]: 1e+300 does not fit a 32-bit float");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["camera_path"] = {{"mode", "spiral"}}; })),
              "r.json: camera_path.mode: expects fixed, orbit or walkthrough, got 'spiral'");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["knobs"]["ssao.samples"] = {8}; })),
              "r.json: knobs.ssao.samples: expects a string, got [8]");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["shaders"] = {{"folder", "/s"}, {"files", {{{"path", 1}}}}}; })),
              "r.json: shaders.files[0].path: expects a string, got 1");
    EXPECT_EQ(refusal(renderRecord([](nlohmann::json& j) { j["results"]["image"].erase("sha256"); })),
              "r.json: results.image.sha256: missing");
    // The wrong type at every top-level field: each refusal starts with the field's name.
    for (const char* field : {"format", "command", "scene", "shaders", "camera", "camera_path", "knobs", "seeds", "size",
                              "frames", "warmup", "scene_time", "buffer", "build", "gl", "host", "results"})
        for (const nlohmann::json& wrong : {nlohmann::json("3"), nlohmann::json::array(), nlohmann::json(nullptr)}) {
            if (wrong.is_string() && (std::string(field) == "buffer" || std::string(field) == "command")) continue;
            const std::string why = refusal(renderRecord([&](nlohmann::json& j) { j[field] = wrong; }));
            EXPECT_TRUE(startsWith(why, std::string("r.json: ") + field + ": ")) << field << " = " << wrong.dump() << ": " << why;
        }
    for (const char* field : {"grid", "results"})
        for (const std::function<void(nlohmann::json&)>& kind : {std::function<void(nlohmann::json&)>(bench), std::function<void(nlohmann::json&)>(tradeoff)}) {
            const std::string why = refusal(renderRecord([&](nlohmann::json& j) { kind(j); j[field] = "x"; }));
            EXPECT_TRUE(startsWith(why, std::string("r.json: ") + field + ": ")) << field << ": " << why;
        }
}

// The shader files a record holds: by their path in the shader folder, each
// with the sha256 of the text compiled; compared with a replay's by name.
TEST(ShaderFiles, RecordedByPathInTheFolderAndComparedByName) {
    const fs::path dir = test::tempDir() / "shader-files";
    fs::remove_all(dir);
    fs::create_directories(dir / "ssao");
    fs::create_directories(dir / "params");
    writeFile(dir / "ssao" / "ssao.frag", "void main() {}\n");
    writeFile(dir / "params" / "ssao.h", "// params\n");
    writeFile(dir / "overlay.frag", "void main() {}\n");
    gl::CompiledShaders compiled;
    compiled.root = dir;
    compiled.texts[fs::weakly_canonical(dir / "ssao" / "ssao.frag")] = "void main() {}\n";
    compiled.texts[fs::weakly_canonical(dir / "params" / "ssao.h")] = "// params\n";
    const RecordedShaders recorded = shaderFilesOf(compiled);
    ASSERT_EQ(recorded.files.size(), 2u);
    EXPECT_EQ(recorded.files[0].path, "params/ssao.h");
    EXPECT_EQ(recorded.files[1].path, "ssao/ssao.frag");
    EXPECT_EQ(recorded.files[1].sha256, sha256Hex("void main() {}\n", 15));
    EXPECT_EQ(recorded.folder, fs::weakly_canonical(dir).string());

    // Through a record's JSON and back.
    ExperimentRecord r = ExperimentRecord::parse(renderRecord([](nlohmann::json&) {}), "r.json");
    EXPECT_FALSE(r.shaders.present);  // a record written before shader hashes
    r.shaders = recorded;
    const ExperimentRecord back = ExperimentRecord::parse(r.json(), "r.json");
    ASSERT_TRUE(back.shaders.present);
    EXPECT_EQ(back.shaders.folder, recorded.folder);
    ASSERT_EQ(back.shaders.files.size(), 2u);
    EXPECT_EQ(back.shaders.files[0].sha256, recorded.files[0].sha256);

    EXPECT_TRUE(compareShaderFiles(recorded, recorded).empty());
    // Now: ssao.frag changed, params/ssao.h not compiled (looked up in the
    // folder: unchanged there), a new include compiled.
    gl::CompiledShaders again;
    again.root = dir;
    again.texts[fs::weakly_canonical(dir / "ssao" / "ssao.frag")] = "void main() { }\n";
    again.texts[fs::weakly_canonical(dir / "common.glsl")] = "// new\n";
    std::vector<SceneFileChange> c = compareShaderFiles(recorded, shaderFilesOf(again));
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0].kind, SceneFileChange::Kind::Changed);
    EXPECT_EQ(c[0].path, "ssao/ssao.frag");
    EXPECT_EQ(c[1].kind, SceneFileChange::Kind::Added);
    EXPECT_EQ(c[1].path, "common.glsl");
    // A recorded file neither compiled nor in the folder: removed; a path
    // leaving the folder is never opened.
    RecordedShaders withGone = recorded;
    withGone.files.push_back({"gone.frag", "ab"});
    withGone.files.push_back({"../outside.frag", "cd"});
    c = compareShaderFiles(withGone, shaderFilesOf(compiled));
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0].kind, SceneFileChange::Kind::Removed);
    EXPECT_EQ(c[0].path, "gone.frag");
    EXPECT_EQ(c[1].kind, SceneFileChange::Kind::Removed);
    EXPECT_EQ(c[1].path, "../outside.frag");
}

// Issue 32: a built-in scene reads no file, so its record holds the sha256 of
// what it generates. The hash follows the content (a vertex, a light, a
// material, a setting moved changes it), is the same for the same built-in
// made twice, and is not moved by the fire's particles, which move each frame.
TEST(SceneContent, TheHashOfABuiltInFollowsItsContentAndNotItsFrame) {
    const Scene base = makeBuiltinScene("default");
    const std::string hash = sceneContentSha256(base);
    EXPECT_EQ(hash.size(), 64u);
    EXPECT_EQ(sceneContentSha256(makeBuiltinScene("default")), hash);
    EXPECT_NE(sceneContentSha256(makeBuiltinScene("spheres")), hash);
    const std::vector<std::function<void(Scene&)>> edits = {
        [](Scene& s) { s.meshes[0].vertices[0].position.x += 1e-3f; },
        [](Scene& s) { s.meshes[0].indices[0] ^= 1u; },
        [](Scene& s) { s.lights[0].intensity *= 1.01f; },
        [](Scene& s) { s.lights.pop_back(); },
        [](Scene& s) { s.materials[0].roughness += 0.01f; },
        [](Scene& s) { s.settings.emplace_back("tonemap.key", "0.3"); },
        [](Scene& s) { s.ambient.y += 0.01f; },
    };
    for (size_t i = 0; i < edits.size(); ++i) {
        Scene edited = base;
        edits[i](edited);
        EXPECT_NE(sceneContentSha256(edited), hash) << "edit " << i;
    }
    // sceneFilesOf lists the content first, by the scene's source.
    const std::vector<RecordedFile> files = sceneFilesOf(base);
    ASSERT_FALSE(files.empty());
    EXPECT_EQ(files[0].path, "builtin:default");
    EXPECT_EQ(files[0].sha256, hash);
    // The fire: its particle lights move with the frame, its hash does not; its emitters count.
    Scene fire = makeBuiltinScene("fire");
    ASSERT_FALSE(fire.flames.empty());
    const std::string fireHash = sceneContentSha256(fire);
    const glm::vec3 before = fire.lights[fire.flames.firstLight].position;
    animateFlameParticles(fire, 37);
    EXPECT_NE(fire.lights[fire.flames.firstLight].position, before);
    EXPECT_EQ(sceneContentSha256(fire), fireHash);
    fire.flames.emitters[0].brightness *= 2.0f;
    EXPECT_NE(sceneContentSha256(fire), fireHash);
}

// Issue 32: a record holds the sha256 of its own inputs and results, and
// reading it says whether either was edited since; key order and
// indentation are not edits.
TEST(ExperimentRecord, ItsOwnSha256sTellAnEditedRecord) {
    ExperimentRecord r;
    r.sceneSpec = "default";
    r.width = 16;
    r.height = 9;
    r.knobs = {{"ssao.samples", "16"}};
    r.imageSha256 = std::string(64, 'a');
    const std::string text = r.json();
    const ExperimentRecord back = ExperimentRecord::parse(text, "r.json");
    EXPECT_TRUE(back.selfCheck.hashed);
    EXPECT_FALSE(back.selfCheck.inputsEdited);
    EXPECT_FALSE(back.selfCheck.resultsEdited);
    nlohmann::json j = nlohmann::json::parse(text);
    EXPECT_EQ(j["record_sha256"]["inputs"], back.selfCheck.nowInputs);
    const ExperimentRecord compact = ExperimentRecord::parse(j.dump(), "r.json");
    EXPECT_FALSE(compact.selfCheck.inputsEdited || compact.selfCheck.resultsEdited);
    j["knobs"]["ssao.samples"] = "32";
    const ExperimentRecord knob = ExperimentRecord::parse(j.dump(), "r.json");
    EXPECT_TRUE(knob.selfCheck.inputsEdited);
    EXPECT_FALSE(knob.selfCheck.resultsEdited);
    j = nlohmann::json::parse(text);
    j["results"]["image"]["sha256"] = std::string(64, 'b');
    const ExperimentRecord image = ExperimentRecord::parse(j.dump(), "r.json");
    EXPECT_FALSE(image.selfCheck.inputsEdited);
    EXPECT_TRUE(image.selfCheck.resultsEdited);
    j.erase("record_sha256");
    EXPECT_FALSE(ExperimentRecord::parse(j.dump(), "r.json").selfCheck.hashed);
}

// A merge's record (bench merge, tradeoff merge) has no run of its own: its
// size or frames may be 0 where the shards' JSONs said nothing. It reads as
// a merge's record, which replay names ("has no grid to run again"), not as
// a record with a size or frame count out of range.
TEST(ExperimentRecord, AMergesRecordReadsAsOneWithNoRunOfItsOwn) {
    const ExperimentRecord bench = ExperimentRecord::forBenchResults(BenchResults{}, BenchSummary{});
    EXPECT_EQ(bench.frames, 0);
    const ExperimentRecord b = ExperimentRecord::parse(bench.json(), "merged-bench.json");
    ASSERT_TRUE(b.bench);
    EXPECT_TRUE(b.bench->merged);
    const ExperimentRecord tradeoff = ExperimentRecord::forTradeoffTable(TradeoffTable{}, BenchFields{});
    EXPECT_EQ(tradeoff.width, 0);
    const ExperimentRecord t = ExperimentRecord::parse(tradeoff.json(), "merged-tradeoff.json");
    ASSERT_TRUE(t.tradeoff);
    EXPECT_TRUE(t.tradeoff->merged);
    // A run's record is still held to --frames' range.
    nlohmann::json run = nlohmann::json::parse(bench.json());
    run["grid"] = {{"merged", false}};
    EXPECT_THROW(ExperimentRecord::parse(run.dump(), "run.json"), FileError);
}

// Issue 34: a tradeoff record keeps --time, the budget and --search in its
// grid; they read back into the options replay runs, and a value no flag
// would take is refused naming the field.
TEST(ExperimentRecord, TradeoffGridKeepsTimeBudgetAndSearch) {
    auto tradeoff = [](nlohmann::json& j) {
        j["command"] = "tradeoff";
        j["grid"] = {{"axes", {{{"name", "ssao.samples"}, {"values", {"4", "8"}}}}}, {"metric", "flip"}, {"buffer", "final"},
                     {"time", "lighting+ao"}, {"budget_ms", 12.5}, {"budget", nullptr}, {"search", {{"max_evals", 30}}}};
        j["results"] = {{"axes", {"ssao.samples"}}, {"passes", nlohmann::json::array()}, {"rows", nlohmann::json::array()}};
    };
    const ExperimentRecord r = ExperimentRecord::parse(renderRecord(tradeoff), "r.json");
    ASSERT_TRUE(r.tradeoff.has_value());
    EXPECT_EQ(r.tradeoff->options.time, "lighting+ao");
    EXPECT_EQ(r.tradeoff->options.budgetMs, 12.5);
    EXPECT_EQ(r.tradeoff->options.budget, 0.0);
    EXPECT_TRUE(r.tradeoff->search);
    EXPECT_EQ(r.tradeoff->maxEvals, 30);
    // Older records: the results' time, no budget, no search.
    const ExperimentRecord old = ExperimentRecord::parse(renderRecord([&](nlohmann::json& j) {
                                                             tradeoff(j);
                                                             for (const char* k : {"time", "budget_ms", "budget", "search"})
                                                                 j["grid"].erase(k);
                                                             j["results"]["time"] = "ao";
                                                         }),
                                                         "r.json");
    EXPECT_EQ(old.tradeoff->options.time, "ao");
    EXPECT_EQ(old.tradeoff->options.budgetMs, 0.0);
    EXPECT_FALSE(old.tradeoff->search);
    EXPECT_NE(refusal(renderRecord([&](nlohmann::json& j) { tradeoff(j); j["grid"]["budget_ms"] = 0; })).find(
                  "r.json: grid.budget_ms: expects --budget-ms's value (above 0), got 0"),
              std::string::npos);
    EXPECT_NE(refusal(renderRecord([&](nlohmann::json& j) { tradeoff(j); j["grid"]["budget"] = "many"; })).find(
                  "r.json: grid.budget: expects --budget's value"),
              std::string::npos);
    EXPECT_NE(refusal(renderRecord([&](nlohmann::json& j) { tradeoff(j); j["grid"]["search"]["max_evals"] = 0; }))
                  .find("r.json: grid.search.max_evals"),
              std::string::npos);
}

// Issue 35: a tradeoff record keeps --ref-spp and --ref-filter in its grid,
// and a render record of a reference buffer its --spp and filter, through
// JSON and back; records before them read as 1 sample, box; a value no
// flag would take is refused naming the field.
TEST(ExperimentRecord, ReferenceSamplesPerPixelAndFilterGoThroughJson) {
    auto tradeoff = [](nlohmann::json& j) {
        j["command"] = "tradeoff";
        j["grid"] = {{"axes", {{{"name", "gbuffer.texture_filter"}, {"values", {"mipmap", "base_level"}}}}},
                     {"metric", "flip"}, {"buffer", "final"}, {"ref_spp", 16}, {"ref_filter", "tent"}};
        j["results"] = {{"axes", {"gbuffer.texture_filter"}}, {"passes", nlohmann::json::array()},
                        {"rows", nlohmann::json::array()}};
    };
    const ExperimentRecord r = ExperimentRecord::parse(renderRecord(tradeoff), "r.json");
    ASSERT_TRUE(r.tradeoff.has_value());
    EXPECT_EQ(r.tradeoff->refSpp, 16);
    EXPECT_EQ(r.tradeoff->refFilter, "tent");
    const ExperimentRecord back = ExperimentRecord::parse(r.json(), "back.json");
    ASSERT_TRUE(back.tradeoff.has_value());
    EXPECT_EQ(back.tradeoff->refSpp, 16);
    EXPECT_EQ(back.tradeoff->refFilter, "tent");
    EXPECT_EQ(nlohmann::json::parse(r.json())["grid"]["ref_spp"], 16);
    // Older records: the pixel's centre.
    const ExperimentRecord old = ExperimentRecord::parse(renderRecord([&](nlohmann::json& j) {
                                                             tradeoff(j);
                                                             j["grid"].erase("ref_spp");
                                                             j["grid"].erase("ref_filter");
                                                         }),
                                                         "r.json");
    EXPECT_EQ(old.tradeoff->refSpp, 1);
    EXPECT_EQ(old.tradeoff->refFilter, "box");
    EXPECT_NE(refusal(renderRecord([&](nlohmann::json& j) { tradeoff(j); j["grid"]["ref_spp"] = 0; }))
                  .find("r.json: grid.ref_spp"),
              std::string::npos);
    EXPECT_NE(refusal(renderRecord([&](nlohmann::json& j) { tradeoff(j); j["grid"]["ref_filter"] = "gauss"; }))
                  .find("r.json: grid.ref_filter: expects box or tent (as --filter takes it), got 'gauss'"),
              std::string::npos);

    // A render record of a reference buffer.
    ExperimentRecord render = ExperimentRecord::parse(renderRecord([](nlohmann::json&) {}), "r.json");
    render.setReference(8, 3, 4, "tent");
    const nlohmann::json j = nlohmann::json::parse(render.json());
    EXPECT_EQ(j["reference"]["spp"], 4);
    EXPECT_EQ(j["reference"]["filter"], "tent");
    const ExperimentRecord rendered = ExperimentRecord::parse(render.json(), "r.json");
    EXPECT_EQ(rendered.referenceAoRays, 8);
    EXPECT_EQ(rendered.referenceSeed, 3u);
    EXPECT_EQ(rendered.referenceSpp, 4);
    EXPECT_EQ(rendered.referenceFilter, "tent");
    const ExperimentRecord before = ExperimentRecord::parse(
        renderRecord([](nlohmann::json& k) { k["reference"] = {{"ao_rays", 8}}; }), "r.json");
    EXPECT_EQ(before.referenceSpp, 1);
    EXPECT_EQ(before.referenceFilter, "box");
    EXPECT_NE(refusal(renderRecord([](nlohmann::json& k) { k["reference"] = {{"ao_rays", 8}, {"spp", 70000}}; }))
                  .find("r.json: reference.spp"),
              std::string::npos);
}
