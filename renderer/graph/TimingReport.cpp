#include "renderer/graph/TimingReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "renderer/Error.h"

namespace dw {

using Json = nlohmann::ordered_json;

namespace {

// The samples of frames first..last only: the timer's history also holds the
// warm-up frames (and, in the window, frames long gone).
void statsOver(const PassTimer& timer, const std::string& name, std::uint64_t first, std::uint64_t last, TimingRow& row) {
    std::vector<float> gpu, cpu;
    if (const PassTimer::Series* s = timer.find(name))
        for (const TimingSample& t : s->samples)
            if (t.frame >= first && t.frame <= last) {
                gpu.push_back(t.gpuMs);
                cpu.push_back(t.cpuMs);
            }
    row.gpu = computeStats(std::move(gpu));
    row.cpu = computeStats(std::move(cpu));
}

// The last counted frame's counters, and the first counted frame that differs from them.
void countsOver(const PassTimer& timer, const std::string& name, std::uint64_t first, std::uint64_t last, TimingRow& row) {
    const PassTimer::Series* s = timer.find(name);
    if (!s) return;
    const TimingSample* newest = nullptr;
    for (const TimingSample& t : s->samples)
        if (t.frame >= first && t.frame <= last) newest = &t;
    if (!newest || !newest->counts.measured()) return;
    row.counts = newest->counts;
    for (const TimingSample& t : s->samples)
        if (t.frame >= first && t.frame <= last && !(t.counts == row.counts)) {
            row.countsDiffer = true;
            row.differingFrame = t.frame;
            return;
        }
}

std::string countText(std::int64_t v) { return v < 0 ? std::string("-") : std::to_string(v); }

Json countsJson(const PassCounts& c) {
    Json j = Json::object();
    for (int i = 0; i < PassCounts::kCount; ++i)
        if (c[i] >= 0) j[PassCounts::name(i)] = c[i];
    return j;
}

// Microsecond resolution: the float samples' further digits are noise.
double ms(float v) { return std::round(static_cast<double>(v) * 1e4) / 1e4; }

Json msJson(const TimingStats& s) {
    return {{"median", ms(s.median)}, {"min", ms(s.min)}, {"max", ms(s.max)}, {"mean", ms(s.mean)}};
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string q = "\"";
    for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string formatted(const char* format, auto... args) {
    char line[256];
    std::snprintf(line, sizeof(line), format, args...);
    return line;
}

}  // namespace

TimingReport TimingReport::build(PassTimer& timer, const FrameReport& last, std::uint64_t firstFrame, int warmup) {
    timer.collect(true);
    TimingReport r;
    r.warmup_ = warmup;
    const std::uint64_t lastFrame = last.frameIndex;
    for (const PassRecord& rec : last.passes) {
        TimingRow row;
        row.kind = TimingRow::Kind::Pass;
        row.series = rec.name;
        row.pass = rec.name;
        row.ran = rec.ran;
        row.reason = rec.reason;
        row.stats = rec.stats;
        if (rec.ran) statsOver(timer, rec.name, firstFrame, lastFrame, row);
        if (rec.ran) countsOver(timer, rec.name, firstFrame, lastFrame, row);
        r.rows_.push_back(row);
        if (!rec.ran) continue;
        // Parts of the pass with their own spans (e.g. lighting/shadow maps).
        for (const auto& series : timer.series()) {
            if (series.name.rfind(rec.name + "/", 0) != 0) continue;
            TimingRow span;
            span.kind = TimingRow::Kind::Span;
            span.series = series.name;
            span.pass = rec.name;
            statsOver(timer, series.name, firstFrame, lastFrame, span);
            if (span.gpu.count > 0) r.rows_.push_back(span);
        }
    }
    TimingRow total;
    total.kind = TimingRow::Kind::Total;
    total.series = PassTimer::kFrameSeries;
    statsOver(timer, PassTimer::kFrameSeries, firstFrame, lastFrame, total);
    countsOver(timer, PassTimer::kFrameSeries, firstFrame, lastFrame, total);
    r.rows_.push_back(total);
    return r;
}

const TimingRow* TimingReport::find(const std::string& series) const {
    for (const auto& row : rows_)
        if (row.series == series) return &row;
    return nullptr;
}

std::string TimingReport::table() const {
    std::string out = formatted("timings over %d frame(s)", countedFrames());
    out += warmup_ > 0 ? formatted(" after %d warm-up frame(s)\n", warmup_) : std::string("\n");
    out += formatted("%-16s %14s %14s %14s %14s  %s\n", "pass", "GPU median ms", "GPU min ms", "GPU max ms", "CPU median ms",
                     "frames");
    auto numbers = [](const TimingRow& row) {
        return formatted(" %14.3f %14.3f %14.3f %14.3f  %d\n", row.gpu.median, row.gpu.min, row.gpu.max, row.cpu.median,
                         row.gpu.count);
    };
    for (size_t i = 0; i < rows_.size(); ++i) {
        const TimingRow& row = rows_[i];
        if (row.kind == TimingRow::Kind::Total) {
            out += formatted("%-16s", "frame (total)") + numbers(row);
        } else if (!row.ran) {
            out += formatted("%-16s %14s  (skipped: %s)\n", row.series.c_str(), "-", row.reason.c_str());
        } else {
            out += formatted("%-16s", row.series.c_str()) + numbers(row);
            for (; i + 1 < rows_.size() && rows_[i + 1].kind == TimingRow::Kind::Span; ++i) {
                const TimingRow& span = rows_[i + 1];
                out += formatted("  %-14s", span.series.substr(span.pass.size() + 1).c_str()) + numbers(span);
            }
            if (!row.stats.empty()) out += "  (" + row.stats + ")\n";
        }
    }
    return out + countersTable();
}

std::string TimingReport::countersTable() const {
    if (!counted()) return {};
    const TimingRow* differs = nullptr;
    for (const auto& row : rows_)
        if (row.countsDiffer && !differs) differs = &row;
    std::string out = "cost counters per frame (exact; ";
    out += differs ? formatted("they differ between frames: frame %llu's %s differ from the last frame's, shown)\n",
                               static_cast<unsigned long long>(differs->differingFrame), differs->series.c_str())
                   : formatted("the same in all %d counted frame(s))\n", countedFrames());
    out += formatted("%-16s", "pass");
    for (int i = 0; i < PassCounts::kCount; ++i) out += formatted(" %14s", PassCounts::name(i));
    out += "\n";
    for (const auto& row : rows_) {
        if (row.kind == TimingRow::Kind::Span || !row.counts.measured()) continue;
        out += formatted("%-16s", row.kind == TimingRow::Kind::Total ? "frame (total)" : row.series.c_str());
        for (int i = 0; i < PassCounts::kCount; ++i) out += formatted(" %14s", countText(row.counts[i]).c_str());
        out += "\n";
    }
    return out;
}

std::string TimingReport::json() const {
    Json passes = Json::array();
    for (const auto& row : rows_) {
        if (row.kind == TimingRow::Kind::Pass) {
            Json p = {{"name", row.series}, {"ran", row.ran}};
            if (!row.ran) {
                p["reason"] = row.reason;
            } else {
                if (!row.stats.empty()) p["stats"] = row.stats;
                p["frames"] = row.gpu.count;
                p["gpu_ms"] = msJson(row.gpu);
                p["cpu_ms"] = msJson(row.cpu);
                p["spans"] = Json::array();
                if (row.counts.measured()) p["counters"] = countsJson(row.counts);
            }
            passes.push_back(p);
        } else if (row.kind == TimingRow::Kind::Span) {
            passes.back()["spans"].push_back({{"name", row.series.substr(row.pass.size() + 1)},
                                              {"series", row.series},
                                              {"frames", row.gpu.count},
                                              {"gpu_ms", msJson(row.gpu)},
                                              {"cpu_ms", msJson(row.cpu)}});
        }
    }
    Json j = {{"frames", countedFrames()},
              {"warmup", warmup_},
              {"passes", passes},
              {"total", {{"frames", total().gpu.count}, {"gpu_ms", msJson(total().gpu)}, {"cpu_ms", msJson(total().cpu)}}}};
    if (counted()) {
        j["total"]["counters"] = countsJson(total().counts);
        j["counters_same_every_frame"] = std::none_of(rows_.begin(), rows_.end(), [](const TimingRow& r) { return r.countsDiffer; });
    }
    return j.dump(2) + "\n";
}

std::string TimingReport::csvHeader() {
    return "series,kind,ran,frames,gpu_median_ms,gpu_min_ms,gpu_max_ms,gpu_mean_ms,"
           "cpu_median_ms,cpu_min_ms,cpu_max_ms,cpu_mean_ms";
}

std::vector<std::string> TimingReport::csvRows() const {
    std::vector<std::string> lines;
    for (const auto& row : rows_) {
        const char* kind = row.kind == TimingRow::Kind::Pass ? "pass" : row.kind == TimingRow::Kind::Span ? "span" : "total";
        std::string line = csvField(row.series) + "," + kind + "," + (row.ran ? "1" : "0") + ",";
        if (!row.ran) {
            lines.push_back(line + "0,,,,,,,,");
            continue;
        }
        line += formatted("%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f", row.gpu.count, row.gpu.median, row.gpu.min, row.gpu.max,
                          row.gpu.mean, row.cpu.median, row.cpu.min, row.cpu.max, row.cpu.mean);
        lines.push_back(line);
    }
    return lines;
}

std::string TimingReport::csv() const {
    std::string out = csvHeader() + "\n";
    for (const auto& line : csvRows()) out += line + "\n";
    return out;
}

void TimingReport::write(const std::string& path) const {
    std::ofstream f(path, std::ios::trunc);
    if (!f) throw FileError(path, "cannot write the timings");
    f << (std::filesystem::path(path).extension() == ".json" ? json() : csv());
    if (!f.flush()) throw FileError(path, "writing the timings failed");
}

}  // namespace dw
