#include "renderer/record/ExperimentRecord.h"

#include <sys/utsname.h>

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <thread>

#include "renderer/Error.h"
#include "renderer/OptionLimits.h"
#include "renderer/bench/Bootstrap.h"
#include "renderer/bench/BenchSummary.h"
#include "renderer/bench/TradeoffTable.h"
#include "renderer/graph/RenamedOutputs.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"
#include "renderer/record/BuildInfo.h"
#include "renderer/record/HostInfo.h"
#include "renderer/record/SceneFiles.h"
#include "renderer/scene/BuiltinScenes.h"
#include "renderer/scene/CameraCheck.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;
const char* const kFormat = "deferred-workbench record";

// A scene spec, source or file that names a file (not a built-in scene).
bool namesFile(const std::string& p) {
    return !p.empty() && !isBuiltinScene(p) && p.rfind("builtin:", 0) != 0;
}

// A path relative to the working directory, as written into a record in
// `recordDir` (absolute): relative to that folder. Absolute paths and
// built-in names stay.
std::string relativeToRecord(const std::string& p, const fs::path& recordDir) {
    if (!namesFile(p) || fs::path(p).is_absolute()) return p;
    std::error_code ec;
    const fs::path abs = fs::absolute(p, ec).lexically_normal();
    if (ec) return p;
    const fs::path rel = abs.lexically_relative(recordDir);
    return rel.empty() ? abs.string() : rel.string();
}

// A relative path read from a record in `recordDir`: against that folder;
// when nothing is there but the path names a file from the working
// directory, that one (records written before paths were kept relative to
// the record). Otherwise the record's folder, so an error names where it looked.
std::string resolvedFromRecord(const std::string& p, const fs::path& recordDir) {
    if (!namesFile(p) || fs::path(p).is_absolute()) return p;
    const std::string there = (recordDir / p).lexically_normal().string();
    std::error_code ec;
    if (fs::exists(there, ec)) return there;
    if (fs::exists(p, ec)) return p;
    return there;
}

// A whole number field held to the range of the option it stands for.
int wholeNumber(const nlohmann::json& v, const std::string& path, const std::string& field, OptionRange range,
                const std::string& option) {
    if (!v.is_number_integer())
        throw FileError(path, field + ": expects a whole number (as " + option + " does), got " + v.dump());
    const long long n = v.is_number_unsigned() && v.get<unsigned long long>() > 9223372036854775807ull
                            ? 9223372036854775807ll
                            : v.get<long long>();
    if (!range.holds(n))
        throw FileError(path, field + ": " + std::to_string(n) + " is outside " + option + "'s range " +
                                  std::to_string(range.min) + ".." + std::to_string(range.max));
    return static_cast<int>(n);
}

// "WxH" with both sides in --size's range.
std::pair<int, int> sizeField(const std::string& t, const std::string& path, const std::string& field) {
    const size_t x = t.find('x');
    if (x == std::string::npos) throw FileError(path, field + ": '" + t + "' is not WxH");
    auto side = [&](const std::string& s, const char* which) {
        long long n = 0;
        const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
        if (s.empty() || ec == std::errc::invalid_argument || end != s.data() + s.size())
            throw FileError(path, field + ": '" + t + "' is not WxH");
        if (ec == std::errc::result_out_of_range) n = s[0] == '-' ? LLONG_MIN : LLONG_MAX;
        return wholeNumber(nlohmann::json(n), path, field + " " + which, limits::kSize, "--size");
    };
    return {side(t.substr(0, x), "width"), side(t.substr(x + 1), "height")};
}

// CameraCheck's field names as the record names them.
std::string recordCameraField(const std::string& field) {
    if (field == "fov") return "camera.fov_y_degrees";
    if (field == "pos") return "camera.position";
    if (field == "look-at") return "camera.target";
    return "camera." + field;  // near, far, up
}

Json fieldsJson(const RecordFields& fields) {
    Json j = Json::object();
    for (const auto& [k, v] : fields) j[k] = v;
    return j;
}

RecordFields fieldsOf(const nlohmann::json& j) {
    RecordFields f;
    if (!j.is_object()) return f;
    for (auto it = j.begin(); it != j.end(); ++it)
        f.emplace_back(it.key(), it.value().is_string() ? it.value().get<std::string>() : it.value().dump());
    return f;
}

std::string fieldOr(const RecordFields& f, const std::string& key, const std::string& fallback) {
    for (const auto& [k, v] : f)
        if (k == key) return v;
    return fallback;
}

Json vec3(const glm::vec3& v) { return Json::array({v.x, v.y, v.z}); }

glm::vec3 readVec3(const nlohmann::json& j, const std::string& path, const std::string& field) {
    if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
        throw FileError(path, field + ": expected [x, y, z]");
    return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}

// Finite numbers as themselves, anything else as null (JSON has no NaN).
Json number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

// The median with its bootstrap 95% interval; below kMinIntervalSamples
// frames the median with "ci95": null and why.
Json intervalJson(const std::vector<double>& values) {
    if (values.empty()) return Json(nullptr);
    if (!enoughForInterval(values.size()))
        return {{"median", number(median(values))},
                {"ci95", nullptr},
                {"interval", kTooFewForInterval + " (" + std::to_string(values.size()) + " counted, " +
                                 std::to_string(kMinIntervalSamples) + " needed)"}};
    const MedianInterval m = bootstrapMedian(values, 2000, ExperimentRecord::kBootstrapSeed);
    if (!m.valid()) return Json(nullptr);
    return {{"median", number(m.median)}, {"ci95", {number(m.low), number(m.high)}}};
}

RecordFields hostFields() {
    RecordFields host;
    host.emplace_back("cpu", cpuModel());
    host.emplace_back("cpu_threads", std::to_string(std::thread::hardware_concurrency()));
    utsname u{};
    if (uname(&u) == 0) host.emplace_back("os", std::string(u.sysname) + " " + u.release + " " + u.machine);
    host.emplace_back("date", utcNow());
    return host;
}

std::string sizeText(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

RecordFields ExperimentRecord::knobFields(const KnobRegistry& knobs) {
    RecordFields f;
    for (size_t i = 0; i < knobs.size(); ++i) f.emplace_back(knobs.spec(static_cast<int>(i)).name, knobs.format(static_cast<int>(i)));
    return f;
}

std::string ExperimentRecord::hashBuffer(RenderSession& session, const std::string& buffer, int& width, int& height,
                                         int& channels) {
    const PublishedOutput* o = session.pipeline().outputs().find(buffer);
    if (!o) throw Error(unknownBufferMessage(buffer));
    const FloatImage image = session.readRaw(buffer);
    width = image.width;
    height = image.height;
    channels = image.channels;
    if (!isDisplayReady(*o)) return sha256Hex(image.pixels.data(), image.pixels.size() * sizeof(float));
    // The 8-bit values a .png of it holds (ImageIO's conversion).
    std::vector<std::uint8_t> bytes(image.pixels.size());
    for (size_t i = 0; i < bytes.size(); ++i) {
        const float v = image.pixels[i];
        bytes[i] = static_cast<std::uint8_t>((std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f) * 255.0f + 0.5f);
    }
    return sha256Hex(bytes.data(), bytes.size());
}

ExperimentRecord ExperimentRecord::capture(RenderSession& session, const RunConfig& run, const std::string& buffer,
                                           std::uint64_t firstCounted, const std::string& glPlatform) {
    ExperimentRecord r;
    r.sceneSpec = run.sceneSpec();
    r.sceneSource = session.scene().source;
    r.sceneFiles = sceneFilesOf(session.scene());
    r.camera = session.camera();
    r.knobs = knobFields(session.knobs());
    r.seeds.emplace_back("bootstrap", std::to_string(kBootstrapSeed));
    r.width = run.width;
    r.height = run.height;
    r.frames = run.frames;
    r.warmup = run.warmup;
    r.buffer = buffer;
    r.build = buildFields();
    const gl::GlInfo& info = session.glInfo();
    r.gl = {{"vendor", info.vendor}, {"renderer", info.renderer}, {"version", info.version}, {"platform", glPlatform}};
    r.host = hostFields();
    PassTimer& timer = session.pipeline().timer();
    timer.collect(true);
    for (const PassTimer::Series& s : timer.series()) {
        RecordedSeries rs{s.name, {}, {}};
        for (const TimingSample& t : s.samples)
            if (t.frame >= firstCounted) {
                rs.gpuMs.push_back(t.gpuMs);
                rs.cpuMs.push_back(t.cpuMs);
            }
        if (!rs.gpuMs.empty()) r.timings.push_back(std::move(rs));
    }
    r.imageSha256 = hashBuffer(session, buffer, r.imageWidth, r.imageHeight, r.imageChannels);
    return r;
}

ExperimentRecord ExperimentRecord::forBenchResults(const BenchResults& results, const BenchSummary& summary) {
    ExperimentRecord r;
    r.command = "bench";
    r.sceneSpec = fieldOr(results.settings, "scene", "");
    r.sceneSource = r.sceneSpec;
    r.frames = std::atoi(fieldOr(results.settings, "frames", "0").c_str());
    r.warmup = std::atoi(fieldOr(results.settings, "warmup_per_switch", "0").c_str());
    r.seeds = {{"lights", fieldOr(results.settings, "seed", "1")}, {"bootstrap", std::to_string(kBootstrapSeed)}};
    if (!results.configs.empty()) {
        r.width = results.configs.front().config.width;
        r.height = results.configs.front().config.height;
    }
    r.buffer = "";
    r.build = buildFields();
    r.gl = {{"vendor", fieldOr(results.machine, "gl_vendor", "")},
            {"renderer", fieldOr(results.machine, "gl_renderer", "")},
            {"version", fieldOr(results.machine, "gl_version", "")},
            {"platform", fieldOr(results.machine, "gl_platform", "")}};
    r.host = hostFields();
    for (const auto& key : {"cpu", "cpu_threads", "host", "os"}) {
        const std::string v = fieldOr(results.machine, key, "");
        if (v.empty()) continue;
        bool set = false;
        for (auto& [k, old] : r.host)
            if (k == key) old = v, set = true;
        if (!set) r.host.emplace_back(key, v);
    }
    RecordedBench b;
    b.merged = true;
    b.ratioOf = summary.baseline.series;
    r.bench = b;
    r.benchResults = benchResultsJson(results, summary);
    return r;
}

ExperimentRecord ExperimentRecord::forBench(const RecordedBench& bench, const Scene& scene, const BenchResults& results,
                                            const BenchSummary& summary) {
    ExperimentRecord r = forBenchResults(results, summary);
    const BenchOptions& o = bench.options;
    r.sceneSpec = o.run.sceneSpec();
    r.sceneSource = scene.source;
    r.sceneFiles = sceneFilesOf(scene);
    r.camera = o.run.camera(scene);
    if (o.walkthrough) {
        r.cameraPath.mode = "walkthrough";
        r.cameraPath.keyframes = scene.cameraPath;
    } else if (o.orbit > 0) {
        r.cameraPath.mode = "orbit";
        r.cameraPath.orbitPoses = o.orbit;
    }
    // The knobs every configuration starts from (its swept values go over them).
    KnobRegistry knobs = RunConfig::declaredKnobs();
    o.run.applyKnobs(knobs, scene);
    r.knobs = knobFields(knobs);
    r.seeds = {{"lights", std::to_string(o.seed)}, {"bootstrap", std::to_string(kBootstrapSeed)}};
    r.frames = o.frames;
    r.warmup = o.warmup;
    if (!o.grid.sizes.empty()) std::tie(r.width, r.height) = o.grid.sizes.front();
    r.bench = bench;
    r.bench->merged = false;
    return r;
}

namespace {

Json settingsJson(const BenchFields& settings) {
    Json s = Json::object();
    for (const auto& [k, v] : settings) {
        if (s.contains(k)) {
            if (!s[k].is_array()) s[k] = Json::array({s[k]});
            s[k].push_back(v);
        } else {
            s[k] = v;
        }
    }
    return s;
}

std::string fieldOfBench(const BenchFields& f, const std::string& key) {
    for (const auto& [k, v] : f)
        if (k == key) return v;
    return "";
}

// A tradeoff table as a record's results: per point and camera the swept
// knobs, the error with its interval, the times, the front; and `metrics`,
// the errors alone with what they were measured on and against.
Json tradeoffResultsJson(const TradeoffTable& t, const BenchFields& machine, const BenchFields& settings) {
    Json m = Json::object();
    for (const auto& [k, v] : machine) m[k] = v;
    const std::string against = fieldOfBench(settings, "against");
    Json rows = Json::array(), front = Json::array(), metrics = Json::array();
    for (const auto& r : t.rows) {
        Json values = Json::object(), passes = Json::object();
        for (size_t a = 0; a < t.axes.size(); ++a) values[t.axes[a]] = r.axisValues[a];
        for (size_t p = 0; p < t.passes.size(); ++p) passes[t.passes[p]] = number(r.passGpuMs[p]);
        rows.push_back({{"point", r.point}, {"values", values}, {"camera", r.camera}, {"metric", r.metric},
                        {"buffer", r.buffer}, {"error", number(r.error)},
                        {"error_ci95", {number(r.errorLo), number(r.errorHi)}}, {"frames", r.frames},
                        {"frame_gpu_ms", number(r.frameGpuMs)},
                        {"frame_gpu_ms_ci95", {number(r.frameGpuMsLo), number(r.frameGpuMsHi)}}, {"gpu_ms", passes},
                        {"pareto", r.pareto}});
        if (r.pareto) front.push_back({{"point", r.point}, {"camera", r.camera}});
        metrics.push_back({{"point", r.point}, {"camera", r.camera}, {"metric", r.metric}, {"buffer", r.buffer},
                           {"against", against}, {"value", number(r.error)},
                           {"ci95", {number(r.errorLo), number(r.errorHi)}}});
    }
    return {{"machine", m}, {"settings", settingsJson(settings)}, {"axes", t.axes}, {"passes", t.passes},
            {"rows", rows}, {"front", front}, {"metrics", metrics}};
}

double numberOr(const nlohmann::json& j) { return j.is_number() ? j.get<double>() : NAN; }

}  // namespace

ExperimentRecord ExperimentRecord::forTradeoffTable(const TradeoffTable& table, const BenchFields& settings) {
    ExperimentRecord r;
    r.command = "tradeoff";
    r.buffer = "";
    r.build = buildFields();
    r.host = hostFields();
    r.seeds = {{"bootstrap", std::to_string(kBootstrapSeed)}};
    const std::string size = fieldOfBench(settings, "size");
    if (const size_t x = size.find('x'); x != std::string::npos) {
        r.width = std::atoi(size.substr(0, x).c_str());
        r.height = std::atoi(size.substr(x + 1).c_str());
    }
    r.frames = std::max(1, std::atoi(fieldOfBench(settings, "frames").c_str()));
    r.warmup = std::max(0, std::atoi(fieldOfBench(settings, "warmup_per_switch").c_str()));
    RecordedTradeoff t;
    t.merged = true;
    r.tradeoff = t;
    r.tradeoffResults = tradeoffResultsJson(table, {}, settings);
    return r;
}

ExperimentRecord ExperimentRecord::forTradeoff(const RecordedTradeoff& tradeoff, const Scene& scene,
                                               const TradeoffTable& table, const BenchFields& machine,
                                               const BenchFields& settings) {
    ExperimentRecord r = forTradeoffTable(table, settings);
    const TradeoffOptions& o = tradeoff.options;
    r.tradeoff = tradeoff;
    r.tradeoff->merged = false;
    r.tradeoffResults = tradeoffResultsJson(table, machine, settings);
    r.sceneSpec = o.run.sceneSpec();
    r.sceneSource = scene.source;
    r.sceneFiles = sceneFilesOf(scene);
    r.camera = o.run.camera(scene);
    if (o.walkthrough) {
        r.cameraPath.mode = "walkthrough";
        r.cameraPath.keyframes = scene.cameraPath;
    } else if (o.orbit > 0) {
        r.cameraPath.mode = "orbit";
        r.cameraPath.orbitPoses = o.orbit;
    }
    // The knobs every point starts from (its axis values go over them).
    KnobRegistry knobs = RunConfig::declaredKnobs();
    o.run.applyKnobs(knobs, scene);
    r.knobs = knobFields(knobs);
    r.frames = o.frames;
    r.warmup = o.warmup;
    r.width = o.run.width;
    r.height = o.run.height;
    r.buffer = o.buffer;
    r.gl = {{"vendor", fieldOfBench(machine, "gl_vendor")},
            {"renderer", fieldOfBench(machine, "gl_renderer")},
            {"version", fieldOfBench(machine, "gl_version")},
            {"platform", fieldOfBench(machine, "gl_platform")}};
    return r;
}

TradeoffTable ExperimentRecord::tradeoffTable(const std::string& path) const {
    TradeoffTable t;
    try {
        const Json& res = tradeoffResults;
        t.axes = res.at("axes").get<std::vector<std::string>>();
        t.passes = res.at("passes").get<std::vector<std::string>>();
        for (const auto& row : res.at("rows")) {
            TradeoffRow r;
            r.point = row.at("point").get<int>();
            for (const auto& a : t.axes) r.axisValues.push_back(row.at("values").at(a).get<std::string>());
            r.camera = row.at("camera").get<std::string>();
            r.metric = row.at("metric").get<std::string>();
            r.buffer = row.at("buffer").get<std::string>();
            r.error = numberOr(row.at("error"));
            r.errorLo = numberOr(row.at("error_ci95").at(0));
            r.errorHi = numberOr(row.at("error_ci95").at(1));
            r.frames = row.value("frames", 0);
            r.frameGpuMs = numberOr(row.at("frame_gpu_ms"));
            r.frameGpuMsLo = numberOr(row.at("frame_gpu_ms_ci95").at(0));
            r.frameGpuMsHi = numberOr(row.at("frame_gpu_ms_ci95").at(1));
            for (const auto& p : t.passes) {
                const auto& g = row.at("gpu_ms");
                r.passGpuMs.push_back(g.contains(p) ? numberOr(g[p]) : NAN);
            }
            r.pareto = row.value("pareto", false);
            t.rows.push_back(std::move(r));
        }
    } catch (const nlohmann::json::exception& e) {
        throw FileError(path, "tradeoff results: " + jsonErrorText(e));
    }
    return t;
}

std::string ExperimentRecord::json(const std::string& recordPath) const {
    std::error_code ec;
    const fs::path recordDir = recordPath.empty() ? fs::path() : fs::absolute(recordPath, ec).parent_path().lexically_normal();
    auto placed = [&](const std::string& p) { return recordPath.empty() || ec ? p : relativeToRecord(p, recordDir); };
    Json j;
    j["format"] = kFormat;
    j["version"] = version;
    j["command"] = command;
    Json files = Json::array();
    for (const auto& f : sceneFiles) files.push_back({{"path", placed(f.path)}, {"sha256", f.sha256}});
    j["scene"] = {{"spec", placed(sceneSpec)}, {"source", placed(sceneSource)}, {"files", files}};
    j["camera"] = {{"position", vec3(camera.position)}, {"target", vec3(camera.target)}, {"up", vec3(camera.up)},
                   {"fov_y_degrees", camera.fovYDegrees}, {"near", camera.nearPlane}, {"far", camera.farPlane}};
    Json path = {{"mode", cameraPath.mode}};
    if (cameraPath.mode == "orbit") path["orbit_poses"] = cameraPath.orbitPoses;
    if (!cameraPath.keyframes.empty()) {
        Json keys = Json::array();
        for (const auto& k : cameraPath.keyframes)
            keys.push_back({{"time", k.time}, {"position", vec3(k.position)}, {"target", vec3(k.target)}});
        path["keyframes"] = keys;
    }
    j["camera_path"] = path;
    j["knobs"] = fieldsJson(knobs);
    j["seeds"] = fieldsJson(seeds);
    j["size"] = Json::array({width, height});
    j["frames"] = frames;
    j["warmup"] = warmup;
    if (command != "bench" && command != "tradeoff") j["buffer"] = buffer;
    if (bench) {
        const BenchOptions& o = bench->options;
        Json sizes = Json::array(), sweep = Json::array();
        for (const auto& [w, h] : o.grid.sizes) sizes.push_back(sizeText(w, h));
        for (const auto& a : o.grid.knobAxes) sweep.push_back({{"knob", a.knob}, {"values", a.values}});
        if (bench->merged)
            j["grid"] = {{"merged", true}};
        else
            j["grid"] = {{"sizes", sizes},
                         {"lights", o.grid.lights},
                         {"sweep", sweep},
                         {"block", o.block},
                         {"light_radius", o.lightRadius},
                         {"keep_scene_lights", o.keepSceneLights},
                         {"orbit", o.orbit},
                         {"walkthrough", o.walkthrough},
                         {"lpp", o.lpp},
                         {"lpp_poses", o.lppPoses},
                         {"shard", std::to_string(o.shard.index) + "/" + std::to_string(o.shard.count)},
                         {"baseline", o.baseline},
                         {"ratio_of", bench->ratioOf},
                         {"resamples", bench->resamples}};
    }
    if (tradeoff) {
        const TradeoffOptions& o = tradeoff->options;
        if (tradeoff->merged) {
            j["grid"] = {{"merged", true}};
        } else {
            Json axes = Json::array();
            for (const auto& a : o.sweep.axes) axes.push_back({{"name", a.name}, {"values", a.values}});
            j["grid"] = {{"axes", axes},
                         {"one_at_a_time", o.sweep.oneAtATime},
                         {"centre", o.sweep.centre},
                         {"exclude", tradeoff->exclude},
                         {"against", o.against},
                         {"metric", o.metric},
                         {"buffer", o.buffer},
                         {"ao_rays", tradeoff->aoRays},
                         {"orbit", o.orbit},
                         {"walkthrough", o.walkthrough},
                         {"block", o.block},
                         {"resamples", o.resamples},
                         {"run_preset", tradeoff->runPreset},
                         {"run_presets", tradeoff->runPresets},
                         {"run_sets", tradeoff->runSets},
                         {"shard", std::to_string(o.shard.index) + "/" + std::to_string(o.shard.count)}};
        }
    }
    j["build"] = fieldsJson(build);
    j["gl"] = fieldsJson(gl);
    j["host"] = fieldsJson(host);
    if (command == "bench") {
        j["results"] = benchResults.is_null() ? Json::object() : benchResults;
    } else if (command == "tradeoff") {
        j["results"] = tradeoffResults.is_null() ? Json::object() : tradeoffResults;
    } else {
        Json series = Json::array();
        for (const auto& s : timings)
            series.push_back({{"name", s.name}, {"gpu_ms", s.gpuMs}, {"cpu_ms", s.cpuMs}, {"gpu", intervalJson(s.gpuMs)},
                              {"cpu", intervalJson(s.cpuMs)}});
        Json m = Json::object();
        for (const auto& [k, v] : metrics) m[k] = number(v);
        j["results"] = {{"timings", series},
                        {"image", {{"buffer", buffer}, {"sha256", imageSha256}, {"width", imageWidth},
                                   {"height", imageHeight}, {"channels", imageChannels}}},
                        {"metrics", m}};
    }
    return j.dump(2) + "\n";
}

void ExperimentRecord::write(const std::string& path) const { writeFileAtomically(path, json(path)); }

ExperimentRecord ExperimentRecord::read(const std::string& path) {
    JsonGuardOptions options;
    options.numbersAreFloats = false;
    return fromJson(readJsonFile(path, options), path);
}

ExperimentRecord ExperimentRecord::parse(const std::string& text, const std::string& path) {
    JsonGuardOptions options;
    options.numbersAreFloats = false;
    return fromJson(parseJson(text, path, options), path);
}

ExperimentRecord ExperimentRecord::fromJson(const nlohmann::json& j, const std::string& path) {
    if (!j.is_object() || !j.contains("format") || j["format"] != kFormat)
        throw FileError(path, std::string("not a deferred-workbench record (no \"format\": \"") + kFormat + "\")");
    if (!j.contains("version") || !j["version"].is_number_integer())
        throw FileError(path, "the record has no integer \"version\"");
    ExperimentRecord r;
    r.readVersion = j["version"].get<int>();
    if (r.readVersion > kVersion)
        throw FileError(path, "record version " + std::to_string(r.readVersion) + " is newer than this build reads (" +
                                  std::to_string(kVersion) + "); replay it with a newer deferred-workbench");
    if (r.readVersion < 1) throw FileError(path, "record version " + std::to_string(r.readVersion) + " does not exist");
    try {
        r.command = j.at("command").get<std::string>();
        if (r.command != "render" && r.command != "bench" && r.command != "tradeoff" && r.command != "gui")
            throw FileError(path, "unknown command '" + r.command + "' (render, bench, tradeoff or gui)");
        if (r.readVersion == 1 && r.command != "render")
            throw FileError(path, "a version 1 record is of render only, this one says '" + r.command + "'");
        const auto& scene = j.at("scene");
        r.sceneSpec = scene.at("spec").get<std::string>();
        r.sceneSource = scene.value("source", "");
        for (const auto& f : scene.value("files", nlohmann::json::array()))
            r.sceneFiles.push_back({f.at("path").get<std::string>(), f.at("sha256").get<std::string>()});
        // Relative paths: against the record's folder (then the working directory).
        const fs::path recordDir = fs::path(path).parent_path();
        r.sceneSpec = resolvedFromRecord(r.sceneSpec, recordDir);
        r.sceneSource = resolvedFromRecord(r.sceneSource, recordDir);
        for (auto& f : r.sceneFiles) f.path = resolvedFromRecord(f.path, recordDir);
        const auto& cam = j.at("camera");
        r.camera.position = readVec3(cam.at("position"), path, "camera.position");
        r.camera.target = readVec3(cam.at("target"), path, "camera.target");
        r.camera.up = readVec3(cam.at("up"), path, "camera.up");
        r.camera.fovYDegrees = cam.at("fov_y_degrees").get<float>();
        r.camera.nearPlane = cam.at("near").get<float>();
        r.camera.farPlane = cam.at("far").get<float>();
        // Version 1 had a fixed camera and no seeds (render used none).
        if (j.contains("camera_path")) {
            const auto& p = j["camera_path"];
            r.cameraPath.mode = p.at("mode").get<std::string>();
            r.cameraPath.orbitPoses = p.value("orbit_poses", 0);
            for (const auto& k : p.value("keyframes", nlohmann::json::array()))
                r.cameraPath.keyframes.push_back({k.at("time").get<float>(),
                                                  readVec3(k.at("position"), path, "camera_path.keyframes.position"),
                                                  readVec3(k.at("target"), path, "camera_path.keyframes.target")});
        }
        r.knobs = fieldsOf(j.at("knobs"));
        r.seeds = fieldsOf(j.value("seeds", nlohmann::json::object()));
        // Held to the ranges of --size, --frames and --warmup.
        const auto& size = j.at("size");
        if (!size.is_array() || size.size() != 2) throw FileError(path, "size: expected [width, height]");
        r.width = wholeNumber(size.at(0), path, "size width", limits::kSize, "--size");
        r.height = wholeNumber(size.at(1), path, "size height", limits::kSize, "--size");
        r.frames = wholeNumber(j.at("frames"), path, "frames", limits::kFrames, "--frames");
        r.warmup = wholeNumber(j.at("warmup"), path, "warmup", limits::kWarmup, "--warmup");
        // The one definition of a usable camera (a zero up vector renders nothing useful).
        if (const auto problem = findCameraProblem(r.camera, 0.0f))
            throw FileError(path, recordCameraField(problem->field) + ": " + problem->what);
        r.build = fieldsOf(j.value("build", nlohmann::json::object()));
        r.gl = fieldsOf(j.value("gl", nlohmann::json::object()));
        r.host = fieldsOf(j.value("host", nlohmann::json::object()));
        const auto& results = j.at("results");
        if (r.command == "bench") {
            const auto& g = j.at("grid");
            RecordedBench b;
            b.merged = g.value("merged", false);
            BenchOptions& o = b.options;
            o.run.scene = r.sceneSpec;
            for (const auto& [k, v] : r.knobs) o.run.sets.push_back(k + "=" + v);
            o.frames = r.frames;
            o.warmup = r.warmup;
            o.seed = static_cast<std::uint32_t>(std::stoul(fieldOr(r.seeds, "lights", "1")));
            if (!b.merged) {
                for (const auto& s : g.at("sizes")) o.grid.sizes.push_back(sizeField(s.get<std::string>(), path, "grid.sizes"));
                for (const auto& n : g.at("lights"))
                    o.grid.lights.push_back(wholeNumber(n, path, "grid.lights", limits::kBenchLights, "--lights"));
                for (const auto& a : g.at("sweep"))
                    o.grid.knobAxes.push_back({a.at("knob").get<std::string>(), a.at("values").get<std::vector<std::string>>()});
                if (g.contains("block")) o.block = wholeNumber(g["block"], path, "grid.block", limits::kBlock, "--block");
                o.lightRadius = g.value("light_radius", 0.0f);
                o.keepSceneLights = g.value("keep_scene_lights", false);
                // 0: no orbit (the option is absent).
                if (g.contains("orbit") && g["orbit"] != 0)
                    o.orbit = wholeNumber(g["orbit"], path, "grid.orbit", limits::kOrbit, "--orbit");
                o.walkthrough = g.value("walkthrough", false);
                o.lpp = g.value("lpp", true);
                if (g.contains("lpp_poses"))
                    o.lppPoses = wholeNumber(g["lpp_poses"], path, "grid.lpp_poses", limits::kLppPoses, "--lpp-poses");
                o.shard = BenchShard::parse(g.value("shard", std::string("0/1")));
                o.baseline = g.value("baseline", std::string());
                b.ratioOf = g.value("ratio_of", std::string("frame"));
                if (g.contains("resamples"))
                    b.resamples = wholeNumber(g["resamples"], path, "grid.resamples", limits::kResamples, "--resamples");
            }
            r.bench = std::move(b);
            r.benchResults = Json(results);
        } else if (r.command == "tradeoff") {
            const auto& g = j.at("grid");
            RecordedTradeoff t;
            t.merged = g.value("merged", false);
            TradeoffOptions& o = t.options;
            o.run.scene = r.sceneSpec;
            o.run.width = r.width;
            o.run.height = r.height;
            for (const auto& [k, v] : r.knobs) o.run.sets.push_back(k + "=" + v);
            o.frames = r.frames;
            o.warmup = r.warmup;
            if (!t.merged) {
                for (const auto& a : g.at("axes"))
                    o.sweep.axes.push_back({a.at("name").get<std::string>(), a.at("values").get<std::vector<std::string>>()});
                o.sweep.oneAtATime = g.value("one_at_a_time", false);
                o.sweep.centre = g.value("centre", std::vector<std::string>{});
                t.exclude = g.value("exclude", std::vector<std::string>{});
                for (const auto& e : t.exclude) o.sweep.exclusion.add(e);
                o.against = g.value("against", std::vector<std::string>{});
                o.metric = g.at("metric").get<std::string>();
                o.buffer = g.at("buffer").get<std::string>();
                if (g.contains("ao_rays")) t.aoRays = wholeNumber(g["ao_rays"], path, "grid.ao_rays", limits::kAoRays, "--ao-rays");
                if (g.contains("orbit") && g["orbit"] != 0)
                    o.orbit = wholeNumber(g["orbit"], path, "grid.orbit", limits::kOrbit, "--orbit");
                o.walkthrough = g.value("walkthrough", false);
                if (g.contains("block")) o.block = wholeNumber(g["block"], path, "grid.block", limits::kBlock, "--block");
                if (g.contains("resamples"))
                    o.resamples = wholeNumber(g["resamples"], path, "grid.resamples", limits::kResamples, "--resamples");
                t.runPreset = g.value("run_preset", std::string());
                // Records before repeated --preset hold the one preset only.
                t.runPresets = g.value("run_presets", std::vector<std::string>{});
                if (t.runPresets.empty() && !t.runPreset.empty()) t.runPresets = {t.runPreset};
                t.runSets = g.value("run_sets", std::vector<std::string>{});
                o.shard = BenchShard::parse(g.value("shard", std::string("0/1")));
            }
            r.tradeoff = std::move(t);
            r.tradeoffResults = Json(results);
            r.tradeoffTable(path);  // the rows are checked here, not when they are needed
        } else {
            r.buffer = j.at("buffer").get<std::string>();
            for (const auto& s : results.value("timings", nlohmann::json::array()))
                r.timings.push_back({s.at("name").get<std::string>(), s.at("gpu_ms").get<std::vector<double>>(),
                                     s.at("cpu_ms").get<std::vector<double>>()});
            const auto& image = results.at("image");
            r.imageSha256 = image.at("sha256").get<std::string>();
            r.imageWidth = image.value("width", 0);
            r.imageHeight = image.value("height", 0);
            r.imageChannels = image.value("channels", 0);
            for (const auto& [k, v] : results.value("metrics", nlohmann::json::object()).items())
                if (v.is_number()) r.metrics.emplace_back(k, v.get<double>());
        }
    } catch (const nlohmann::json::exception& e) {
        throw FileError(path, "record version " + std::to_string(r.readVersion) + ": " + jsonErrorText(e));
    } catch (const std::logic_error& e) {  // std::stoi and friends
        throw FileError(path, "record version " + std::to_string(r.readVersion) + ": a number does not parse");
    } catch (const FileError&) {
        throw;
    } catch (const Error& e) {
        throw FileError(path, e.what());
    }
    return r;
}

}  // namespace dw
