#include "renderer/bench/BenchRunner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <map>
#include <memory>
#include <set>

#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/ao/AovCostEstimate.h"
#include "renderer/bench/ConfigurationRunner.h"
#include "renderer/knobs/KnobAssignment.h"
#include "renderer/scene/CameraPath.h"
#include "renderer/scene/LightGenerator.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

namespace {

// A number as the fewest digits that read back the same (to_string's six
// decimals wrote a radius of 1e-7 as 0.000000).
std::string shortest(double v) {
    char text[32];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof(text), "%.*g", digits, v);
        if (std::strtod(text, nullptr) == v) break;
    }
    return text;
}


using Clock = std::chrono::steady_clock;

std::string duration(double seconds) {
    const long s = std::lround(seconds);
    char text[32];
    std::snprintf(text, sizeof(text), "%ld:%02ld", s / 60, s % 60);
    return text;
}

std::string describe(const BenchConfig& c, const BenchGrid& grid) {
    std::string d = c.size() + ", " + std::to_string(c.lights) + " lights";
    for (size_t k = 0; k < grid.knobAxes.size(); ++k) d += ", " + grid.knobAxes[k].knob + "=" + c.knobValues[k];
    return d;
}

struct SizeSession {
    std::unique_ptr<RenderSession> session;
    int lights = -1;  // the light count whose list the session's scene holds now
};

}  // namespace

BenchRunner::BenchRunner(BenchOptions options) : o_(std::move(options)) {
    if (o_.frames < 1) throw Error("bench needs at least one counted frame per configuration");
    if (o_.warmup < 0) throw Error("the warm-up frame count must not be negative");
    if (o_.block < 1) throw Error("--block must be at least 1");
    if (o_.grid.sizes.empty()) throw Error("bench needs at least one render size");
    if (o_.orbit > 0 && o_.walkthrough) throw Error("--orbit and --walkthrough are two camera paths; pick one");
    if (o_.lppPoses < 1) throw Error("--lpp-poses must be at least 1");
    for (int n : o_.grid.lights)
        if (n < 0) throw Error("--lights: a light count must not be negative, got " + std::to_string(n));

    // Every knob value a configuration will set, checked before any GL work.
    o_.run.validate();
    const KnobRegistry declared = RunConfig::declaredKnobs();
    // Each value is then written as the knob writes it (TRUE and 1 as true,
    // 16.0 as 16), so that two spellings of one value are one configuration
    // and --baseline finds the value however it is spelt.
    for (size_t a = 0; a < o_.grid.knobAxes.size(); ++a) {
        auto& axis = o_.grid.knobAxes[a];
        // An old knob name (KnobRegistry::addAlias) sweeps the new knob, with --set's warning;
        // the column is named by the new name.
        axis.knob = declared.canonicalName(axis.knob);
        for (size_t b = 0; b < a; ++b)
            if (o_.grid.knobAxes[b].knob == axis.knob) throw Error("--sweep " + axis.knob + " is given twice");
        if (!declared.find(axis.knob)) throw Error("--sweep: unknown knob '" + axis.knob + "' (see: list knobs)");
        axis.numbers.clear();
        for (size_t i = 0; i < axis.values.size(); ++i) {
            const std::string given = axis.values[i];
            const KnobAssignment read = readKnobAssignment(declared, axis.knob, given);
            axis.values[i] = read.text;
            axis.numbers.push_back(read.value);
            for (size_t j = 0; j < i; ++j)
                if (axis.values[j] == axis.values[i])
                    throw Error("--sweep " + axis.knob + ": '" + given + "' is '" + axis.values[i] +
                                "', which is given before");
        }
    }
    if (const size_t eq = o_.baseline.find('='); eq != std::string::npos) {
        const std::string axis = o_.baseline.substr(0, eq);
        for (const auto& a : o_.grid.knobAxes)
            if (a.knob == axis) {
                try {
                    o_.baseline = axis + "=" + readKnobAssignment(declared, axis, o_.baseline.substr(eq + 1)).text;
                } catch (const Error&) {
                    // Not a value of the knob: chooseBaseline says the axis never has it.
                }
            }
    }

    scene_ = loadScene(o_.run.sceneSpec());
    if (o_.walkthrough && scene_.cameraPath.empty())
        throw Error("--walkthrough: the scene '" + scene_.name + "' has no camera.path (docs/scene-format.md)");

    // The radius is meant at the threshold the configurations start from.
    KnobRegistry start = declared;
    o_.run.applyKnobs(start, scene_);
    threshold_ = 1.0 / 255.0;
    if (auto id = start.find("lighting.threshold")) threshold_ = start.value(*id);
    radius_ = o_.lightRadius > 0.0f ? o_.lightRadius : 0.2f * std::max(scene_.bounds().radius(), 1e-3f);

    const int sceneLights = static_cast<int>(scene_.lights.size());
    baseline_ = chooseBaseline(o_.grid, sceneLights, o_.baseline);
    gridSize_ = o_.grid.count();
    std::vector<BenchConfig> all = o_.grid.configs(sceneLights);
    const std::vector<int> groups = o_.grid.groupsAlong(all, baseline_.axis);
    // --exclude: the axes as the table names them, knob values as the knob writes them.
    GridExclusion::Axes axes;
    std::vector<std::string> sizes, lightCounts;
    for (const auto& [w, h] : o_.grid.sizes) sizes.push_back(std::to_string(w) + "x" + std::to_string(h));
    for (int n : o_.grid.lights) lightCounts.push_back(std::to_string(n));
    if (o_.grid.lights.empty()) lightCounts.push_back(std::to_string(sceneLights));
    axes.emplace_back("size", sizes);
    axes.emplace_back("lights", lightCounts);
    for (const auto& a : o_.grid.knobAxes) axes.emplace_back(a.knob, a.values);
    o_.exclude.resolve(axes, [&](const std::string& axis, const std::string& value) {
        return axis == "size" || axis == "lights" ? value : readKnobAssignment(declared, axis, value).text;
    });
    size_t kept = 0;
    for (size_t i = 0; i < all.size(); ++i) {
        const BenchConfig& c = all[i];
        const bool excluded = o_.exclude.excludes([&](const std::string& axis) {
            if (axis == "size") return c.size();
            if (axis == "lights") return std::to_string(c.lights);
            for (size_t k = 0; k < o_.grid.knobAxes.size(); ++k)
                if (o_.grid.knobAxes[k].knob == axis) return c.knobValues[k];
            return std::string();
        });
        if (excluded) continue;
        ++kept;
        if (o_.shard.takes(groups[i])) configs_.push_back(std::move(all[i]));
    }
    if (kept == 0)
        throw Error("the grid is empty after --exclude: every one of its " + std::to_string(all.size()) +
                    " configuration(s) is left out");
}

namespace {

// The results before any frame: one row per configuration of this shard, LPP unknown.
BenchResults emptyResults(const BenchGrid& grid, const std::vector<BenchConfig>& configs) {
    BenchResults results;
    for (const auto& a : grid.knobAxes) results.knobAxes.push_back(a.knob);
    for (const auto& c : configs) {
        BenchConfigResult r;
        r.config = c;
        r.lpp = r.lppLit = std::nan("");
        results.configs.push_back(r);
    }
    return results;
}

// Generated lights per light count, made once (a longer list from the same
// seed starts with the shorter one); the scene's own first with --keep-scene-lights.
std::map<int, std::vector<Light>> generateLightLists(const BenchOptions& o, const std::vector<BenchConfig>& configs,
                                                     const Scene& scene, float radius, double threshold) {
    std::map<int, std::vector<Light>> lists;
    if (o.grid.lights.empty()) return lists;
    for (const auto& c : configs) {
        if (lists.count(c.lights)) continue;
        LightGeneratorSettings g;
        g.count = c.lights;
        g.seed = o.seed;
        g.radius = radius;
        g.threshold = threshold;
        std::vector<Light> lights = o.keepSceneLights ? scene.lights : std::vector<Light>{};
        for (auto& l : generateLights(scene.bounds(), g)) lights.push_back(std::move(l));
        lists.emplace(c.lights, std::move(lights));
    }
    return lists;
}

// Lights per pixel, untimed: the counting shader on its own frames, at
// `poses` poses of the camera path. A strategy that cannot count (a new one,
// say) costs its LPP, not the run.
void measureLightsPerPixel(ConfigurationRunner& runner, BenchResults& results, int frames, int poses,
                           const BenchProgress& say) {
    // gbuffer.view_position's alpha is 0 where no surface is: sky and
    // background count towards LPP (a full-screen light's shader runs
    // there too) but not towards LPP lit.
    const FrameRequest counting{{"lighting.overlap", "gbuffer.view_position"}};
    for (size_t i = 0; i < results.configs.size(); ++i) {
        BenchConfigResult& r = results.configs[i];
        double sum = 0.0, pixels = 0.0, lit = 0.0, litSum = 0.0;
        try {
            for (int p = 0; p < poses; ++p) {
                const int k = poses > 1 ? static_cast<int>(std::lround(static_cast<double>(p) * (frames - 1) / (poses - 1))) : 0;
                RenderSession& session = runner.capture(static_cast<int>(i), k, counting);
                const FloatImage overlap = session.readRaw("lighting.overlap");
                const FloatImage position = session.readRaw("gbuffer.view_position");
                for (int y = 0; y < overlap.height; ++y)
                    for (int x = 0; x < overlap.width; ++x) {
                        const float v = overlap.at(x, y, 0);
                        sum += v;
                        if (v > 0.0f && position.at(x, y, 3) != 0.0f) {
                            lit += 1.0;
                            litSum += v;
                        }
                    }
                pixels += static_cast<double>(overlap.width) * overlap.height;
            }
        } catch (const Error& e) {
            say("bench: no lights per pixel for configuration " + std::to_string(r.config.index) + ": " + e.what());
            continue;
        }
        r.lpp = pixels > 0.0 ? sum / pixels : std::nan("");
        r.lppLit = lit > 0.0 ? litSum / lit : 0.0;
    }
}

// Frames an interrupted run measured (bench --resume): kept in `results`,
// not measured again.
struct ResumedFrames {
    std::set<std::pair<int, int>> measured;  // (grid index, sample) with a "frame" row
    long long seqBase = 0;                   // the next sequence number after the kept ones
};

ResumedFrames keepResumedFrames(const BenchResults& resumed, BenchResults& results, int frames,
                                const BenchProgress& say) {
    ResumedFrames kept;
    if (resumed.knobAxes != results.knobAxes)
        throw Error("--resume: the CSV sweeps other knobs (" + BenchResults::csvHeader(resumed.knobAxes) + ")");
    for (const auto& c : resumed.configs) {
        const BenchConfigResult* mine = results.find(c.config.index);
        if (!mine) continue;  // another shard's
        if (mine->config.size() != c.config.size() || mine->config.lights != c.config.lights ||
            mine->config.knobValues != c.config.knobValues)
            throw Error("--resume: configuration " + std::to_string(c.config.index) +
                        " of the CSV is not this grid's (another run's CSV?)");
    }
    for (const auto& sample : resumed.samples)
        if (sample.series == PassTimer::kFrameSeries && sample.sample < frames && results.find(sample.config))
            kept.measured.insert({sample.config, sample.sample});
    for (const auto& sample : resumed.samples)
        if (kept.measured.count({sample.config, sample.sample})) {
            results.samples.push_back(sample);
            kept.seqBase = std::max(kept.seqBase, sample.seq + 1);
        }
    say("bench: resuming: " + std::to_string(kept.measured.size()) + " counted frame(s) kept from the CSV");
    return kept;
}

}  // namespace

// What the run was, for the CSV's and the record's settings.
BenchFields BenchRunner::settingsOf(const CameraPath& path, double seconds) const {
    BenchFields settings = {
        {"scene", scene_.source},
        {"preset", o_.run.presetSpec()},
        {"frames", std::to_string(o_.frames)},
        {"warmup_per_switch", std::to_string(o_.warmup)},
        {"block", std::to_string(o_.block)},
        {"lights", o_.grid.lights.empty()  ? "the scene's own"
                   : o_.keepSceneLights ? "generated, added to the scene's " + std::to_string(scene_.lights.size())
                                        : "generated"},
        {"seed", std::to_string(o_.seed)},
        {"light_radius", shortest(radius_)},
        {"radius_threshold", shortest(threshold_)},
        {"camera", o_.walkthrough ? "walkthrough (camera.path)" : o_.orbit > 0 ? "orbit " + std::to_string(o_.orbit) : "still"},
        {"lpp_poses", o_.lpp ? std::to_string(path.moving() ? o_.lppPoses : 1) : "0"},
        {"shard", std::to_string(o_.shard.index) + "/" + std::to_string(o_.shard.count)},
        {"grid_configurations", std::to_string(gridSize_)},
        {"seconds", std::to_string(seconds)},
    };
    std::string sets;
    for (const auto& s : o_.run.sets) sets += (sets.empty() ? "" : " ") + s;
    settings.emplace_back("set", sets);
    return settings;
}

// The run in named stages: plan (results, light lists, a session per size,
// AOV's cost), lights per pixel, resumed frames, the timed rounds, settings.
BenchResults BenchRunner::run(const BenchProgress& progress, const BenchStream& stream, const BenchResults* resumed) {
    auto say = [&](const std::string& line) {
        if (progress) progress(line);
    };
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

    BenchResults results = emptyResults(o_.grid, configs_);
    results.counted = o_.counters;
    const std::map<int, std::vector<Light>> lightLists = generateLightLists(o_, configs_, scene_, radius_, threshold_);
    // A session per size, all in this context, each with the scene uploaded once.
    std::map<std::string, SizeSession> sessions;
    Camera base = o_.run.camera(scene_);
    const CameraPath path = o_.walkthrough ? CameraPath::keyframes(base, scene_.cameraPath)
                            : o_.orbit > 0 ? CameraPath::orbit(base, o_.orbit)
                                           : CameraPath::still(base);

    // Switching to a configuration: its size's session, its light list, the
    // run configuration's knobs (defaults, scene, preset, --set), then its own values.
    auto apply = [&](const BenchConfig& c) -> RenderSession& {
        SizeSession& s = sessions[c.size()];
        if (!s.session) {
            say("bench: setting up " + c.size() + " (compiling shaders, uploading " + scene_.name + ")");
            s.session = std::make_unique<RenderSession>();
            s.session->setScene(scene_, o_.run);
            s.session->resize(c.width, c.height);
        }
        RenderSession& session = *s.session;
        if (!o_.grid.lights.empty() && s.lights != c.lights) {
            session.mutableScene().lights = lightLists.at(c.lights);
            s.lights = c.lights;
        }
        o_.run.applyKnobs(session.knobs(), session.scene());
        for (size_t k = 0; k < o_.grid.knobAxes.size(); ++k)
            session.knobs().set(*session.knobs().find(o_.grid.knobAxes[k].knob), o_.grid.knobAxes[k].numbers[c.knobAt[k]]);
        return session;
    };
    RunnerPlan plan;
    plan.configurations = static_cast<int>(configs_.size());
    plan.frames = o_.frames;
    plan.warmup = o_.warmup;
    plan.block = o_.block;
    plan.counters = o_.counters;
    ConfigurationRunner runner(
        plan, [&](int i) -> RenderSession& { return apply(configs_[static_cast<size_t>(i)]); },
        [&](RenderSession& session, int, int sample) { session.camera() = path.at(sample, o_.frames); });
    for (const auto& c : configs_) apply(c);  // every size set up before the first line about frames
    // AOV's cost estimated from the triangles before any frame (issue 22: a
    // large model at the default radius ran for minutes with no word).
    for (const auto& c : configs_) {
        RenderSession& s = apply(c);
        const std::string w = AovCostEstimate::check(s.knobs(), s.scene(), path.at(0, o_.frames), c.width, c.height);
        if (w.empty()) continue;
        warn("bench: warning: configuration " + std::to_string(c.index) + " (" + c.size() + "): " + w);
    }
    if (!sessions.empty()) {
        const gl::GlInfo& gl = sessions.begin()->second.session->glInfo();
        results.machine = {{"gl_vendor", gl.vendor}, {"gl_renderer", gl.renderer}, {"gl_version", gl.version}};
    }

    say("bench: " + std::to_string(configs_.size()) + " configuration(s)" +
        (o_.shard.whole() ? "" : " (shard " + std::to_string(o_.shard.index) + "/" + std::to_string(o_.shard.count) +
                                     " of " + std::to_string(gridSize_) + ")") +
        " x " + std::to_string(o_.frames) + " frame(s), in blocks of " + std::to_string(o_.block) + ", " +
        std::to_string(o_.warmup) + " warm-up frame(s) per switch");
    if (o_.lpp) {
        say("bench: lights per pixel (untimed frames)");
        measureLightsPerPixel(runner, results, o_.frames, path.moving() ? o_.lppPoses : 1, say);
    }
    const ResumedFrames kept = resumed ? keepResumedFrames(*resumed, results, o_.frames, say) : ResumedFrames{};
    const std::vector<BenchSample> keptSamples = results.samples;
    if (stream && !keptSamples.empty()) stream(results, keptSamples);
    timeRounds(runner, results, kept.measured, kept.seqBase, stream, say);
    results.settings = settingsOf(path, elapsed());
    for (const auto& [size, s] : sessions)
        if (s.session) results.shaders.add(s.session->shaders().compiled());
    say("bench: done in " + duration(elapsed()));
    return results;
}

void BenchRunner::warn(const std::string& line) const {
    if (warning_) warning_(line);
    else std::fprintf(stderr, "%s\n", line.c_str());
}

// The timed rounds, streamed as they come; the runner numbers configurations
// by position, the results by grid index (after the kept frames' sequence).
void BenchRunner::timeRounds(ConfigurationRunner& runner, BenchResults& results,
                             const std::set<std::pair<int, int>>& measured, long long seqBase, const BenchStream& stream,
                             const BenchProgress& say) const {
    auto toGrid = [&](std::vector<BenchSample> samples) {
        for (auto& sample : samples) {
            sample.config = configs_[static_cast<size_t>(sample.config)].index;
            sample.seq += seqBase;
        }
        return samples;
    };
    RunnerTimings timings = runner.measure(
        "bench", [&](int i) { return describe(configs_[static_cast<size_t>(i)], o_.grid); }, say,
        stream ? ConfigurationRunner::Stream([&](const std::vector<BenchSample>& fresh) { stream(results, toGrid(fresh)); })
               : ConfigurationRunner::Stream(),
        [&](int i, int sample) { return measured.count({configs_[static_cast<size_t>(i)].index, sample}) > 0; });
    for (auto& sample : toGrid(std::move(timings.samples))) results.samples.push_back(std::move(sample));
    std::stable_sort(results.samples.begin(), results.samples.end(), [](const BenchSample& a, const BenchSample& b) {
        return a.config != b.config ? a.config < b.config : a.sample < b.sample;
    });
    for (auto& [i, stats] : timings.stats) results.configs[static_cast<size_t>(i)].stats = std::move(stats);
    for (const auto& [i, w] : timings.warnings) {
        const BenchConfig& c = configs_[static_cast<size_t>(i)];
        warn("bench: warning: configuration " + std::to_string(c.index) + " (" + describe(c, o_.grid) +
             "): " + w.text(o_.frames));
    }
}

}  // namespace dw
