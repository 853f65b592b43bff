#include "app/ReplayDiff.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "app/ReplayReport.h"
#include "app/ReplaySearch.h"
#include "renderer/Error.h"
#include "renderer/RunConfig.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/record/SceneFiles.h"
#include "renderer/record/ShaderFiles.h"

namespace dw {

namespace {

using replay::ChangedInputs;
namespace fs = std::filesystem;

std::string nameOf(const std::string& path) { return fs::path(path).filename().string(); }

std::string shown(const nlohmann::json& v) {
    if (v.is_null()) return "none";
    return v.is_string() ? v.get<std::string>() : v.dump();
}

// "FIELD: A -> B" for a value that differs (absent on one side: "none").
void reportValue(const std::string& field, const nlohmann::json& a, const nlohmann::json& b, ChangedInputs& inputs) {
    if (a == b) return;
    std::printf("%s: %s -> %s\n", field.c_str(), shown(a).c_str(), shown(b).c_str());
    inputs.add(field);
}

// Each key of two objects ("grid", "camera") that differs, as "PREFIX.KEY".
void reportObject(const std::string& prefix, const nlohmann::json& a, const nlohmann::json& b, ChangedInputs& inputs) {
    if (!a.is_object() || !b.is_object()) {
        reportValue(prefix, a, b, inputs);
        return;
    }
    std::set<std::string> keys;
    for (const auto& [k, v] : a.items()) keys.insert(k);
    for (const auto& [k, v] : b.items()) keys.insert(k);
    for (const auto& k : keys)
        reportValue(prefix + "." + k, a.contains(k) ? a[k] : nlohmann::json(), b.contains(k) ? b[k] : nlohmann::json(),
                    inputs);
}

// Name -> text fields (build, gl, host, seeds) that differ: "WHAT KEY: A -> B".
void reportFields(const std::string& what, const RecordFields& a, const RecordFields& b, ChangedInputs& inputs,
                  const std::set<std::string>& skip = {}) {
    std::map<std::string, std::string> left(a.begin(), a.end()), right(b.begin(), b.end());
    std::set<std::string> keys;
    for (const auto& [k, v] : a) keys.insert(k);
    for (const auto& [k, v] : b) keys.insert(k);
    for (const auto& k : keys) {
        if (skip.count(k)) continue;
        const std::string va = left.count(k) ? left[k] : "none", vb = right.count(k) ? right[k] : "none";
        if (va == vb) continue;
        std::printf("%s %s: %s -> %s\n", what.c_str(), k.c_str(), va.c_str(), vb.c_str());
        inputs.add(what + " " + k);
    }
}

// Knobs by their current names (an old name in one record is the knob it became).
void reportKnobs(const ExperimentRecord& a, const ExperimentRecord& b, const std::string& nameA, const std::string& nameB,
                 ChangedInputs& inputs) {
    const KnobRegistry declared = RunConfig::declaredKnobs();
    auto byName = [&](const RecordFields& knobs) {
        std::map<std::string, std::string> m;
        for (const auto& [k, v] : knobs) m[declared.canonicalName(k)] = v;
        return m;
    };
    const auto left = byName(a.knobs), right = byName(b.knobs);
    for (const auto& [k, v] : left) {
        const auto it = right.find(k);
        if (it == right.end()) {
            std::printf("knob not in %s: %s (recorded %s)\n", nameB.c_str(), k.c_str(), v.c_str());
            inputs.add("knob " + k);
        } else if (it->second != v) {
            std::printf("knob %s: %s -> %s\n", k.c_str(), v.c_str(), it->second.c_str());
            inputs.add("knob " + k);
        }
    }
    for (const auto& [k, v] : right)
        if (!left.count(k)) {
            std::printf("knob not in %s: %s (recorded %s)\n", nameA.c_str(), k.c_str(), v.c_str());
            inputs.add("knob " + k);
        }
}

void reportFiles(const ExperimentRecord& a, const ExperimentRecord& b, const std::string& nameA, const std::string& nameB,
                 ChangedInputs& inputs) {
    replay::reportFileChanges("scene file", compareSceneFiles(a.sceneFiles, a.sceneSpec, b.sceneFiles, b.sceneSpec),
                              nameB + " does not list it", inputs, nameA + " does not list it");
    if (!a.shaders.present || !b.shaders.present) {
        for (const auto* r : {&a, &b})
            if (!r->shaders.present)
                std::printf("%s: record holds no shader hashes (written before records kept them)\n",
                            (r == &a ? nameA : nameB).c_str());
        return;
    }
    RecordedShaders right = b.shaders;
    right.folder.clear();  // compare the two lists only: no file is looked up
    replay::reportFileChanges("shader file", compareShaderFiles(a.shaders, right), nameB + " does not list it", inputs,
                              nameA + " does not list it");
}

// Every input, build and machine field that differs, in replay's words.
void reportInputs(const ExperimentRecord& a, const ExperimentRecord& b, const std::string& nameA,
                  const std::string& nameB, ChangedInputs& inputs) {
    reportValue("command", a.command, b.command, inputs);
    if (a.sceneSpec != b.sceneSpec) reportValue("scene", a.sceneSpec, b.sceneSpec, inputs);
    reportFiles(a, b, nameA, nameB, inputs);
    reportKnobs(a, b, nameA, nameB, inputs);
    reportFields("seed", a.seeds, b.seeds, inputs);
    // The other inputs as the records write them (the same JSON either way).
    JsonGuardOptions exact;
    exact.numbersAreFloats = false;  // records hold 64-bit counts and hashes
    const nlohmann::json ja = parseJson(a.json(), nameA, exact), jb = parseJson(b.json(), nameB, exact);
    for (const char* key : {"camera", "camera_path", "grid"})
        reportObject(key, ja.contains(key) ? ja[key] : nlohmann::json(), jb.contains(key) ? jb[key] : nlohmann::json(),
                     inputs);
    for (const char* key : {"size", "frames", "warmup", "buffer"})
        reportValue(key, ja.contains(key) ? ja[key] : nlohmann::json(), jb.contains(key) ? jb[key] : nlohmann::json(),
                    inputs);
    reportFields("build", a.build, b.build, inputs);
    reportFields("gl", a.gl, b.gl, inputs);
    reportFields("host", a.host, b.host, inputs, {"date"});
}

// B's results against A's, as replay compares a new run with its record.
int compareResults(const ExperimentRecord& a, const ExperimentRecord& b, const std::string& pathA,
                   const std::string& pathB) {
    if (a.command != b.command) {
        std::printf("results: not compared (a %s record and a %s record)\n", a.command.c_str(), b.command.c_str());
        return 1;
    }
    if (a.command == "bench") {
        const std::string series = a.bench->ratioOf;
        std::vector<std::pair<int, replay::RecordedConfig>> after;
        for (auto& entry : replay::recordedConfigs(b.benchResults, series)) after.push_back(std::move(entry));
        return replay::compareBench(replay::recordedConfigs(a.benchResults, series), after, series, a.bench->resamples)
            .verdict();
    }
    if (a.command == "tradeoff") {
        const TradeoffTable before = a.tradeoffTable(pathA), after = b.tradeoffTable(pathB);
        replay::TradeoffComparison compared = replay::compareTradeoff(
            before, after, a.frames, b.frames,
            a.tradeoff->options.cost != "gpu_ms" && a.tradeoff->options.cost == b.tradeoff->options.cost);
        compared.pickMoved = replay::reportPick(before, after);
        return compared.verdict();
    }
    replay::compareTimings(a.timings, b.timings);
    const int counters = replay::compareCounters(a.timings, b.timings);
    return std::max(replay::imageVerdict(a.imageSha256, b.imageSha256), counters);
}

}  // namespace

int runReplayDiff(const std::string& pathA, const std::string& pathB) {
    ExperimentRecord a, b;
    try {
        a = ExperimentRecord::read(pathA);
        b = ExperimentRecord::read(pathB);
    } catch (const Error& e) {
        std::fprintf(stderr, "refused: %s\n", e.what());
        return 2;
    }
    std::string nameA = nameOf(pathA), nameB = nameOf(pathB);
    if (nameA == nameB) nameA = pathA, nameB = pathB;
    ChangedInputs inputs;
    replay::reportSelfCheck(a, nameA + ": ", inputs);
    replay::reportSelfCheck(b, nameB + ": ", inputs);
    reportInputs(a, b, nameA, nameB, inputs);
    inputs.print();
    try {
        return compareResults(a, b, pathA, pathB);
    } catch (const Error& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "refused: %s\n", e.what());
        return 2;
    }
}

}  // namespace dw
