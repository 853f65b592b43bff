#include "renderer/record/ExperimentRecord.h"

#include <sys/utsname.h>

#include <algorithm>
#include <charconv>
#include <climits>
#include <limits>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <thread>
#include <tuple>

#include "renderer/Error.h"
#include "renderer/OptionLimits.h"
#include "renderer/metrics/Bootstrap.h"
#include "renderer/bench/BenchSummary.h"
#include "renderer/bench/TradeoffTable.h"
#include "renderer/graph/RenamedOutputs.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"
#include "renderer/record/BuildInfo.h"
#include "renderer/record/HostInfo.h"
#include "renderer/record/SceneFiles.h"
#include "renderer/record/ShaderFiles.h"
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
template <typename J>
int wholeNumber(const J& v, const std::string& path, const std::string& field, OptionRange range,
                const std::string& option) {
    if (!v.is_number_integer())
        throw FileError(path, field + ": expects a whole number (as " + option + " does), got " + v.dump());
    const long long n = v.is_number_unsigned() && v.template get<unsigned long long>() > 9223372036854775807ull
                            ? 9223372036854775807ll
                            : v.template get<long long>();
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


std::string fieldOr(const RecordFields& f, const std::string& key, const std::string& fallback) {
    for (const auto& [k, v] : f)
        if (k == key) return v;
    return fallback;
}

Json vec3(const glm::vec3& v) { return Json::array({v.x, v.y, v.z}); }


// A value of the record with its path in it ("scene.files[2].path"): every
// refusal names the field it is about, whatever is wrong with it (missing,
// of another type, out of range).
template <typename J>
class Field {
public:
    Field(const J& j, std::string where, const std::string& file) : j_(j), where_(std::move(where)), file_(file) {}

    const J& json() const { return j_; }
    const std::string& where() const { return where_; }
    [[noreturn]] void refuse(const std::string& what) const { throw FileError(file_, where_ + ": " + what); }

    bool has(const std::string& key) const { return j_.is_object() && j_.contains(key); }
    Field at(const std::string& key) const {
        object();
        if (!j_.contains(key)) throw FileError(file_, child(key) + ": missing");
        return Field(j_[key], child(key), file_);
    }
    Field at(size_t i) const {
        array();
        if (i >= j_.size()) throw FileError(file_, where_ + "[" + std::to_string(i) + "]: missing");
        return Field(j_[i], where_ + "[" + std::to_string(i) + "]", file_);
    }
    const Field& object() const {
        if (!j_.is_object()) refuse("expects an object, got " + shown());
        return *this;
    }
    const Field& array() const {
        if (!j_.is_array()) refuse("expects an array, got " + shown());
        return *this;
    }
    std::vector<Field> items() const {
        array();
        std::vector<Field> out;
        for (size_t i = 0; i < j_.size(); ++i) out.push_back(at(i));
        return out;
    }
    std::string str() const {
        if (!j_.is_string()) refuse("expects a string, got " + shown());
        return j_.template get<std::string>();
    }
    bool boolean() const {
        if (!j_.is_boolean()) refuse("expects true or false, got " + shown());
        return j_.template get<bool>();
    }
    // A finite number that fits a 32-bit float (what the renderer stores).
    float number32() const {
        if (!j_.is_number()) refuse("expects a number, got " + shown());
        const double v = j_.template get<double>();
        if (!std::isfinite(v) || std::abs(v) > static_cast<double>(std::numeric_limits<float>::max()))
            refuse(shown() + " does not fit a 32-bit float");
        return static_cast<float>(v);
    }
    std::vector<std::string> strings() const {
        std::vector<std::string> out;
        for (const auto& item : items()) out.push_back(item.str());
        return out;
    }
    // The value of `key` when present, else `fallback`.
    std::string str(const std::string& key, const std::string& fallback) const {
        return has(key) ? at(key).str() : fallback;
    }
    bool boolean(const std::string& key, bool fallback) const { return has(key) ? at(key).boolean() : fallback; }
    float number32(const std::string& key, float fallback) const { return has(key) ? at(key).number32() : fallback; }
    std::vector<std::string> strings(const std::string& key) const {
        return has(key) ? at(key).strings() : std::vector<std::string>{};
    }
    // The value as the text it stands for: a string, or a number or true/false as written.
    std::string text() const {
        if (j_.is_string()) return j_.template get<std::string>();
        if (j_.is_number() || j_.is_boolean()) return j_.dump();
        refuse("expects a string, got " + shown());
    }
    // An object of name: text (knobs, seeds, build, gl, host).
    RecordFields fields() const {
        object();
        RecordFields f;
        for (auto it = j_.begin(); it != j_.end(); ++it) f.emplace_back(it.key(), at(it.key()).text());
        return f;
    }
    // A whole number held to the range of the option it stands for.
    int whole(OptionRange range, const std::string& option) const {
        return wholeNumber(j_, file_, where_, range, option);
    }
    std::string shown() const {
        std::string d = j_.dump();
        if (d.size() > 60) d = d.substr(0, 57) + "...";
        return j_.is_null() ? "null" : d;
    }

private:
    std::string child(const std::string& key) const { return where_.empty() ? key : where_ + "." + key; }
    const J& j_;
    std::string where_;
    const std::string& file_;
};

using RecordField = Field<nlohmann::json>;

glm::vec3 readVec3(const RecordField& f) {
    const auto& j = f.json();
    if (!j.is_array() || j.size() != 3) f.refuse("expected [x, y, z], got " + f.shown());
    return {f.at(0).number32(), f.at(1).number32(), f.at(2).number32()};
}

// Per-frame milliseconds: an array of numbers.
std::vector<double> numbers(const RecordField& f) {
    std::vector<double> out;
    for (const auto& item : f.items()) {
        if (!item.json().is_number()) item.refuse("expects a number (milliseconds), got " + item.shown());
        out.push_back(item.json().get<double>());
    }
    return out;
}

// seeds.NAME as a 32-bit unsigned seed (--seed), `1` when absent.
std::uint32_t seedField(const RecordFields& seeds, const std::string& name, const std::string& path) {
    const std::string text = fieldOr(seeds, name, "1");
    std::uint32_t n = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size())
        throw FileError(path, "seeds." + name + ": expects a whole number 0..4294967295 (as --seed takes), got '" + text + "'");
    return n;
}

// The reference's pixel filter (box or tent, as --filter takes it), "box" when absent.
std::string pixelFilterField(const RecordField& object, const std::string& key) {
    const std::string text = object.str(key, "box");
    if (text != "box" && text != "tent") object.at(key).refuse("expects box or tent (as --filter takes it), got '" + text + "'");
    return text;
}

// grid.shard "i/n" as --shard takes it.
BenchShard shardField(const RecordField& grid, const std::string& fallback) {
    const std::string text = grid.str("shard", fallback);
    try {
        return BenchShard::parse(text);
    } catch (const Error& e) {
        grid.at("shard").refuse(e.what());
    }
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

void ExperimentRecord::setReference(int aoRays, std::uint32_t seed, int spp, const std::string& filter) {
    referenceAoRays = aoRays;
    referenceSeed = seed;
    referenceSpp = spp;
    referenceFilter = filter;
    std::erase_if(seeds, [](const auto& f) { return f.first == "reference"; });
    seeds.emplace_back("reference", std::to_string(seed));
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
    r.shaders = shaderFilesOf(session.shaders().compiled());
    r.camera = session.camera();
    r.knobs = knobFields(session.knobs());
    r.seeds.emplace_back("bootstrap", std::to_string(kBootstrapSeed));
    r.width = run.width;
    r.height = run.height;
    r.frames = run.frames;
    r.warmup = run.warmup;
    r.sceneTime = run.sceneTime;
    r.animation = run.animation;
    r.buffer = buffer;
    r.build = buildFields();
    const gl::GlInfo& info = session.glInfo();
    r.gl = {{"vendor", info.vendor}, {"renderer", info.renderer}, {"version", info.version}, {"platform", glPlatform}};
    r.host = hostFields();
    PassTimer& timer = session.pipeline().timer();
    timer.collect(true);
    for (const PassTimer::Series& s : timer.series()) {
        RecordedSeries rs{s.name, {}, {}, {}};
        for (const TimingSample& t : s.samples)
            if (t.frame >= firstCounted) {
                rs.gpuMs.push_back(t.gpuMs);
                rs.cpuMs.push_back(t.cpuMs);
                rs.counts = t.counts;
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
    r.shaders = shaderFilesOf(results.shaders);
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
    r.sceneTime = o.run.sceneTime;
    r.animation = o.run.animation;
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

// A row's tied_with as the CSV writes it: [{"point": 1, "axes": "error"}, ...].
Json tiesJson(const TradeoffRow& r) {
    Json ties = Json::array();
    for (const auto& [point, axes] : r.tiedWith) ties.push_back({{"point", point}, {"axes", axes}});
    return ties;
}

// A row's counters: {"frame": {fragments: ..., ...}, "<pass>": {...}}, the
// measured ones only (replay compares them exactly).
Json tradeoffCountersJson(const TradeoffTable& t, const TradeoffRow& r) {
    auto one = [](const CounterValues& v) {
        Json c = Json::object();
        for (int i = 0; i < PassCounts::kCount; ++i)
            if (!std::isnan(v[static_cast<size_t>(i)])) c[PassCounts::name(i)] = number(v[static_cast<size_t>(i)]);
        return c;
    };
    Json all = {{"frame", one(r.frameCounts)}};
    for (size_t p = 0; p < t.passes.size() && p < r.passCounts.size(); ++p)
        if (Json c = one(r.passCounts[p]); !c.empty()) all[t.passes[p]] = c;
    return all;
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
                        {"pareto", r.pareto}, {"time_ms", number(r.timeMs)},
                        {"time_ms_ci95", {number(r.timeMsLo), number(r.timeMsHi)}}, {"front", r.front},
                        {"dominated_by", r.dominatedBy}, {"tied_with", tiesJson(r)}, {"pick", r.pick},
                        {"gpu_mem_peak_mib", number(r.gpuMemPeakMib)}});
        if (t.counted) rows.back()["counters"] = tradeoffCountersJson(t, r);
        if (r.pareto) front.push_back({{"point", r.point}, {"camera", r.camera}});
        metrics.push_back({{"point", r.point}, {"camera", r.camera}, {"metric", r.metric}, {"buffer", r.buffer},
                           {"against", against}, {"value", number(r.error)},
                           {"ci95", {number(r.errorLo), number(r.errorHi)}}});
    }
    return {{"machine", m}, {"settings", settingsJson(settings)}, {"axes", t.axes}, {"passes", t.passes},
            {"time", t.time}, {"rows", rows}, {"front", front}, {"metrics", metrics}};
}


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
                                               const TradeoffResult& result, const BenchFields& machine) {
    const TradeoffTable& table = result.table;
    const BenchFields& settings = result.settings;
    ExperimentRecord r = forTradeoffTable(table, settings);
    const TradeoffOptions& o = tradeoff.options;
    r.tradeoff = tradeoff;
    r.tradeoff->merged = false;
    r.tradeoffResults = tradeoffResultsJson(table, machine, settings);
    r.sceneSpec = o.run.sceneSpec();
    r.sceneSource = scene.source;
    r.sceneFiles = sceneFilesOf(scene);
    r.shaders = shaderFilesOf(result.shaders);
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
    r.sceneTime = o.run.sceneTime;
    r.animation = o.run.animation;
    r.width = o.run.width;
    r.height = o.run.height;
    r.buffer = o.buffer;
    // Against the CPU reference: the seed of its AO samples, so replay traces the same reference.
    if (o.against.empty()) r.seeds.emplace_back("reference", std::to_string(tradeoff.referenceSeed));
    r.gl = {{"vendor", fieldOfBench(machine, "gl_vendor")},
            {"renderer", fieldOfBench(machine, "gl_renderer")},
            {"version", fieldOfBench(machine, "gl_version")},
            {"platform", fieldOfBench(machine, "gl_platform")}};
    return r;
}

namespace {

// The front's fields of a record's row (issue 34); a record written before them: the frame time, no front.
template <class F, class Optional>
void readFrontFields(const F& row, TradeoffRow& r, const Optional& optional) {
    if (!row.has("time_ms")) {
        r.timeMs = r.frameGpuMs;
        r.timeMsLo = r.frameGpuMsLo;
        r.timeMsHi = r.frameGpuMsHi;
        return;
    }
    r.timeMs = optional(row.at("time_ms"));
    r.timeMsLo = optional(row.at("time_ms_ci95").at(0));
    r.timeMsHi = optional(row.at("time_ms_ci95").at(1));
    if (row.has("front")) r.front = row.at("front").str();
    if (row.has("pick")) r.pick = row.at("pick").str();
    if (row.has("gpu_mem_peak_mib")) r.gpuMemPeakMib = optional(row.at("gpu_mem_peak_mib"));
    if (row.has("dominated_by"))
        for (const F& p : row.at("dominated_by").items())
            r.dominatedBy.push_back(p.whole(OptionRange{0, std::numeric_limits<int>::max()}, "a point's index"));
    if (row.has("tied_with"))
        for (const F& tie : row.at("tied_with").items())
            r.tiedWith.emplace_back(tie.at("point").whole(OptionRange{0, std::numeric_limits<int>::max()}, "a point's index"),
                                    tie.at("axes").str());
}

// tradeoffCountersJson read back into `r` (none: the row was not counted).
template <typename F, typename Optional>
void readTradeoffCounters(const F& row, TradeoffTable& t, TradeoffRow& r, const Optional& optional) {
    CounterValues none;
    none.fill(NAN);
    r.passCounts.assign(t.passes.size(), none);
    if (!row.has("counters")) return;
    t.counted = true;
    const F c = row.at("counters").object();
    auto read = [&](const std::string& span, CounterValues& v) {
        if (!c.has(span)) return;
        const F one = c.at(span).object();
        for (int i = 0; i < PassCounts::kCount; ++i)
            if (one.has(PassCounts::name(i))) v[static_cast<size_t>(i)] = optional(one.at(PassCounts::name(i)));
    };
    read("frame", r.frameCounts);
    for (size_t p = 0; p < t.passes.size(); ++p) read(t.passes[p], r.passCounts[p]);
}
}  // namespace

TradeoffTable ExperimentRecord::tradeoffTable(const std::string& path) const {
    using F = Field<Json>;
    const F res(tradeoffResults, "results", path);
    TradeoffTable t;
    try {
        t.axes = res.at("axes").strings();
        t.passes = res.at("passes").strings();
        if (res.has("time")) t.time = res.at("time").str();
        for (const F& row : res.at("rows").items()) {
            TradeoffRow r;
            r.point = row.at("point").whole(OptionRange{0, std::numeric_limits<int>::max()}, "a point's index");
            for (const auto& a : t.axes) r.axisValues.push_back(row.at("values").at(a).text());
            r.camera = row.at("camera").text();
            r.metric = row.at("metric").str();
            r.buffer = row.at("buffer").str();
            auto optional = [](const F& f) {
                if (f.json().is_null()) return static_cast<double>(NAN);
                if (!f.json().is_number()) f.refuse("expects a number or null, got " + f.shown());
                return f.json().template get<double>();
            };
            r.error = optional(row.at("error"));
            r.errorLo = optional(row.at("error_ci95").at(0));
            r.errorHi = optional(row.at("error_ci95").at(1));
            if (row.has("frames")) r.frames = row.at("frames").whole(OptionRange{0, limits::kFrames.max}, "--frames");
            r.frameGpuMs = optional(row.at("frame_gpu_ms"));
            r.frameGpuMsLo = optional(row.at("frame_gpu_ms_ci95").at(0));
            r.frameGpuMsHi = optional(row.at("frame_gpu_ms_ci95").at(1));
            const F g = row.at("gpu_ms").object();
            for (const auto& p : t.passes) r.passGpuMs.push_back(g.has(p) ? optional(g.at(p)) : NAN);
            r.pareto = row.boolean("pareto", false);
            readFrontFields(row, r, optional);
            readTradeoffCounters(row, t, r, optional);
            t.rows.push_back(std::move(r));
        }
    } catch (const nlohmann::json::exception& e) {
        throw FileError(path, "results: " + jsonErrorText(e));
    }
    return t;
}

namespace {

// bench's grid as a record holds it (readBenchGrid reads it back).
Json benchGridJson(const RecordedBench& bench) {
    if (bench.merged) return {{"merged", true}};
    const BenchOptions& o = bench.options;
    Json sizes = Json::array(), sweep = Json::array();
    for (const auto& [w, h] : o.grid.sizes) sizes.push_back(sizeText(w, h));
    for (const auto& a : o.grid.knobAxes) sweep.push_back({{"knob", a.knob}, {"values", a.values}});
    return {{"sizes", sizes},
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
            {"ratio_of", bench.ratioOf},
            {"resamples", bench.resamples}};
}

// tradeoff's sweep as a record holds it (readTradeoffGrid reads it back).
Json tradeoffGridJson(const RecordedTradeoff& tradeoff) {
    if (tradeoff.merged) return {{"merged", true}};
    const TradeoffOptions& o = tradeoff.options;
    Json axes = Json::array();
    for (const auto& a : o.sweep.axes) axes.push_back({{"name", a.name}, {"values", a.values}});
    Json grid = {{"axes", axes},
            {"one_at_a_time", o.sweep.oneAtATime},
            {"centre", o.sweep.centre},
            {"exclude", tradeoff.exclude},
            {"against", o.against},
            {"metric", o.metric},
            {"buffer", o.buffer},
            {"ao_rays", tradeoff.aoRays},
            {"ref_spp", tradeoff.refSpp},
            {"ref_filter", tradeoff.refFilter},
            {"orbit", o.orbit},
            {"orbit_degrees", o.orbitDegrees},
            {"walkthrough", o.walkthrough},
            {"block", o.block},
            {"resamples", o.resamples},
            {"cost", o.cost},
            {"counters", o.counters},
            {"time", o.time},
            {"budget_ms", o.budgetMs > 0.0 ? Json(o.budgetMs) : Json()},
            {"budget", o.budget > 0.0 ? Json(o.budget) : Json()},
            {"search", tradeoff.search ? Json{{"max_evals", tradeoff.maxEvals}} : Json()},
            {"run_preset", tradeoff.runPreset},
            {"run_presets", tradeoff.runPresets},
            {"run_sets", tradeoff.runSets},
            {"shard", std::to_string(o.shard.index) + "/" + std::to_string(o.shard.count)}};
    // What the front used besides time and budget, so replay uses it too (records before it: no mask).
    grid["mask"] = o.mask;
    // tradeoff --study: the points one by one, each its value positions on the axes.
    if (!o.sweep.listed.empty()) grid["points"] = o.sweep.listed;
    return grid;
}

// The listed points of a --study record's grid, each checked against the axes.
std::vector<std::vector<size_t>> listedPoints(const RecordField& g, const TradeoffSweep& sweep) {
    std::vector<std::vector<size_t>> listed;
    if (!g.has("points")) return listed;
    for (const RecordField& p : g.at("points").items()) {
        std::vector<size_t> at;
        for (const RecordField& v : p.items()) {
            if (at.size() >= sweep.axes.size()) p.refuse("more positions than the grid's axes");
            const TradeoffAxis& axis = sweep.axes[at.size()];
            const int most = std::max(0, static_cast<int>(axis.values.size()) - 1);
            at.push_back(static_cast<size_t>(v.whole(OptionRange{0, most}, "a value's position on " + axis.name)));
        }
        if (at.size() != sweep.axes.size()) p.refuse("expected a position per axis");
        listed.push_back(std::move(at));
    }
    if (listed.empty()) g.at("points").refuse("no points");
    return listed;
}

// What the front and the pick used: --time (records before it kept it only
// in the results), --mask (before: in the rows' buffer); the budget is read beside --search.
void readFrontInputs(const RecordField& g, const RecordField& results, TradeoffOptions& o) {
    if (g.has("time")) o.time = g.at("time").str();
    else if (results.has("time")) o.time = results.at("time").str();
    if (g.has("mask")) {
        o.mask = g.at("mask").str();
    } else if (results.has("rows") && !results.at("rows").items().empty()) {
        const std::string buffer = results.at("rows").items().front().at("buffer").str();
        const std::string edges = ":shadow_edges";
        if (buffer.size() > edges.size() && buffer.compare(buffer.size() - edges.size(), edges.size(), edges) == 0)
            o.mask = "shadow_edges";
    }
}

}  // namespace

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
    if (shaders.present) {
        Json shaderFiles = Json::array();
        for (const auto& f : shaders.files) shaderFiles.push_back({{"path", f.path}, {"sha256", f.sha256}});
        j["shaders"] = {{"folder", shaders.folder}, {"files", shaderFiles}};
    }
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
    j["scene_time"] = sceneTime;
    if (!animation.empty()) j["animation"] = animation;
    if (command != "bench" && command != "tradeoff") j["buffer"] = buffer;
    if (referenceAoRays) j["reference"] = {{"ao_rays", *referenceAoRays}, {"spp", referenceSpp}, {"filter", referenceFilter}};
    if (bench) j["grid"] = benchGridJson(*bench);
    if (tradeoff) j["grid"] = tradeoffGridJson(*tradeoff);
    j["build"] = fieldsJson(build);
    j["gl"] = fieldsJson(gl);
    j["host"] = fieldsJson(host);
    if (command == "bench") {
        j["results"] = benchResults.is_null() ? Json::object() : benchResults;
    } else if (command == "tradeoff") {
        j["results"] = tradeoffResults.is_null() ? Json::object() : tradeoffResults;
    } else {
        Json series = Json::array();
        for (const auto& s : timings) {
            series.push_back({{"name", s.name}, {"gpu_ms", s.gpuMs}, {"cpu_ms", s.cpuMs}, {"gpu", intervalJson(s.gpuMs)},
                              {"cpu", intervalJson(s.cpuMs)}});
            if (!s.counts.measured()) continue;
            Json c = Json::object();
            for (int i = 0; i < PassCounts::kCount; ++i)
                if (s.counts[i] >= 0) c[PassCounts::name(i)] = s.counts[i];
            series.back()["counters"] = c;
        }
        Json m = Json::object();
        for (const auto& [k, v] : metrics) m[k] = number(v);
        j["results"] = {{"timings", series},
                        {"image", {{"buffer", buffer}, {"sha256", imageSha256}, {"width", imageWidth},
                                   {"height", imageHeight}, {"channels", imageChannels}}},
                        {"metrics", m}};
    }
    const auto [inputsSha, resultsSha] = contentSha256(nlohmann::json(j));  // the same values, unordered, as a reader parses them
    j["record_sha256"] = {{"inputs", inputsSha}, {"results", resultsSha}};
    return j.dump(2) + "\n";
}

std::pair<std::string, std::string> ExperimentRecord::contentSha256(const nlohmann::json& record) {
    nlohmann::json inputs = record;
    const std::string results = record.is_object() && record.contains("results") ? record["results"].dump() : "null";
    if (inputs.is_object()) {
        inputs.erase("results");
        inputs.erase("record_sha256");
    }
    const std::string text = inputs.dump();
    return {sha256Hex(text.data(), text.size()), sha256Hex(results.data(), results.size())};
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


namespace {

// A bench record's grid (what replay runs again) and results.
void readBenchGrid(ExperimentRecord& r, const RecordField& root, const RecordField& results, const std::string& path) {
    using F = RecordField;
    const F g = root.at("grid").object();
    RecordedBench b;
    b.merged = g.boolean("merged", false);
    BenchOptions& o = b.options;
    o.run.scene = r.sceneSpec;
    for (const auto& [k, value] : r.knobs) o.run.sets.push_back(k + "=" + value);
    o.frames = r.frames;
    o.warmup = r.warmup;
    o.run.sceneTime = r.sceneTime;
    o.run.animation = r.animation;
    o.seed = seedField(r.seeds, "lights", path);
    if (!b.merged) {
        for (const F& s : g.at("sizes").items()) o.grid.sizes.push_back(sizeField(s.str(), path, s.where()));
        for (const F& n : g.at("lights").items()) o.grid.lights.push_back(n.whole(limits::kBenchLights, "--lights"));
        for (const F& a : g.at("sweep").items()) o.grid.knobAxes.push_back({a.at("knob").str(), a.at("values").strings()});
        if (g.has("block")) o.block = g.at("block").whole(limits::kBlock, "--block");
        o.lightRadius = g.number32("light_radius", 0.0f);
        o.keepSceneLights = g.boolean("keep_scene_lights", false);
        // 0: no orbit (the option is absent).
        if (g.has("orbit") && g.at("orbit").json() != 0) o.orbit = g.at("orbit").whole(limits::kOrbit, "--orbit");
        o.walkthrough = g.boolean("walkthrough", false);
        o.lpp = g.boolean("lpp", true);
        if (g.has("lpp_poses")) o.lppPoses = g.at("lpp_poses").whole(limits::kLppPoses, "--lpp-poses");
        o.shard = shardField(g, "0/1");
        o.baseline = g.str("baseline", "");
        b.ratioOf = g.str("ratio_of", "frame");
        if (g.has("resamples")) b.resamples = g.at("resamples").whole(limits::kResamples, "--resamples");
    }
    r.bench = std::move(b);
    r.benchResults = Json(results.json());
}

// A tradeoff record's sweep (what replay runs again) and its rows, checked here.
void readTradeoffGrid(ExperimentRecord& r, const RecordField& root, const RecordField& results, const std::string& path) {
    using F = RecordField;
    const F g = root.at("grid").object();
    RecordedTradeoff t;
    t.merged = g.boolean("merged", false);
    TradeoffOptions& o = t.options;
    o.run.scene = r.sceneSpec;
    o.run.width = r.width;
    o.run.height = r.height;
    for (const auto& [k, value] : r.knobs) o.run.sets.push_back(k + "=" + value);
    o.frames = r.frames;
    o.warmup = r.warmup;
    o.run.sceneTime = r.sceneTime;
    o.run.animation = r.animation;
    if (!t.merged) {
        for (const F& a : g.at("axes").items()) o.sweep.axes.push_back({a.at("name").str(), a.at("values").strings()});
        o.sweep.oneAtATime = g.boolean("one_at_a_time", false);
        o.sweep.centre = g.strings("centre");
        o.sweep.listed = listedPoints(g, o.sweep);
        t.exclude = g.strings("exclude");
        for (size_t i = 0; i < t.exclude.size(); ++i) {
            try {
                o.sweep.exclusion.add(t.exclude[i]);
            } catch (const Error& e) {
                g.at("exclude").at(i).refuse(e.what());
            }
        }
        o.against = g.strings("against");
        o.metric = g.at("metric").str();
        o.buffer = g.at("buffer").str();
        o.cost = g.has("cost") ? g.at("cost").str() : "gpu_ms";
        readFrontInputs(g, results, o);
        o.counters = g.boolean("counters", true);
        // Records before these were kept: no budget (null: none), no search.
        auto budgetOf = [&](const char* key, RealRange range, const char* flag) {
            if (!g.has(key) || g.at(key).json().is_null()) return 0.0;
            const double v = g.at(key).json().is_number() ? g.at(key).json().get<double>() : NAN;
            if (!range.holds(v)) g.at(key).refuse(std::string("expects ") + flag + "'s value (above 0), got " + g.at(key).shown());
            return v;
        };
        o.budgetMs = budgetOf("budget_ms", limits::kBudgetMs, "--budget-ms");
        o.budget = budgetOf("budget", limits::kBudget, "--budget");
        if (g.has("search") && !g.at("search").json().is_null()) {
            t.search = true;
            t.maxEvals = g.at("search").object().at("max_evals").whole(limits::kMaxEvals, "--max-evals");
        }
        if (g.has("ao_rays")) t.aoRays = g.at("ao_rays").whole(limits::kAoRays, "--ao-rays");
        // Records before --ref-spp traced the pixel's centre: 1 sample, box.
        if (g.has("ref_spp")) t.refSpp = g.at("ref_spp").whole(limits::kPixelSamples, "--ref-spp");
        t.refFilter = pixelFilterField(g, "ref_filter");
        if (g.has("orbit") && g.at("orbit").json() != 0) o.orbit = g.at("orbit").whole(limits::kOrbit, "--orbit");
        // Records before --orbit-degrees: a whole turn.
        if (g.has("orbit_degrees")) {
            const Json& v = g.at("orbit_degrees").json();
            o.orbitDegrees = v.is_number() ? v.get<double>() : NAN;
            if (!limits::kOrbitDegrees.holds(o.orbitDegrees))
                g.at("orbit_degrees").refuse("expects --orbit-degrees' value (above 0, at most 360), got " +
                                             g.at("orbit_degrees").shown());
        }
        o.walkthrough = g.boolean("walkthrough", false);
        if (g.has("block")) o.block = g.at("block").whole(limits::kBlock, "--block");
        if (g.has("resamples")) o.resamples = g.at("resamples").whole(limits::kResamples, "--resamples");
        t.runPreset = g.str("run_preset", "");
        // Records before repeated --preset hold the one preset only.
        t.runPresets = g.strings("run_presets");
        if (t.runPresets.empty() && !t.runPreset.empty()) t.runPresets = {t.runPreset};
        t.runSets = g.strings("run_sets");
        o.shard = shardField(g, "0/1");
    }
    // The CPU reference's AO sample seed; records before it was kept ran with 1.
    t.referenceSeed = seedField(r.seeds, "reference", path);
    r.tradeoff = std::move(t);
    r.tradeoffResults = Json(results.json());
    r.tradeoffTable(path);  // the rows are checked here, not when they are needed
}

// A render or window record's buffer, the reference it traced, timings and image.
void readRenderResults(ExperimentRecord& r, const RecordField& root, const RecordField& results, const std::string& path) {
    using F = RecordField;
    r.buffer = root.at("buffer").str();
    if (root.has("reference")) {
        const RecordField ref = root.at("reference").object();
        r.referenceAoRays = ref.at("ao_rays").whole(limits::kAoRays, "--ao-rays");
        // Records before --spp was kept traced the pixel's centre: 1 sample, box.
        if (ref.has("spp")) r.referenceSpp = ref.at("spp").whole(limits::kPixelSamples, "--spp");
        r.referenceFilter = pixelFilterField(ref, "filter");
        r.referenceSeed = seedField(r.seeds, "reference", path);
        if (r.referenceSeed > static_cast<std::uint32_t>(limits::kSeed.max))
            throw FileError(path, "seeds.reference: " + std::to_string(r.referenceSeed) + " is outside --seed's range " +
                                      std::to_string(limits::kSeed.min) + ".." + std::to_string(limits::kSeed.max));
    }
    if (results.has("timings"))
        for (const F& s : results.at("timings").items())
        {
            r.timings.push_back({s.at("name").str(), numbers(s.at("gpu_ms")), numbers(s.at("cpu_ms")), {}});
            if (!s.has("counters")) continue;
            const F c = s.at("counters").object();
            for (int i = 0; i < PassCounts::kCount; ++i) {
                if (!c.has(PassCounts::name(i))) continue;
                const F v = c.at(PassCounts::name(i));
                if (!v.json().is_number_integer() || v.json().get<long long>() < 0)
                    v.refuse("expects a count (a whole number, at least 0), got " + v.shown());
                r.timings.back().counts.v[static_cast<size_t>(i)] = v.json().get<long long>();
            }
        }
    const F image = results.at("image").object();
    r.imageSha256 = image.at("sha256").str();
    // 0: no image was written.
    const OptionRange side{0, limits::kSize.max};
    if (image.has("width")) r.imageWidth = image.at("width").whole(side, "--size");
    if (image.has("height")) r.imageHeight = image.at("height").whole(side, "--size");
    if (image.has("channels")) r.imageChannels = image.at("channels").whole(OptionRange{0, 4}, "a buffer's channels");
    if (results.has("metrics"))
        for (const auto& [k, m] : results.at("metrics").object().json().items())
            if (m.is_number()) r.metrics.emplace_back(k, m.get<double>());
}

// The record's format version, refused when this build cannot read it.
int recordVersion(const nlohmann::json& j, const RecordField& root, const std::string& path) {
    constexpr int kVersion = ExperimentRecord::kVersion;
    const nlohmann::json& v = j["version"];
    const std::string newer = " is newer than this build reads (" + std::to_string(kVersion) +
                              "); replay it with a newer deferred-workbench";
    if (v.is_number_integer()) {
        if (v.is_number_unsigned() ? v.get<unsigned long long>() > static_cast<unsigned long long>(kVersion)
                                   : v.get<long long>() > kVersion)
            throw FileError(path, "version: record version " + v.dump() + newer);
        if (v.get<long long>() < 1) throw FileError(path, "version: record version " + v.dump() + " does not exist");
    } else if (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>() && v.get<double>() > kVersion) {
        // 2**70: beyond 64-bit whole numbers, JSON numbers parse as floating point.
        throw FileError(path, "version: record version " + v.dump() + newer + " (it is beyond any 64-bit whole number)");
    } else {
        throw FileError(path, "version: expects a whole number (1.." + std::to_string(kVersion) + "), got " +
                                  root.at("version").shown());
    }
    return static_cast<int>(v.get<long long>());
}

// The record's own sha256s against its fields as read.
ExperimentRecord::SelfCheck readSelfCheck(const nlohmann::json& j, const RecordField& root) {
    ExperimentRecord::SelfCheck c;
    if (!root.has("record_sha256")) return c;
    const RecordField written = root.at("record_sha256").object();
    c.hashed = true;
    c.writtenInputs = written.at("inputs").str();
    c.writtenResults = written.at("results").str();
    std::tie(c.nowInputs, c.nowResults) = ExperimentRecord::contentSha256(j);
    c.inputsEdited = c.nowInputs != c.writtenInputs;
    c.resultsEdited = c.nowResults != c.writtenResults;
    return c;
}

}  // namespace

ExperimentRecord ExperimentRecord::fromJson(const nlohmann::json& j, const std::string& path) {
    using F = Field<nlohmann::json>;
    const F root(j, "", path);
    if (!j.is_object())
        throw FileError(path, std::string("not a deferred-workbench record (expects an object with \"format\": \"") +
                                  kFormat + "\", got " + root.shown() + ")");
    if (!j.contains("format") || j["format"] != kFormat)
        throw FileError(path, std::string("format: not a deferred-workbench record (expects \"") + kFormat + "\", got " +
                                  (j.contains("format") ? root.at("format").shown() : std::string("none")) + ")");
    if (!j.contains("version")) throw FileError(path, "version: missing (every record says its format version)");
    ExperimentRecord r;
    r.readVersion = recordVersion(j, root, path);
    r.selfCheck = readSelfCheck(j, root);
    try {
        r.command = root.at("command").str();
        if (r.command != "render" && r.command != "bench" && r.command != "tradeoff" && r.command != "gui")
            throw FileError(path, "command: unknown command '" + r.command + "' (render, bench, tradeoff or gui)");
        if (r.readVersion == 1 && r.command != "render")
            throw FileError(path, "command: a version 1 record is of render only, this one says '" + r.command + "'");
        const F scene = root.at("scene").object();
        r.sceneSpec = scene.at("spec").str();
        r.sceneSource = scene.str("source", "");
        if (scene.has("files"))
            for (const F& f : scene.at("files").items())
                r.sceneFiles.push_back({f.at("path").str(), f.at("sha256").str()});
        // Relative paths: against the record's folder (then the working directory).
        const fs::path recordDir = fs::path(path).parent_path();
        r.sceneSpec = resolvedFromRecord(r.sceneSpec, recordDir);
        r.sceneSource = resolvedFromRecord(r.sceneSource, recordDir);
        for (auto& f : r.sceneFiles) f.path = resolvedFromRecord(f.path, recordDir);
        // Version 2 records written before shader hashes have none: replay says so.
        if (root.has("shaders")) {
            const F shaders = root.at("shaders").object();
            r.shaders.present = true;
            r.shaders.folder = shaders.at("folder").str();
            for (const F& f : shaders.at("files").items()) r.shaders.files.push_back({f.at("path").str(), f.at("sha256").str()});
        }
        const F cam = root.at("camera").object();
        r.camera.position = readVec3(cam.at("position"));
        r.camera.target = readVec3(cam.at("target"));
        r.camera.up = readVec3(cam.at("up"));
        r.camera.fovYDegrees = cam.at("fov_y_degrees").number32();
        r.camera.nearPlane = cam.at("near").number32();
        r.camera.farPlane = cam.at("far").number32();
        // Version 1 had a fixed camera and no seeds (render used none).
        if (root.has("camera_path")) {
            const F p = root.at("camera_path").object();
            r.cameraPath.mode = p.at("mode").str();
            if (r.cameraPath.mode != "fixed" && r.cameraPath.mode != "orbit" && r.cameraPath.mode != "walkthrough")
                p.at("mode").refuse("expects fixed, orbit or walkthrough, got '" + r.cameraPath.mode + "'");
            if (p.has("orbit_poses") && p.at("orbit_poses").json() != 0)
                r.cameraPath.orbitPoses = p.at("orbit_poses").whole(limits::kOrbit, "--orbit");
            if (p.has("keyframes"))
                for (const F& k : p.at("keyframes").items())
                    r.cameraPath.keyframes.push_back(
                        {k.at("time").number32(), readVec3(k.at("position")), readVec3(k.at("target"))});
        }
        r.knobs = root.at("knobs").fields();
        if (root.has("seeds")) r.seeds = root.at("seeds").fields();
        // Held to the ranges of --size, --frames and --warmup; a merge's
        // record (no run of its own: grid.merged) may hold 0 where its
        // shards' JSONs said nothing, and replay names it as a merge's.
        const bool merged = root.has("grid") && root.json()["grid"].is_object() &&
                            root.json()["grid"].value("merged", false) == true;
        auto orZero = [&](OptionRange range) { return merged ? OptionRange{0, range.max} : range; };
        const F size = root.at("size");
        if (!size.json().is_array() || size.json().size() != 2) size.refuse("expected [width, height], got " + size.shown());
        r.width = wholeNumber(size.json()[0], path, "size width", orZero(limits::kSize), "--size");
        r.height = wholeNumber(size.json()[1], path, "size height", orZero(limits::kSize), "--size");
        r.frames = root.at("frames").whole(orZero(limits::kFrames), "--frames");
        r.warmup = root.at("warmup").whole(limits::kWarmup, "--warmup");
        if (root.has("scene_time")) {
            const F t = root.at("scene_time");
            r.sceneTime = t.number32();
            if (!limits::kSceneTime.holds(r.sceneTime))
                t.refuse(t.shown() + " is outside --scene-time's range 0..1000000 (seconds)");
        }
        if (root.has("animation")) {
            const F a = root.at("animation");
            if (!a.json().is_string() || a.json().get<std::string>().empty())
                a.refuse("expected a clip's name or index, or \"none\" (--animation), got " + a.shown());
            r.animation = a.json().get<std::string>();
        }
        // The one definition of a usable camera (a zero up vector renders nothing useful).
        if (const auto problem = findCameraProblem(r.camera, 0.0f))
            throw FileError(path, recordCameraField(problem->field) + ": " + problem->what);
        if (root.has("build")) r.build = root.at("build").fields();
        if (root.has("gl")) r.gl = root.at("gl").fields();
        if (root.has("host")) r.host = root.at("host").fields();
        const F results = root.at("results").object();
        if (r.command == "bench")
            readBenchGrid(r, root, results, path);
        else if (r.command == "tradeoff")
            readTradeoffGrid(r, root, results, path);
        else
            readRenderResults(r, root, results, path);
    } catch (const nlohmann::json::exception& e) {
        throw FileError(path, "record version " + std::to_string(r.readVersion) + ": " + jsonErrorText(e));
    } catch (const FileError&) {
        throw;
    } catch (const Error& e) {
        throw FileError(path, e.what());
    }
    return r;
}

std::string benchJson(const BenchResults& results, const BenchSummary& summary) {
    return ExperimentRecord::forBenchResults(results, summary).json();
}

void writeBenchJson(const std::string& path, const BenchResults& results, const BenchSummary& summary) {
    writeBenchFile(path, benchJson(results, summary), "bench JSON");
}

}  // namespace dw
