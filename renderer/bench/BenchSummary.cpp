#include "renderer/bench/BenchSummary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "renderer/Error.h"

namespace dw {

using Json = nlohmann::ordered_json;

namespace {

// The value a configuration has on an axis, as text.
std::string axisValue(const BenchResults& r, const BenchConfig& c, const std::string& axis) {
    if (axis == "size") return c.size();
    if (axis == "lights") return std::to_string(c.lights);
    for (size_t k = 0; k < r.knobAxes.size(); ++k)
        if (r.knobAxes[k] == axis) return c.knobValues[k];
    return {};
}

std::vector<std::string> axisNames(const BenchResults& r) {
    std::vector<std::string> names = {"size", "lights"};
    names.insert(names.end(), r.knobAxes.begin(), r.knobAxes.end());
    return names;
}

// The values an axis takes, in the order of the configurations.
std::vector<std::string> axisValues(const BenchResults& r, const std::string& axis) {
    std::vector<std::string> values;
    for (const auto& c : r.configs) {
        std::string v = axisValue(r, c.config, axis);
        if (std::find(values.begin(), values.end(), v) == values.end()) values.push_back(std::move(v));
    }
    return values;
}

bool sameExcept(const BenchResults& r, const BenchConfig& a, const BenchConfig& b, const std::string& axis) {
    for (const auto& name : axisNames(r))
        if (name != axis && axisValue(r, a, name) != axisValue(r, b, name)) return false;
    return true;
}

std::string fixed(double v, int digits = 3) {
    if (!std::isfinite(v)) return "-";
    char text[64];
    std::snprintf(text, sizeof(text), "%.*f", digits, v);
    return text;
}

std::string row(const std::vector<std::string>& cells) {
    std::string line = "|";
    for (const auto& c : cells) line += " " + c + " |";
    return line + "\n";
}

std::string rule(const std::vector<std::string>& header, size_t textColumns) {
    std::string line = "|";
    for (size_t i = 0; i < header.size(); ++i) line += i < textColumns ? " --- |" : " ---: |";
    return line + "\n";
}

double finiteOrNan(double v) { return std::isfinite(v) ? v : std::nan(""); }

// Four decimals, as in the CSV: a 0.1 microsecond step, finer than the timestamps' noise.
double rounded(double v) { return std::round(v * 1e4) / 1e4; }

Json msJson(const TimingStats& s) {
    auto r = [](float v) { return rounded(static_cast<double>(v)); };
    return {{"median", r(s.median)}, {"min", r(s.min)}, {"max", r(s.max)}, {"mean", r(s.mean)}, {"frames", s.count}};
}

Json optionalNumber(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

}  // namespace

const BenchSeriesStats* BenchSummaryRow::find(const std::string& name) const {
    for (const auto& s : series)
        if (s.series == name) return &s;
    return nullptr;
}

const BenchSummaryRow* BenchSummary::find(int config) const {
    for (const auto& r : rows)
        if (r.config == config) return &r;
    return nullptr;
}

namespace {

// The rule of both chooseBaseline()s, over axes given as (name, values in
// order), knob axes first, then lights, then size.
using AxisList = std::vector<std::pair<std::string, std::vector<std::string>>>;

BenchBaseline chooseFrom(const AxisList& axes, const std::string& spec) {
    BenchBaseline b;
    if (!spec.empty()) {
        const size_t eq = spec.find('=');
        if (eq == std::string::npos)
            throw Error("--baseline expects axis=value (e.g. lighting.strategy=volumes), got '" + spec + "'");
        b.axis = spec.substr(0, eq);
        b.value = spec.substr(eq + 1);
        std::string names;
        for (const auto& [name, values] : axes) {
            names += (names.empty() ? "" : ", ") + name;
            if (name != b.axis) continue;
            if (std::find(values.begin(), values.end(), b.value) != values.end()) return b;
            std::string all;
            for (const auto& v : values) all += (all.empty() ? "" : ", ") + v;
            throw Error("--baseline: " + b.axis + " is never '" + b.value + "' here (" + all + ")");
        }
        throw Error("--baseline: '" + b.axis + "' is not an axis of this run (" + names + ")");
    }
    for (const auto& [name, values] : axes)
        if (values.size() > 1) {
            b.axis = name;
            b.value = values.front();
            return b;
        }
    return b;
}

}  // namespace

BenchBaseline chooseBaseline(const BenchResults& results, const std::string& spec) {
    AxisList axes;
    for (const auto& k : results.knobAxes) axes.emplace_back(k, axisValues(results, k));
    axes.emplace_back("lights", axisValues(results, "lights"));
    axes.emplace_back("size", axisValues(results, "size"));
    return chooseFrom(axes, spec);
}

BenchBaseline chooseBaseline(const BenchGrid& grid, int sceneLights, const std::string& spec) {
    AxisList axes;
    for (const auto& a : grid.knobAxes) axes.emplace_back(a.knob, a.values);
    std::vector<std::string> lights, sizes;
    for (int n : grid.lights) lights.push_back(std::to_string(n));
    if (grid.lights.empty()) lights.push_back(std::to_string(sceneLights));
    for (const auto& [w, h] : grid.sizes) sizes.push_back(std::to_string(w) + "x" + std::to_string(h));
    axes.emplace_back("lights", lights);
    axes.emplace_back("size", sizes);
    return chooseFrom(axes, spec);
}

bool hasSeries(const BenchResults& results, const std::string& series) {
    for (const auto& s : results.samples)
        if (s.series == series) return true;
    return false;
}

BenchSummary summarize(const BenchResults& results, const BenchBaseline& baseline, int resamples, std::uint64_t seed) {
    BenchSummary summary;
    summary.baseline = baseline;
    // Samples by configuration and series, and the frame times for the ratios.
    std::map<int, std::map<std::string, std::pair<std::vector<float>, std::vector<float>>>> bySeries;
    std::map<int, std::vector<double>> compared;  // the ratio series' GPU samples
    for (const auto& s : results.samples) {
        auto& [gpu, cpu] = bySeries[s.config][s.series];
        gpu.push_back(static_cast<float>(s.gpuMs));
        cpu.push_back(static_cast<float>(s.cpuMs));
        if (s.series == baseline.series) compared[s.config].push_back(s.gpuMs);
        if (s.series != PassTimer::kFrameSeries &&
            std::find(summary.passes.begin(), summary.passes.end(), s.series) == summary.passes.end()) {
            // Keep pipeline order: a span follows its pass, a pass seen late goes last.
            summary.passes.push_back(s.series);
        }
    }
    for (const auto& c : results.configs) {
        BenchSummaryRow r;
        r.config = c.config.index;
        for (const auto& name : results.seriesOf(r.config)) {
            const auto& [gpu, cpu] = bySeries[r.config][name];
            r.series.push_back({name, computeStats(gpu), computeStats(cpu)});
        }
        // The frame total last, whatever order the samples came in.
        std::stable_partition(r.series.begin(), r.series.end(),
                              [](const BenchSeriesStats& s) { return s.series != PassTimer::kFrameSeries; });
        if (!baseline.axis.empty()) {
            for (const auto& other : results.configs)
                if (axisValue(results, other.config, baseline.axis) == baseline.value &&
                    sameExcept(results, other.config, c.config, baseline.axis)) {
                    r.baseline = other.config.index;
                    break;
                }
            if (r.baseline >= 0 && !compared[r.config].empty() && !compared[r.baseline].empty())
                r.ratio = bootstrapRatioOfMedians(compared[r.config], compared[r.baseline], resamples,
                                                  seed + static_cast<std::uint64_t>(r.config));
            if (r.baseline >= 0 && baseline.series != PassTimer::kFrameSeries) {
                auto frames = [&](int config) {
                    const auto& bySeriesOf = bySeries[config];
                    auto it = bySeriesOf.find(PassTimer::kFrameSeries);
                    std::vector<double> v;
                    if (it != bySeriesOf.end())
                        for (float f : it->second.first) v.push_back(f);
                    return v;
                };
                const std::vector<double> mine = frames(r.config), theirs = frames(r.baseline);
                if (!mine.empty() && !theirs.empty())
                    r.frameRatio = bootstrapRatioOfMedians(mine, theirs, resamples, seed + static_cast<std::uint64_t>(r.config));
            }
        }
        summary.rows.push_back(std::move(r));
    }
    return summary;
}

namespace {

// What lighting.strategy=auto chose, from the lighting pass's statistics line ("... ; auto picked tiled: ...").
std::string autoPicked(const BenchConfigResult& c) {
    auto it = c.stats.find("lighting");
    if (it == c.stats.end()) return {};
    const std::string key = "auto picked ";
    const size_t at = it->second.find(key);
    if (at == std::string::npos) return {};
    const size_t from = at + key.size();
    return it->second.substr(from, it->second.find_first_of(":;", from) - from);
}

}  // namespace

std::string lppText(double lpp) {
    if (std::isfinite(lpp) && lpp != 0.0 && std::fabs(lpp) < 0.005) {
        char text[32];
        std::snprintf(text, sizeof(text), "%.2g", lpp);
        return text;
    }
    return fixed(lpp, 2);
}

std::string mainTableCaption(const BenchSummary& summary, int resamples) {
    const bool frame = summary.baseline.series == PassTimer::kFrameSeries;
    std::string c = "Per configuration: LPP = lights per pixel (mean lighting.overlap over all pixels; LPP lit: over "
                    "the lit surface pixels), frames = counted frames, GPU ms = median/min/max of the whole frame's GPU "
                    "time over them, CPU ms = median CPU time to issue it";
    if (!summary.baseline.axis.empty()) {
        c += frame ? "; ratio = this configuration's median frame GPU ms / its baseline's"
                   : "; frame ratio = median frame GPU ms / the baseline's; " + summary.baseline.series +
                         " GPU ms median and ratio = the " + summary.baseline.series + " series' own";
        c += "; 95% CI = percentile bootstrap interval of the ratio (" + std::to_string(resamples) + " resamples)";
    }
    return c + ".";
}

namespace {
// ShadowPass::render's span: in the pass that shades the light when the map
// is reused, in the shadows pass itself (all of its time) when it is not.
const std::string kShadowMapsSpan = "/shadow maps";
}  // namespace

std::string passTableCaption() {
    return "GPU median ms per pass and span (PASS/NAME) over the counted frames; frame = the whole frame. "
           "shadows \"(reused: maps in PASS/shadow maps)\": with shadows.reuse_map on, the shadows pass draws no map "
           "(its time is only its set-up); each map is drawn just before its light is shaded, and timed in that span.";
}

std::string markdownTable(const BenchResults& results, const BenchSummary& summary) {
    std::vector<std::string> header = {"config", "size", "lights"};
    header.insert(header.end(), results.knobAxes.begin(), results.knobAxes.end());
    const size_t text = header.size();
    bool anyAuto = false;
    for (const auto& c : results.configs) anyAuto = anyAuto || !autoPicked(c).empty();
    for (const char* h : {"LPP", "LPP lit", "frames", "GPU ms median", "GPU ms min", "GPU ms max", "CPU ms median", "GPU MiB peak"})
        header.emplace_back(h);
    if (anyAuto) header.emplace_back("auto picked");
    const bool frameSeries = summary.baseline.series == PassTimer::kFrameSeries;
    const std::string series = frameSeries ? std::string() : summary.baseline.series + " ";
    const std::string to = summary.baseline.axis.empty() ? "" : " to " + summary.baseline.axis + "=" + summary.baseline.value;
    if (!frameSeries && !summary.baseline.axis.empty()) {
        header.push_back("frame ratio" + to);
        header.emplace_back("frame 95% CI");
        header.push_back(series + "GPU ms median");
    }
    header.push_back(summary.baseline.axis.empty() ? "ratio" : series + "ratio" + to);
    header.emplace_back("95% CI");
    std::string out = row(header) + rule(header, text);
    auto ratioCells = [](std::vector<std::string>& cells, const BenchSummaryRow* r, const RatioInterval& ratio,
                         bool isBaseline) {
        if (isBaseline) {
            cells.emplace_back("1 (baseline)");
            cells.emplace_back("-");
        } else if (r && ratio.valid()) {
            cells.push_back(fixed(ratio.ratio));
            cells.push_back("[" + fixed(ratio.low) + ", " + fixed(ratio.high) + "]");
        } else {
            cells.emplace_back("-");
            cells.emplace_back("-");
        }
    };
    for (const auto& c : results.configs) {
        const BenchSummaryRow* r = summary.find(c.config.index);
        const BenchSeriesStats* f = r ? r->frame() : nullptr;
        std::vector<std::string> cells = {std::to_string(c.config.index), c.config.size(), std::to_string(c.config.lights)};
        cells.insert(cells.end(), c.config.knobValues.begin(), c.config.knobValues.end());
        cells.push_back(lppText(c.lpp));
        cells.push_back(lppText(c.lppLit));
        cells.push_back(std::to_string(f ? f->gpu.count : 0));
        for (double v : {f ? f->gpu.median : NAN, f ? f->gpu.min : NAN, f ? f->gpu.max : NAN, f ? f->cpu.median : NAN})
            cells.push_back(fixed(finiteOrNan(v)));
        cells.push_back(fixed(gpuMemPeakMib(results.samples, c.config.index)));
        if (anyAuto) {
            const std::string picked = autoPicked(c);
            cells.push_back(picked.empty() ? "-" : picked);
        }
        const bool isBaseline = r && r->baseline == r->config;
        if (!frameSeries && !summary.baseline.axis.empty()) {
            ratioCells(cells, r, r ? r->frameRatio : RatioInterval{}, isBaseline && f);
            const BenchSeriesStats* s = r ? r->find(summary.baseline.series) : nullptr;
            cells.push_back(s ? fixed(s->gpu.median) : "-");
        }
        ratioCells(cells, r, r ? r->ratio : RatioInterval{}, isBaseline && r->find(summary.baseline.series));
        out += row(cells);
    }
    return out;
}

std::string markdownPassTable(const BenchResults& results, const BenchSummary& summary) {
    std::vector<std::string> header = {"config", "size", "lights"};
    header.insert(header.end(), results.knobAxes.begin(), results.knobAxes.end());
    const size_t text = header.size();
    // A pass named like an axis column (or "frame"): "<name> (pass)", so no two columns share a name.
    for (const auto& p : summary.passes)
        header.push_back(std::find(header.begin(), header.end(), p) != header.end() || p == PassTimer::kFrameSeries
                             ? p + " (pass)"
                             : p);
    header.emplace_back("frame");
    std::string out = row(header) + rule(header, text);
    for (const auto& c : results.configs) {
        const BenchSummaryRow* r = summary.find(c.config.index);
        std::vector<std::string> cells = {std::to_string(c.config.index), c.config.size(), std::to_string(c.config.lights)};
        cells.insert(cells.end(), c.config.knobValues.begin(), c.config.knobValues.end());
        // With shadows.reuse_map the shadows pass draws no map: each is drawn
        // just before its light is shaded, inside the pass that shades it
        // (its span PASS/shadow maps). Its near-zero time is true, and marked.
        std::string reusedIn;
        for (const auto& p : summary.passes)
            if (p.size() > kShadowMapsSpan.size() && p.compare(p.size() - kShadowMapsSpan.size(), std::string::npos, kShadowMapsSpan) == 0 &&
                p.rfind("shadows/", 0) != 0 && r && r->find(p))
                reusedIn = p;
        for (const auto& p : summary.passes) {
            const BenchSeriesStats* s = r ? r->find(p) : nullptr;
            cells.push_back(s ? fixed(s->gpu.median) + (p == "shadows" && !reusedIn.empty() ? " (reused: maps in " + reusedIn + ")" : "")
                              : "-");
        }
        const BenchSeriesStats* f = r ? r->frame() : nullptr;
        cells.push_back(f ? fixed(f->gpu.median) : "-");
        out += row(cells);
    }
    return out;
}

nlohmann::ordered_json benchResultsJson(const BenchResults& results, const BenchSummary& summary) {
    Json machine = Json::object(), settings = Json::object();
    for (const auto& [k, v] : results.machine) machine[k] = v;
    for (const auto& [k, v] : results.settings) settings[k] = v;
    Json axes = Json::array();
    for (const auto& name : axisNames(results)) axes.push_back({{"name", name}, {"values", axisValues(results, name)}});

    std::map<int, Json> samples;
    for (const auto& s : results.samples) {
        Json& list = samples[s.config];
        if (list.is_null()) list = Json::array();
        if (list.empty() || list.back()["sample"] != s.sample)
            list.push_back({{"sample", s.sample}, {"seq", s.seq}, {"frame", s.frame}, {"gpu_ms", Json::object()},
                            {"cpu_ms", Json::object()}});
        list.back()["gpu_ms"][s.series] = rounded(s.gpuMs);
        list.back()["cpu_ms"][s.series] = rounded(s.cpuMs);
        if (!s.counts.measured()) continue;
        Json c = Json::object();
        for (int i = 0; i < PassCounts::kCount; ++i)
            if (s.counts[i] >= 0) c[PassCounts::name(i)] = s.counts[i];
        list.back()["counters"][s.series] = c;
    }
    std::map<std::pair<int, std::string>, std::vector<double>> gpuOf;
    for (const auto& s : results.samples) gpuOf[{s.config, s.series}].push_back(s.gpuMs);
    Json configs = Json::array();
    for (const auto& c : results.configs) {
        Json knobs = Json::object();
        for (size_t k = 0; k < results.knobAxes.size(); ++k) knobs[results.knobAxes[k]] = c.config.knobValues[k];
        Json j = {{"config", c.config.index}, {"size", c.config.size()}, {"width", c.config.width},
                  {"height", c.config.height}, {"lights", c.config.lights}, {"knobs", knobs},
                  {"lpp", optionalNumber(c.lpp)}, {"lpp_lit", optionalNumber(c.lppLit)},
                  {"gpu_mem_peak_mib", optionalNumber(gpuMemPeakMib(results.samples, c.config.index))}};
        const BenchSummaryRow* r = summary.find(c.config.index);
        Json series = Json::object();
        if (r) {
            const BenchSeriesStats* f = r->frame();
            j["frames"] = f ? f->gpu.count : 0;
            for (const auto& s : r->series) {
                // The GPU median's bootstrap 95% interval (the records' "timings with intervals").
                Json gpu = msJson(s.gpu);
                const MedianInterval m = bootstrapMedian(gpuOf[{c.config.index, s.series}], 1000,
                                                         12345 + static_cast<std::uint64_t>(c.config.index));
                if (m.valid()) gpu["ci95"] = {rounded(m.low), rounded(m.high)};
                series[s.series] = {{"gpu_ms", gpu}, {"cpu_ms", msJson(s.cpu)}};
            }
            j["series"] = series;
            j["baseline_config"] = r->baseline >= 0 ? Json(r->baseline) : Json(nullptr);
            if (r->baseline == r->config && r->find(summary.baseline.series)) {
                // The baseline against itself: 1, with no interval (as the table says).
                j["ratio"] = 1.0;
                j["ci95"] = nullptr;
            } else if (r->ratio.valid()) {
                j["ratio"] = rounded(r->ratio.ratio);
                j["ci95"] = {rounded(r->ratio.low), rounded(r->ratio.high)};
            } else {
                j["ratio"] = nullptr;
                j["ci95"] = nullptr;
            }
        }
        if (!c.stats.empty()) j["stats"] = c.stats;
        j["samples"] = samples.count(c.config.index) ? samples[c.config.index] : Json::array();
        configs.push_back(std::move(j));
    }
    Json baseline = summary.baseline.axis.empty()
                        ? Json(nullptr)
                        : Json{{"axis", summary.baseline.axis},
                               {"value", summary.baseline.value},
                               {"series", summary.baseline.series}};
    Json out = {{"tool", "deferred-workbench bench"}, {"machine", machine}, {"settings", settings},
                {"axes", axes}, {"baseline", baseline}, {"configs", configs}};
    // Counters are exact: the same in every counted frame of a configuration, or the first that is not.
    if (results.counted) out["counters_mismatch"] = results.counterMismatch();
    return out;
}

const nlohmann::json& benchSummaryOf(const nlohmann::json& file) {
    if (file.is_object() && file.contains("results") && file["results"].is_object()) return file["results"];
    return file;
}

}  // namespace dw
