#include "renderer/bench/TradeoffRunner.h"

#include "renderer/gl/CounterQuery.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <tuple>

#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/ao/AovCostEstimate.h"
#include "renderer/metrics/Bootstrap.h"
#include "renderer/bench/BudgetPick.h"
#include "renderer/bench/ConfigurationRunner.h"
#include "renderer/bench/ImageError.h"
#include "renderer/bench/TradeoffEvidence.h"
#include "renderer/metrics/ShadowEdgeMask.h"
#include "renderer/passes/AaMethod.h"
#include "renderer/passes/TaaPass.h"
#include "renderer/graph/Pipeline.h"
#include "renderer/knobs/KnobAssignment.h"
#include "renderer/scene/CameraPath.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

// The series a tradeoff table has a gpu_ms.<series> column for: every pass,
// and the span PASS/shadow maps, where the shadow maps are drawn with
// shadows.reuse_map on (the shadows pass itself then draws none; with it off
// the maps are the shadows pass's own span, the same time as the pass).
bool tabledSeries(const std::string& series) {
    static const std::string kMaps = "/shadow maps";
    const auto slash = series.find('/');
    return slash == std::string::npos ||
           (series.compare(slash, std::string::npos, kMaps) == 0 && series.rfind("shadows/", 0) != 0);
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) { return std::chrono::duration<double>(Clock::now() - since).count(); }

// A clip plane's value: a positive, finite number.
float planeValue(const std::string& axis, const std::string& text) {
    char* end = nullptr;
    const float v = std::strtof(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v) || !(v > 0.0f))
        throw Error("--sweep " + axis + ": expected a distance above 0, got '" + text + "'");
    return v;
}

std::string shortText(double v) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", v);
    return text;
}

}  // namespace

std::string TradeoffRunner::gpuOutput(const std::string& buffer) {
    if (buffer == "final" || buffer == "lbuffer") return buffer;
    // The AO the lighting pass reads, whichever ao.method wrote it (the one
    // place that says which output `--buffer ao` means).
    if (buffer == "ao") return "ao.filtered";
    if (buffer == "shadow") return "lighting.shadow";
    throw Error("--buffer: expected final, lbuffer, ao or shadow, got '" + buffer + "'");
}

TradeoffRunner::TradeoffRunner(TradeoffOptions options) : o_(std::move(options)) {
    checkOptions();
    const KnobRegistry declared = RunConfig::declaredKnobs();
    readAxes(declared);
    readAgainst(declared);
    sweepSize_ = o_.sweep.count();
    for (auto& p : o_.sweep.points())
        if (o_.shard.takes(p.index)) points_.push_back(std::move(p));
    scene_ = loadScene(o_.run.sceneSpec());
    placeCameras();
    planPointRuns();
}

// What needs neither the scene nor the knobs.
void TradeoffRunner::checkOptions() const {
    if (o_.frames < 1) throw Error("tradeoff needs at least one counted frame per point and camera");
    if (o_.orbit > 0 && o_.walkthrough) throw Error("--orbit and --walkthrough are two camera paths; pick one");
    if (o_.orbitDegrees != 360.0 && o_.orbit == 0) throw Error("--orbit-degrees is the arc of --orbit N's cameras; give --orbit");
    gpuOutput(o_.buffer);
    if (!o_.mask.empty() && o_.mask != "shadow_edges")
        throw Error("--mask: expected shadow_edges, got '" + o_.mask + "'");
    if (o_.time.empty()) throw Error("--time: expected frame or a pass's name");
    TradeoffTable::timeTerms(o_.time);  // an empty term, a term twice, frame in a sum
    if (o_.budgetMs != 0.0) BudgetPicker::check(o_.budgetMs);
    if (o_.budget != 0.0) BudgetPicker::check(o_.budget, "--budget");
    if (o_.budgetMs != 0.0 && o_.budget != 0.0) throw Error("--budget-ms and --budget: give one");
    if (o_.budget != 0.0 && o_.cost == "gpu_ms") throw Error("--budget bounds a counter: give --cost with a counter");
    if (!TradeoffTable::isCost(o_.cost))
        throw Error("--cost: expected one of " + TradeoffTable::costNames() + ", got '" + o_.cost + "'");
    const auto& metrics = ImageError::metrics();
    if (std::find(metrics.begin(), metrics.end(), o_.metric) == metrics.end() && o_.metric != "temporal")
        throw Error("--metric: expected flip, rms, psnr, ssim or temporal, got '" + o_.metric + "'");
    if (o_.metric == "temporal" && o_.orbit < 2 && !o_.walkthrough)
        throw Error("--metric temporal measures the change from frame to frame along a camera path: give --orbit N "
                    "(N >= 2) or --walkthrough (a camera.path of 2 or more keyframes)");
    if (o_.metric == "temporal" && !o_.mask.empty())
        throw Error("--mask applies to an image's error, not to --metric temporal");
    o_.run.validate();
}

// Each axis' values checked once and kept as written (TradeoffAxis::values)
// and as applied (TradeoffAxis::numbers): a knob (its old name sweeps the
// knob it became, with --set's warning, and names the column), the presets,
// or a clip plane; then --exclude's values read the same way.
void TradeoffRunner::readAxes(const KnobRegistry& declared) {
    for (size_t a = 0; a < o_.sweep.axes.size(); ++a) {
        TradeoffAxis& axis = o_.sweep.axes[a];
        if (TradeoffSweep::isKnobAxis(axis.name)) axis.name = declared.canonicalName(axis.name);
        for (size_t b = 0; b < a; ++b)
            if (o_.sweep.axes[b].name == axis.name) throw Error("--sweep " + axis.name + " is given twice");
        if (TradeoffSweep::isKnobAxis(axis.name) && !declared.find(axis.name))
            throw Error("--sweep: unknown knob '" + axis.name + "' (see: list knobs; axes that are not knobs: "
                        "preset, camera.near, camera.far)");
        axis.numbers.clear();
        for (size_t i = 0; i < axis.values.size(); ++i) {
            std::string& v = axis.values[i];
            const std::string given = v;
            readAxisValue(declared, axis, v);
            for (size_t j = 0; j < i; ++j)
                if (axis.values[j] == v)
                    throw Error("--sweep " + axis.name + ": '" + given + "' is '" + v + "', which is given before");
        }
    }
    GridExclusion::Axes axes;
    for (const auto& a : o_.sweep.axes) axes.emplace_back(a.name, a.values);
    o_.sweep.exclusion.resolve(axes, [&](const std::string& axis, const std::string& value) {
        if (axis == "preset" || TradeoffSweep::isStudyAxis(axis)) return value;
        if (TradeoffSweep::isCameraAxis(axis)) return shortText(planeValue(axis, value));
        return readKnobAssignment(declared, axis, value).text;
    });
}

// One value of `axis`: `text` becomes the text the CSV writes, and its
// number (the knob's value, the plane's distance) joins the axis' numbers.
void TradeoffRunner::readAxisValue(const KnobRegistry& declared, TradeoffAxis& axis, std::string& text) {
    if (TradeoffSweep::isStudyAxis(axis.name)) {
        if (text.empty()) throw Error("a study's name is empty");
    } else if (axis.name == "preset") {
        RunConfig probe;
        probe.setPreset(text);  // Error naming the built-in presets, or FileError
    } else if (TradeoffSweep::isCameraAxis(axis.name)) {
        text = shortText(planeValue(axis.name, text));
        axis.numbers.push_back(planeValue(axis.name, text));  // the distance the written text says
    } else {
        const KnobAssignment read = readKnobAssignment(declared, axis.name, text);
        text = read.text;
        axis.numbers.push_back(read.value);
    }
}

// --against's knob values, read once (a bad value fails here) and applied as read.
void TradeoffRunner::readAgainst(const KnobRegistry& declared) {
    for (const auto& s : o_.against) {
        const size_t eq = s.find('=');
        if (eq == std::string::npos || !declared.find(s.substr(0, eq)))
            throw Error("--against: expected 'reference' or knob=value[,knob=value...] of known knobs, got '" + s + "'");
        against_.push_back(readKnobAssignment(declared, s.substr(0, eq), s.substr(eq + 1)));
    }
}

// The run's camera; --orbit N poses about it; or the camera.path keyframes.
void TradeoffRunner::placeCameras() {
    if (o_.walkthrough && scene_.cameraPath.size() < 2)
        throw Error("--walkthrough: the scene '" + scene_.name + "' has no camera.path (docs/scene-format.md)");
    const Camera base = o_.run.camera(scene_);
    if (o_.walkthrough) {
        const CameraPath path = CameraPath::keyframes(base, scene_.cameraPath);
        for (const auto& k : scene_.cameraPath) cameras_.push_back(path.atTime(k.time));
    } else if (o_.orbit > 0) {
        const CameraPath path = CameraPath::orbit(base, o_.orbit, o_.orbitDegrees);
        for (int k = 0; k < o_.orbit; ++k) cameras_.push_back(path.at(k, o_.orbit));
    } else {
        cameras_.push_back(base);
    }
}

// Each point's run: the run's own, with the point's preset after the run's
// --preset ones (its knobs over theirs, under --set); its clip planes must
// keep near < far.
void TradeoffRunner::planPointRuns() {
    const Camera base = o_.run.camera(scene_);
    for (size_t p = 0; p < points_.size(); ++p) {
        RunConfig run = o_.run;
        for (size_t a = 0; a < o_.sweep.axes.size(); ++a)
            if (o_.sweep.axes[a].name == "preset") run.addPreset(points_[p].values[a]);
        const Camera c = withPlanes(base, p);
        if (!(c.nearPlane < c.farPlane))
            throw Error("point " + std::to_string(points_[p].index) + ": camera.near " + shortText(c.nearPlane) +
                        " is not below camera.far " + shortText(c.farPlane) + " (leave it out with --exclude)");
        pointRuns_.push_back(std::move(run));
    }
}

// `camera` with point `p`'s clip planes.
Camera TradeoffRunner::withPlanes(Camera camera, size_t p) const {
    for (size_t a = 0; a < o_.sweep.axes.size(); ++a) {
        const TradeoffAxis& axis = o_.sweep.axes[a];
        const float distance = TradeoffSweep::isCameraAxis(axis.name)
                                   ? static_cast<float>(axis.numbers[points_[p].at[a]]) : 0.0f;
        if (axis.name == "camera.near") camera.nearPlane = distance;
        if (axis.name == "camera.far") camera.farPlane = distance;
    }
    return camera;
}

// The point's knobs (its run's preset and --set, then its axis values) on the session.
void TradeoffRunner::applyPoint(RenderSession& session, size_t p) const {
    pointRuns_[p].applyKnobs(session.knobs(), session.scene());
    for (size_t a = 0; a < o_.sweep.axes.size(); ++a) {
        const TradeoffAxis& axis = o_.sweep.axes[a];
        if (TradeoffSweep::isKnobAxis(axis.name))
            session.knobs().set(*session.knobs().find(axis.name), axis.numbers[points_[p].at[a]]);
    }
}

// Camera `c` with the point's clip planes.
Camera TradeoffRunner::cameraOf(size_t p, int c) const { return withPlanes(cameras_[static_cast<size_t>(c)], p); }

// Seeded by the point's number, so a shard draws what the whole run draws.
std::uint64_t TradeoffRunner::pointSeed(size_t p, int camera) const {
    return 12345u + 1000u * static_cast<std::uint64_t>(points_[p].index) + 2u * static_cast<std::uint64_t>(camera);
}

std::string TradeoffRunner::describeConfiguration(int i) const {
    const int cameraCount = static_cast<int>(cameras_.size());
    const TradeoffPoint& p = points_[static_cast<size_t>(i / cameraCount)];
    std::string d = "point " + std::to_string(p.index);
    for (size_t a = 0; a < o_.sweep.axes.size(); ++a) d += ", " + o_.sweep.axes[a].name + "=" + p.values[a];
    return d + (cameraCount > 1 ? ", camera " + std::to_string(i % cameraCount) : "");
}

// Stage 1: AOV's cost estimated from the triangles before any frame (issue 22).
void TradeoffRunner::warnAovCost(RenderSession& session) const {
    const int cameraCount = static_cast<int>(cameras_.size());
    for (size_t p = 0; p < points_.size(); ++p) {
        applyPoint(session, p);
        for (int c = 0; c < cameraCount; ++c) {
            const std::string w = AovCostEstimate::check(session.knobs(), session.scene(), cameraOf(p, c),
                                                         o_.run.width, o_.run.height);
            if (w.empty()) continue;
            const std::string line = "tradeoff: warning: point " + std::to_string(points_[p].index) +
                                     (cameraCount > 1 ? ", camera " + std::to_string(c) : std::string()) + ": " + w;
            warn(line);
        }
    }
}

void TradeoffRunner::warn(const std::string& line) const {
    if (warning_) warning_(line);
    else std::fprintf(stderr, "%s\n", line.c_str());
}

// After stage 2 (the timed rounds): --time PASS is refused before the error
// captures and references when no configuration timed that pass.
// Before the timed rounds: --time names a pass the pipeline has, or a span
// inside one (a typo was
// caught only after the whole sweep, its results not written). Whether it
// ran is checkTimedPass's, after them.
void TradeoffRunner::checkTimedPassName(RenderSession& session) const {
    if (o_.time == "frame") return;
    // Each term: a pass, or a span inside one ("lighting/shadow maps": PASS/NAME).
    std::string list;
    for (const PassInfo& p : session.pipeline().passList()) list += (list.empty() ? "" : ",") + p.name;
    for (const std::string& term : TradeoffTable::timeTerms(o_.time)) {
        const std::string pass = term.substr(0, term.find('/'));
        const auto& passes = session.pipeline().passList();
        if (std::none_of(passes.begin(), passes.end(), [&](const PassInfo& p) { return p.name == pass; }))
            throw Error("--time " + o_.time + ": the pipeline has no pass " + (term == o_.time ? "of that name" : "'" + term + "'") +
                        " (expected frame or one of: " + list + ", or a sum of them: a+b)");
    }
}

void TradeoffRunner::checkTimedPass(const RunnerTimings& timings) const {
    if (o_.time == "frame") return;
    std::vector<std::string> timed;
    for (const auto& s : timings.samples)
        if (tabledSeries(s.series) && s.series != PassTimer::kFrameSeries &&
            std::find(timed.begin(), timed.end(), s.series) == timed.end())
            timed.push_back(s.series);
    std::string list;
    for (const auto& n : timed) list += (list.empty() ? "" : ",") + n;
    for (const std::string& term : TradeoffTable::timeTerms(o_.time))
        if (std::find(timed.begin(), timed.end(), term) == timed.end())
            throw Error("--time " + o_.time + ": no pass " + (term == o_.time ? "of that name" : "'" + term + "'") +
                        " was timed (expected frame or one of: " + (list.empty() ? std::string("none") : list) + ")");
}

// The buffer a tradeoff measures, as the session holds it: raw floats (HDR) or display values; AO's first channel.
FloatImage TradeoffRunner::measuredImage(RenderSession& s, const std::string& buffer) {
    if (buffer == "lbuffer" && s.pipeline().renderScale() > 1) {
        // SSAA rendered the frame at its factor times the output size: the
        // L-buffer at the output size is ssaa.lbuffer, each pixel the box mean
        // of its rendered pixels (the area mean the reference's lbuffer is).
        s.render(FrameRequest{{"ssaa.lbuffer"}});
        return s.readRaw("ssaa.lbuffer");
    }
    const std::string output = gpuOutput(buffer);
    FloatImage image = buffer != "final" ? s.readRaw(output) : s.readDisplay(output);
    if (buffer == "ao" && image.channels > 1) {  // the AO is in the first channel
        FloatImage one;
        one.width = image.width;
        one.height = image.height;
        one.channels = 1;
        one.pixels.resize(static_cast<size_t>(image.width) * image.height);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) one.at(x, y, 0) = image.at(x, y, 0);
        image = std::move(one);
    }
    return image;
}

// What one capture is measured against: the reference, or --against's
// knobs rendered once per configuration (every knob) and camera.
FloatImage TradeoffRunner::againstImage(RenderSession& session, const TradeoffReference& reference, int camera,
                                        std::map<std::string, FloatImage>& rendered) const {
    if (o_.against.empty())
        return reference(session.scene(), session.knobs(), session.camera(), o_.run.width, o_.run.height, o_.buffer);
    for (const KnobAssignment& a : against_) session.knobs().set(*session.knobs().find(a.knob), a.value);
    std::string key = std::to_string(camera);
    for (int id = 0; id < static_cast<int>(session.knobs().size()); ++id) key += "," + session.knobs().format(id);
    key += "," + shortText(session.camera().nearPlane) + "," + shortText(session.camera().farPlane);
    auto it = rendered.find(key);
    if (it == rendered.end()) {
        const std::string output = gpuOutput(o_.buffer);
        session.render(FrameRequest{{output}});
        it = rendered.emplace(key, measuredImage(session, o_.buffer)).first;
    }
    return it->second;
}

namespace {

// The frames a configuration whose image depends on the frames before it
// renders at the camera before its error is captured: TAA (aa.method=taa)
// blends its history with weight 1 - aa.taa_blend a frame, so after n frames
// the first one's weight is (1 - blend)^n; n is where that falls under 1%
// (44 at the default 0.1), at least TAA's jitter period (every offset once)
// and at most 512. 0 for a configuration without history. Without it the
// error would be one jittered frame after another point's (no history: the
// pass rejects a history it did not write), not the method's converged image.
int historyFrames(const KnobRegistry& knobs) {
    const std::optional<int> method = knobs.find(kAaMethodKnob);
    if (!method || knobs.format(*method) != "taa") return 0;
    const std::optional<int> blendKnob = knobs.find("aa.taa_blend");
    const double blend = blendKnob ? knobs.value(*blendKnob) : 0.1;
    if (!(blend > 0.0 && blend < 1.0)) return TaaPass::kJitterPeriod;
    const double n = std::ceil(std::log(0.01) / std::log(1.0 - blend));
    return static_cast<int>(std::clamp(n, static_cast<double>(TaaPass::kJitterPeriod), 512.0));
}

}  // namespace

// Stage 3: the errors, an untimed frame per (point, camera) against its
// counterpart (after historyFrames of its own for a method with history); a
// configuration that fails gets NaN and a note.
TradeoffRunner::Errors TradeoffRunner::captureErrors(RenderSession& session, ConfigurationRunner& runner,
                                                     const TradeoffReference& reference, std::vector<std::string>& notes,
                                                     const BenchProgress& say) const {
    const int cameraCount = static_cast<int>(cameras_.size());
    const std::string output = gpuOutput(o_.buffer);
    const bool hdr = o_.buffer != "final";
    const FrameRequest request{{output}};
    std::map<std::string, FloatImage> againstImages;  // by configuration (every knob) and camera
    Errors errors(points_.size(), std::vector<ErrorEstimate>(static_cast<size_t>(cameraCount)));
    for (size_t p = 0; p < points_.size(); ++p) {
        for (int c = 0; c < cameraCount; ++c) {
            const int config = static_cast<int>(p) * cameraCount + c;
            ErrorEstimate& e = errors[p][static_cast<size_t>(c)];
            e.value = e.low = e.high = kNaN;
            try {
                RenderSession& captured = runner.capture(config, 0, request);
                for (int f = historyFrames(captured.knobs()); f > 0; --f) runner.capture(config, 0, request);
                FloatImage test = measuredImage(captured, o_.buffer);
                FloatImage against = againstImage(session, reference, c, againstImages);
                // The edges of the reference's shadows (whatever --against says).
                std::optional<FloatImage> mask;
                if (o_.mask == "shadow_edges")
                    mask = ShadowEdgeMask::fromShadow(reference(session.scene(), session.knobs(), session.camera(),
                                                                o_.run.width, o_.run.height, "shadow"));
                e = ImageError::measure(against, test, o_.metric, hdr, o_.resamples, pointSeed(p, c),
                                        mask ? &*mask : nullptr);
            } catch (const Error& err) {
                notes.push_back("point " + std::to_string(points_[p].index) + ", camera " + std::to_string(c) + ": " +
                                err.what());
                if (say) say("tradeoff: no error for " + notes.back());
            }
        }
    }
    return errors;
}

namespace {

// A row's frames, frame time with its interval, and each tabled pass's median.
void fillTimes(TradeoffRow& row, const std::vector<std::string>& passes,
               const std::map<std::string, std::vector<double>>& series, int resamples, std::uint64_t seed) {
    auto frame = series.find(PassTimer::kFrameSeries);
    row.frames = frame == series.end() ? 0 : static_cast<int>(frame->second.size());
    row.frameGpuMs = row.frameGpuMsLo = row.frameGpuMsHi = kNaN;
    if (row.frames > 0) {
        const MedianInterval i = bootstrapMedian(frame->second, resamples, seed);
        row.frameGpuMs = i.median;
        row.frameGpuMsLo = i.low;
        row.frameGpuMsHi = i.high;
    }
    for (const auto& pass : passes) {
        auto it = series.find(pass);
        row.passGpuMs.push_back(it == series.end() ? kNaN : median(it->second));
    }
}

// The time the front ranks by (--time: frame, a pass or a sum), its median
// and interval from the row's per-frame values (a sum: per-frame sums).
void fillRankedTime(TradeoffRow& row, const RowData& data, int resamples, std::uint64_t seed) {
    std::vector<double> v;
    for (const auto* frames : data.frames)
        if (frames)
            for (const auto& [sample, ms] : *frames) v.push_back(ms);
    row.timeMs = row.timeMsLo = row.timeMsHi = kNaN;
    if (v.empty()) return;
    const MedianInterval i = bootstrapMedian(v, resamples, seed);
    row.timeMs = i.median;
    row.timeMsLo = i.low;
    row.timeMsHi = i.high;
}

// The draws the front is decided from: --resamples, raised to what Holm's
// adjustment over the largest group's comparisons needs to decide at all
// (frontDrawsNeeded; capped at 200000: the rule line says when that is short).
int frontResamples(const TradeoffTable& t, const TradeoffOptions& o) {
    std::map<std::tuple<std::string, std::string, std::string>, int> groups;
    int largest = 0;
    for (const TradeoffRow& r : t.rows) largest = std::max(largest, ++groups[{r.camera, r.metric, r.buffer}]);
    const int pairs = largest * (largest - 1) / 2;
    const int needed = frontDrawsNeeded(pairs * (o.cost == "gpu_ms" ? 2 : 1), 0.05);
    return std::max(o.resamples, std::min(needed, 200000));
}

// The front by ConfidentFront's paired bootstrap: the cost is the ranked
// time's draws (--cost gpu_ms) or a counter (exact: compared by value, so
// only the error is tested).
void markConfidentFront(TradeoffTable& t, std::vector<RowData>& data, const TradeoffOptions& o) {
    for (size_t i = 0; i < t.rows.size(); ++i) data[i].time = t.rows[i].timeMs;
    t.checkCost(o.cost);  // a counter no point has: one line
    const EvidenceDraws how{frontResamples(t, o), o.block, 777};
    t.markFront(
        [&](size_t i) {
            FrontEvidence e = rowEvidence(data[i], how);
            if (o.cost != "gpu_ms") {
                const double c = t.costOf(t.rows[i], t.time, o.cost);
                e.cost = {c, c, c, {}, true};
            }
            return e;
        },
        FrontRule::pairedBootstrap);
}

// Per series: each counted frame's counters, by sample.
using CountsBySeries = std::map<std::string, std::map<int, PassCounts>>;

CounterValues valuesOf(const PassCounts& c) {
    CounterValues v;
    for (size_t i = 0; i < v.size(); ++i) v[i] = c.v[i] < 0 ? kNaN : static_cast<double>(c.v[i]);
    return v;
}

// A row's counters: its first counted frame's (they are exact: every frame
// of a configuration should give the same); the first frame whose counters
// differ from them is named in `differs` ("" when none).
void fillCounts(TradeoffRow& row, const std::vector<std::string>& passes, const CountsBySeries& counts,
                std::string& differs) {
    auto first = [&](const std::string& series) {
        auto it = counts.find(series);
        if (it == counts.end() || it->second.empty()) return valuesOf({});
        const PassCounts& c = it->second.begin()->second;
        for (const auto& [sample, other] : it->second)
            if (!(other == c) && differs.empty())
                differs = series + " in counted frame " + std::to_string(sample) + " differs from frame " +
                          std::to_string(it->second.begin()->first) + "'s (tabled)";
        return valuesOf(c);
    };
    row.frameCounts = first(PassTimer::kFrameSeries);
    row.passCounts.clear();
    for (const auto& pass : passes) row.passCounts.push_back(first(pass));
}

// The "all" row's counters: each the mean over the cameras that have it.
void meanCounts(TradeoffRow& all, const std::vector<TradeoffRow>& rows, size_t firstRow, size_t passCount) {
    auto mean = [&](auto value) {
        double sum = 0.0;
        int n = 0;
        for (size_t r = firstRow; r < rows.size(); ++r)
            if (const double v = value(rows[r]); !std::isnan(v)) {
                sum += v;
                ++n;
            }
        return n ? sum / n : kNaN;
    };
    all.passCounts.assign(passCount, valuesOf({}));
    for (size_t i = 0; i < PassCounts::kCount; ++i) {
        all.frameCounts[i] = mean([&](const TradeoffRow& r) { return r.frameCounts[i]; });
        for (size_t p = 0; p < passCount; ++p)
            all.passCounts[p][i] = mean([&](const TradeoffRow& r) { return p < r.passCounts.size() ? r.passCounts[p][i] : kNaN; });
    }
}

}  // namespace

// Stage 4: the table, per (point, camera), then per point over every camera,
// and its Pareto front. Throws Error when no row has an error.
void TradeoffRunner::tabulate(TradeoffTable& t, const RunnerTimings& timings, const Errors& errors,
                              const std::vector<ErrorEstimate>& pathErrors, std::vector<std::string>& notes,
                              const BenchProgress& say) const {
    const int cameraCount = static_cast<int>(cameras_.size());
    for (const auto& a : o_.sweep.axes) t.axes.push_back(a.name);
    std::map<int, std::map<std::string, std::vector<double>>> ms;  // config -> series -> GPU ms
    std::map<int, CountsBySeries> counts;                            // config -> series -> sample -> counters
    for (const auto& s : timings.samples) {
        if (!tabledSeries(s.series)) continue;  // other spans: in the JSON of bench, not here
        if (s.series != PassTimer::kFrameSeries &&
            std::find(t.passes.begin(), t.passes.end(), s.series) == t.passes.end())
            t.passes.push_back(s.series);
        ms[s.config][s.series].push_back(s.gpuMs);
        if (s.counts.measured()) counts[s.config][s.series][s.sample] = s.counts;
    }
    t.counted = o_.counters;
    const std::string bufferColumn = o_.buffer + (o_.mask.empty() ? "" : ":" + o_.mask);
    t.time = o_.time;
    const FrameTimes ranked = frameTimes(timings.samples, TradeoffTable::timeTerms(o_.time));
    std::vector<RowData> data;  // per row: what its front evidence is drawn from
    auto newRow = [&](size_t p, const std::string& camera, const ErrorEstimate& e) {
        TradeoffRow row;
        row.point = points_[p].index;
        row.axisValues = points_[p].values;
        row.camera = camera;
        row.metric = o_.metric;
        row.buffer = bufferColumn;
        row.error = e.value;
        row.errorLo = e.low;
        row.errorHi = e.high;
        RowData d;
        d.lowerIsBetter = TradeoffTable::lowerIsBetter(o_.metric);
        d.error = e.value;
        d.tiles.assign(static_cast<size_t>(cameraCount), nullptr);
        data.push_back(std::move(d));
        return row;
    };
    auto addConfig = [&](RowData& d, int config, int camera) {
        const auto it = ranked.find(config);
        if (it != ranked.end()) d.frames.push_back(&it->second);
        const ErrorEstimate& e = errors[static_cast<size_t>(config / cameraCount)][static_cast<size_t>(camera)];
        if (!std::isnan(e.value)) d.tiles[static_cast<size_t>(camera)] = &e.tiles;
    };
    for (size_t p = 0; p < points_.size(); ++p) {
        const size_t firstRow = t.rows.size();
        std::map<std::string, std::vector<double>> pooled;
        std::vector<double> values;
        for (int c = 0; c < cameraCount; ++c) {
            const int config = static_cast<int>(p) * cameraCount + c;
            const ErrorEstimate& e = errors[p][static_cast<size_t>(c)];
            TradeoffRow row = newRow(p, std::to_string(c), e);
            addConfig(data.back(), config, c);
            fillTimes(row, t.passes, ms[config], o_.resamples, pointSeed(p, c) + 1);
            fillRankedTime(row, data.back(), o_.resamples, pointSeed(p, c) + 1);
            row.gpuMemPeakMib = gpuMemPeakMib(timings.samples, config);
            std::string differs;
            fillCounts(row, t.passes, counts[config], differs);
            if (!differs.empty()) {
                notes.push_back("point " + std::to_string(points_[p].index) + ", camera " + std::to_string(c) +
                                ": the counters are not the same in every counted frame: " + differs);
                if (say) say("tradeoff: " + notes.back());
            }
            for (const auto& [series, v] : ms[config]) pooled[series].insert(pooled[series].end(), v.begin(), v.end());
            values.push_back(e.value);
            t.rows.push_back(std::move(row));
        }
        if (cameraCount > 1) {
            // The path's temporal error (its frame pairs the "tiles" the front resamples), or the mean over cameras.
            const bool path = !pathErrors.empty();
            const ErrorEstimate e =
                path ? pathErrors[p] : ImageError::meanOver(values, o_.resamples, pointSeed(p, cameraCount));
            if (!path) noteMissingCameras(p, values, notes, say);
            TradeoffRow row = newRow(p, TradeoffTable::kAllCameras, e);
            for (int c = 0; c < cameraCount; ++c) addConfig(data.back(), static_cast<int>(p) * cameraCount + c, c);
            if (path && !std::isnan(e.value)) data.back().tiles[0] = &pathErrors[p].tiles;
            fillTimes(row, t.passes, pooled, o_.resamples, pointSeed(p, cameraCount) + 1);
            fillRankedTime(row, data.back(), o_.resamples, pointSeed(p, cameraCount) + 1);
            meanCounts(row, t.rows, firstRow, t.passes.size());
            for (size_t k = firstRow; k < t.rows.size(); ++k)
                if (!std::isnan(t.rows[k].gpuMemPeakMib))
                    row.gpuMemPeakMib = std::isnan(row.gpuMemPeakMib) ? t.rows[k].gpuMemPeakMib
                                                                      : std::max(row.gpuMemPeakMib, t.rows[k].gpuMemPeakMib);
            t.rows.push_back(std::move(row));
        }
    }
    // No error anywhere: no front and nothing to plot, so the study fails (the notes say why).
    if (!t.rows.empty() &&
        std::none_of(t.rows.begin(), t.rows.end(), [](const TradeoffRow& r) { return !std::isnan(r.error); }))
        throw Error("tradeoff: no camera of any point has an error, so there is no front to plot (" +
                    (notes.empty() ? std::string("no note") : notes.front()) +
                    (notes.size() > 1 ? "; and " + std::to_string(notes.size() - 1) + " more like it" : "") + ")");
    if (t.rows.empty()) return;
    markConfidentFront(t, data, o_);
}

// The all-cameras error is the mean over the cameras that have one: said when some have none.
void TradeoffRunner::noteMissingCameras(size_t p, const std::vector<double>& values, std::vector<std::string>& notes,
                                        const BenchProgress& say) const {
    const auto measured = std::count_if(values.begin(), values.end(), [](double v) { return !std::isnan(v); });
    const auto cameraCount = static_cast<std::ptrdiff_t>(values.size());
    if (measured == 0 || measured == cameraCount) return;
    notes.push_back("point " + std::to_string(points_[p].index) + ": the all-cameras error is the mean over " +
                    std::to_string(measured) + " of " + std::to_string(cameraCount) +
                    " cameras (the others have no error)");
    if (say) say("tradeoff: " + notes.back());
}

namespace {

// How the shown rows' front was decided (ConfidentFront's rule line).
std::string frontRuleOf(const TradeoffTable& t) {
    const auto it = t.frontRules.find(BudgetPicker::shownCamera(t));
    return it == t.frontRules.end() ? "" : it->second;
}

}  // namespace

// What time_ms is: the frame, a pass, or the median of per-frame sums of passes.
std::string TradeoffRunner::frontTimeText() const {
    if (o_.time == "frame") return "frame_gpu_ms";
    const std::vector<std::string> terms = TradeoffTable::timeTerms(o_.time);
    if (terms.size() == 1) return "gpu_ms." + o_.time;
    std::string sum;
    for (const auto& t : terms) sum += (sum.empty() ? "" : " + ") + ("gpu_ms." + t);
    return "time_ms: per frame " + sum + ", its median and 95% interval over the frames";
}

// Stage 5: what the run was, for the CSV's and the record's settings.
BenchFields TradeoffRunner::settingsOf(const TradeoffResult& result, double totalSeconds,
                                       const std::vector<std::string>& notes) const {
    const int cameraCount = static_cast<int>(cameras_.size());
    std::string sets;
    for (const auto& s : o_.run.sets) sets += (sets.empty() ? "" : " ") + s;
    std::string against;
    for (const auto& s : o_.against) against += (against.empty() ? "" : ",") + s;
    BenchFields settings = {
        {"scene", scene_.source},
        {"preset", o_.run.presetSpec()},
        {"set", sets},
        {"size", std::to_string(o_.run.width) + "x" + std::to_string(o_.run.height)},
        {"frames", std::to_string(o_.frames)},
        {"warmup_per_switch", std::to_string(o_.warmup)},
        {"block", std::to_string(o_.block)},
        {"cameras", o_.walkthrough ? "walkthrough keyframes (" + std::to_string(cameraCount) + ")"
                    : o_.orbit > 0 ? "orbit " + std::to_string(o_.orbit)
                                   : "the run's camera"},
        {"sweep", !o_.sweep.listed.empty() ? "studies: each its own grid (the column study)"
                  : o_.sweep.oneAtATime    ? "one knob at a time about the current settings"
                                           : "full grid"},
        {"metric", o_.metric},
        {"buffer", o_.buffer + " (" + gpuOutput(o_.buffer) + ")"},
        {"mask", o_.mask.empty() ? "none: every pixel" : o_.mask + ": pixels within 2 px of an edge of the reference's shadow buffer"},
        {"front_time", frontTimeText()},
        {"front_rule", frontRuleOf(result.table)},
        {"against", o_.against.empty() ? "reference" : against},
        {"error_interval", "95% percentile bootstrap over " + std::to_string(ImageError::kTile) + "x" +
                               std::to_string(ImageError::kTile) + "-pixel tiles; the all-cameras row over the cameras"},
        {"time_interval", "95% percentile bootstrap of the median over the counted frames"},
        {"resamples", std::to_string(o_.resamples)},
        {"shard", std::to_string(o_.shard.index) + "/" + std::to_string(o_.shard.count)},
        {"sweep_points", std::to_string(sweepSize_)},
        {"timing_seconds", shortText(result.timingSeconds)},
        {"error_seconds", shortText(result.errorSeconds)},
        {"seconds", shortText(totalSeconds)},
    };
    if (o_.budgetMs != 0.0) {
        settings.emplace_back("budget_ms", shortText(o_.budgetMs));
        for (const auto& line : result.pick.lines) settings.emplace_back("pick", line);
    }
    if (o_.budget != 0.0) {
        settings.emplace_back("budget", shortText(o_.budget) + " " + o_.cost);
        for (const auto& line : result.pick.lines) settings.emplace_back("pick", line);
    }
    for (const auto& n : notes) settings.emplace_back("note", n);
    return settings;
}

// The study in named stages: plan (session, AOV's cost), time (the
// interleaved rounds), capture errors, tabulate (table and front), settings.
void TradeoffRunner::checkCostCounter() const {
    const int counter = PassCounts::index(o_.cost);
    if (counter >= 0 && PassCounts::needsStatistics(counter) && !gl::hasPipelineStatistics())
        throw Error("--cost " + o_.cost + ": this driver (" +
                    std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))) +
                    ") lacks GL_ARB_pipeline_statistics_query; samples, bytes and gpu_ms are counted here");
}

TradeoffResult TradeoffRunner::run(const TradeoffReference& reference, const BenchProgress& progress) {
    auto say = [&](const std::string& line) {
        if (progress) progress(line);
    };
    const auto start = Clock::now();
    const int cameraCount = static_cast<int>(cameras_.size());
    checkCostCounter();
    say("tradeoff: setting up " + std::to_string(o_.run.width) + "x" + std::to_string(o_.run.height) +
        " (compiling shaders, uploading " + scene_.name + ")");
    RenderSession session;
    session.setScene(scene_, o_.run);
    session.resize(o_.run.width, o_.run.height);
    warnAovCost(session);
    checkTimedPassName(session);

    RunnerPlan plan;
    plan.configurations = static_cast<int>(points_.size()) * cameraCount;
    plan.frames = o_.frames;
    plan.warmup = o_.warmup;
    plan.block = o_.block;
    plan.counters = o_.counters;
    ConfigurationRunner runner(
        plan,
        [&](int i) -> RenderSession& {
            applyPoint(session, static_cast<size_t>(i / cameraCount));
            return session;
        },
        [&](RenderSession& s, int i, int) { s.camera() = cameraOf(static_cast<size_t>(i / cameraCount), i % cameraCount); });
    say("tradeoff: " + std::to_string(points_.size()) + " point(s)" +
        (o_.shard.whole() ? "" : " (shard " + std::to_string(o_.shard.index) + "/" + std::to_string(o_.shard.count) +
                                     " of " + std::to_string(sweepSize_) + ")") +
        " x " + std::to_string(cameraCount) + " camera(s) x " + std::to_string(o_.frames) + " frame(s), " +
        std::to_string(o_.warmup) + " warm-up frame(s) per switch");
    TradeoffResult result;
    const gl::GlInfo& gl = session.glInfo();
    result.machine = {{"gl_vendor", gl.vendor}, {"gl_renderer", gl.renderer}, {"gl_version", gl.version}};
    const RunnerTimings timings =
        runner.measure("tradeoff", [&](int i) { return describeConfiguration(i); }, say);
    checkTimedPass(timings);
    // A point whose frames lost fragments measures neither the method's cost nor its error: said, as render says it.
    for (const auto& [i, w] : timings.warnings)
        warn("tradeoff: warning: " + describeConfiguration(i) + ": " + w.text(o_.frames));
    result.timingSeconds = timings.seconds;

    const auto errorStart = Clock::now();
    std::vector<std::string> notes;
    const bool temporal = o_.metric == "temporal";
    const Errors errors = temporal ? Errors(points_.size(), std::vector<ErrorEstimate>(static_cast<size_t>(cameraCount),
                                                                                          ErrorEstimate{kNaN, kNaN, kNaN, {}}))
                                   : captureErrors(session, runner, reference, notes, progress);
    const std::vector<ErrorEstimate> pathErrors =
        temporal ? capturePathErrors(session, runner, reference, notes, progress) : std::vector<ErrorEstimate>{};
    result.errorSeconds = seconds(errorStart);
    tabulate(result.table, timings, errors, pathErrors, notes, progress);
    if (o_.budgetMs != 0.0 && !result.table.rows.empty())
        result.pick = BudgetPicker::pick(result.table, o_.budgetMs, BudgetPicker::shownCamera(result.table));
    if (o_.budget != 0.0 && !result.table.rows.empty())
        result.pick = BudgetPicker::pick(result.table, o_.budget, BudgetPicker::shownCamera(result.table),
                                         BudgetPicker::counterCost(result.table, o_.cost));
    result.settings = settingsOf(result, seconds(start), notes);
    say("tradeoff: timed in " + shortText(result.timingSeconds) + " s, errors in " + shortText(result.errorSeconds) + " s");
    result.shaders = session.shaders().compiled();
    return result;
}

}  // namespace dw
