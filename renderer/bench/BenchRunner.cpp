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

// One counted frame, before its timings are harvested.
struct Counted {
    int config = 0;
    int sample = 0;
    long long seq = 0;
};

struct SizeSession {
    std::unique_ptr<RenderSession> session;
    int lights = -1;  // the light count whose list the session's scene holds now
    std::map<std::uint64_t, Counted> counted;  // by frame index
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
    auto canonical = [&](const std::string& knob, const std::string& value) {
        KnobRegistry k = declared;
        k.applyAssignment(knob + "=" + value);
        return k.format(*k.find(knob));
    };
    for (auto& axis : o_.grid.knobAxes) {
        if (!declared.find(axis.knob)) throw Error("--sweep: unknown knob '" + axis.knob + "' (see: list knobs)");
        for (size_t i = 0; i < axis.values.size(); ++i) {
            const std::string given = axis.values[i];
            axis.values[i] = canonical(axis.knob, given);
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
                    o_.baseline = axis + "=" + canonical(axis, o_.baseline.substr(eq + 1));
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
    for (size_t i = 0; i < all.size(); ++i)
        if (o_.shard.takes(groups[i])) configs_.push_back(std::move(all[i]));
}

BenchResults BenchRunner::run(const BenchProgress& progress) {
    auto say = [&](const std::string& line) {
        if (progress) progress(line);
    };
    const auto start = Clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

    BenchResults results;
    for (const auto& a : o_.grid.knobAxes) results.knobAxes.push_back(a.knob);
    for (const auto& c : configs_) {
        BenchConfigResult r;
        r.config = c;
        r.lpp = r.lppLit = std::nan("");
        results.configs.push_back(r);
    }

    // Generated lights per light count, made once (a longer list from the
    // same seed starts with the shorter one).
    std::map<int, std::vector<Light>> lightLists;
    if (!o_.grid.lights.empty())
        for (const auto& c : configs_) {
            if (lightLists.count(c.lights)) continue;
            LightGeneratorSettings g;
            g.count = c.lights;
            g.seed = o_.seed;
            g.radius = radius_;
            g.threshold = threshold_;
            std::vector<Light> lights = o_.keepSceneLights ? scene_.lights : std::vector<Light>{};
            for (auto& l : generateLights(scene_.bounds(), g)) lights.push_back(std::move(l));
            lightLists.emplace(c.lights, std::move(lights));
        }

    // A session per size, all in this context, each with the scene uploaded once.
    const int rounds = (o_.frames + o_.block - 1) / o_.block;
    std::map<std::string, SizeSession> sessions;
    size_t framesPerSession = 0;
    for (const auto& c : configs_) {
        SizeSession& s = sessions[c.size()];
        if (!s.session) {
            say("bench: setting up " + c.size() + " (compiling shaders, uploading " + scene_.name + ")");
            s.session = std::make_unique<RenderSession>();
            s.session->setScene(scene_, o_.run);
            s.session->resize(c.width, c.height);
        }
        framesPerSession += static_cast<size_t>(rounds * o_.warmup + o_.frames + o_.lppPoses);
    }
    if (!sessions.empty()) {
        const gl::GlInfo& gl = sessions.begin()->second.session->glInfo();
        results.machine = {{"gl_vendor", gl.vendor}, {"gl_renderer", gl.renderer}, {"gl_version", gl.version}};
    }
    for (auto& [size, s] : sessions)  // keep every counted frame's samples until the end
        s.session->pipeline().timer().setHistoryLength(std::max(PassTimer::kHistory, framesPerSession + 64));

    Camera base = o_.run.camera(scene_);
    const CameraPath path = o_.walkthrough ? CameraPath::keyframes(base, scene_.cameraPath)
                            : o_.orbit > 0 ? CameraPath::orbit(base, o_.orbit)
                                           : CameraPath::still(base);

    auto apply = [&](const BenchConfig& c) -> RenderSession& {
        SizeSession& s = sessions.at(c.size());
        RenderSession& session = *s.session;
        if (!o_.grid.lights.empty() && s.lights != c.lights) {
            session.mutableScene().lights = lightLists.at(c.lights);
            s.lights = c.lights;
        }
        // The run configuration's order (defaults, scene, preset, --set), then this configuration's values.
        o_.run.applyKnobs(session.knobs(), session.scene());
        for (size_t k = 0; k < o_.grid.knobAxes.size(); ++k)
            session.knobs().applyAssignment(o_.grid.knobAxes[k].knob + "=" + c.knobValues[k]);
        return session;
    };

    const long long total = static_cast<long long>(configs_.size()) * o_.frames;
    say("bench: " + std::to_string(configs_.size()) + " configuration(s)" +
        (o_.shard.whole() ? "" : " (shard " + std::to_string(o_.shard.index) + "/" + std::to_string(o_.shard.count) +
                                     " of " + std::to_string(gridSize_) + ")") +
        " x " + std::to_string(o_.frames) + " frame(s), in blocks of " + std::to_string(o_.block) + ", " +
        std::to_string(o_.warmup) + " warm-up frame(s) per switch");

    std::map<int, FrameReport> lastReport;
    long long seq = 0;
    int previous = -1;
    double lastSaid = 0.0;
    const FrameRequest request;  // the final image, as a user would see it
    for (int round = 0; round < rounds; ++round) {
        for (const auto& c : configs_) {
            RenderSession& session = apply(c);
            SizeSession& s = sessions.at(c.size());
            const int first = round * o_.block, count = std::min(o_.block, o_.frames - first);
            // Warm-up after a switch (every block when there is more than one configuration).
            if (c.index != previous)
                for (int w = 0; w < o_.warmup; ++w) {
                    session.camera() = path.at(first, o_.frames);
                    session.render(request);
                }
            previous = c.index;
            for (int j = 0; j < count; ++j) {
                session.camera() = path.at(first + j, o_.frames);
                FrameReport report = session.render(request);
                s.counted[report.frameIndex] = {c.index, first + j, seq++};
                lastReport[c.index] = std::move(report);
            }
            if (elapsed() - lastSaid > 2.0) {
                lastSaid = elapsed();
                const double left = seq > 0 ? lastSaid / static_cast<double>(seq) * static_cast<double>(total - seq) : 0.0;
                say("bench: frame " + std::to_string(seq) + "/" + std::to_string(total) + " (round " +
                    std::to_string(round + 1) + "/" + std::to_string(rounds) + "), " + duration(lastSaid) +
                    " elapsed, about " + duration(left) + " left; now " + describe(c, o_.grid));
            }
        }
    }

    // Lights per pixel, untimed: the counting shader on its own frames.
    if (o_.lpp) {
        say("bench: lights per pixel (untimed frames)");
        const int poses = path.moving() ? o_.lppPoses : 1;
        // gbuffer.view_position's alpha is 0 where no surface is: sky and
        // background count towards LPP (a full-screen light's shader runs
        // there too) but not towards LPP lit.
        const FrameRequest counting{{"lighting.overlap", "gbuffer.view_position"}};
        for (auto& r : results.configs) {
            RenderSession& session = apply(r.config);
            double sum = 0.0, pixels = 0.0, lit = 0.0, litSum = 0.0;
            // A strategy that cannot count (a new one, say) costs its LPP, not the run.
            try {
                for (int p = 0; p < poses; ++p) {
                    const int k = poses > 1 ? static_cast<int>(std::lround(static_cast<double>(p) * (o_.frames - 1) / (poses - 1))) : 0;
                    session.camera() = path.at(k, o_.frames);
                    session.render(counting);
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

    // Harvest: wait for every outstanding timestamp once, at the end.
    std::map<int, std::set<std::string>> seriesOf;
    for (auto& [size, s] : sessions) {
        PassTimer& timer = s.session->pipeline().timer();
        timer.collect(true);
        for (const auto& series : timer.series())
            for (const TimingSample& t : series.samples) {
                auto it = s.counted.find(t.frame);
                if (it == s.counted.end()) continue;
                BenchSample b;
                b.config = it->second.config;
                b.sample = it->second.sample;
                b.seq = it->second.seq;
                b.frame = t.frame;
                b.series = series.name;
                // To the CSV's 0.1 µs, so that the tables of this run and of
                // `bench merge` over its CSV are made from the same numbers.
                b.gpuMs = std::round(double{t.gpuMs} * 1e4) / 1e4;
                b.cpuMs = std::round(double{t.cpuMs} * 1e4) / 1e4;
                seriesOf[b.config].insert(b.series);
                results.samples.push_back(std::move(b));
            }
    }
    for (auto& r : results.configs)
        if (auto it = lastReport.find(r.config.index); it != lastReport.end())
            for (const PassRecord& rec : it->second.passes)
                if (rec.ran && !rec.stats.empty()) r.stats[rec.name] = rec.stats;
    // Each frame's series in pipeline order (passes, each followed by its spans), the frame total last.
    std::map<int, std::map<std::string, int>> rank;
    for (auto& [config, report] : lastReport) {
        std::map<std::string, int>& order = rank[config];
        for (const PassRecord& rec : report.passes) {
            if (!rec.ran) continue;
            order.emplace(rec.name, static_cast<int>(order.size()));
            for (const auto& name : seriesOf[config])
                if (name.rfind(rec.name + "/", 0) == 0) order.emplace(name, static_cast<int>(order.size()));
        }
        order.emplace(PassTimer::kFrameSeries, 1 << 20);
    }
    std::sort(results.samples.begin(), results.samples.end(), [&](const BenchSample& a, const BenchSample& b) {
        if (a.config != b.config) return a.config < b.config;
        if (a.sample != b.sample) return a.sample < b.sample;
        const auto& order = rank[a.config];
        auto ra = order.find(a.series), rb = order.find(b.series);
        const int ia = ra == order.end() ? 1 << 19 : ra->second, ib = rb == order.end() ? 1 << 19 : rb->second;
        return ia != ib ? ia < ib : a.series < b.series;
    });

    results.settings = {
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
        {"seconds", std::to_string(elapsed())},
    };
    std::string sets;
    for (const auto& s : o_.run.sets) sets += (sets.empty() ? "" : " ") + s;
    results.settings.emplace_back("set", sets);
    say("bench: done in " + duration(elapsed()));
    return results;
}

}  // namespace dw
