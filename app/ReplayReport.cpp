#include "app/ReplayReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

namespace dw::replay {

namespace {

void printTooFew(size_t now, size_t old) {
    std::printf("  %s (%zu and %zu frames, %zu needed on each side)", kTooFewForInterval.c_str(), old, now,
                kMinIntervalSamples);
}

// Below this a median prints as 0.000 ms: the timer's noise, not a time to divide by.
constexpr double kZeroMs = 0.0005;

// "a, b, c and N more": at most `shown` names.
std::string someOf(const std::vector<std::string>& names, size_t shown = 3) {
    std::string out;
    for (size_t i = 0; i < names.size() && i < shown; ++i) out += (i ? ", " : "") + names[i];
    if (names.size() > shown) out += " and " + std::to_string(names.size() - shown) + " more";
    return out;
}

std::string pointLabel(const TradeoffTable& t, const TradeoffRow& r) {
    std::string label = "point " + std::to_string(r.point) + " camera " + r.camera;
    for (size_t a = 0; a < t.axes.size() && a < r.axisValues.size(); ++a) label += ", " + t.axes[a] + "=" + r.axisValues[a];
    return label;
}

// Errors are deterministic on one machine (the same frames, the same
// reference from the cache): equal to 1e-9 relative, or both not measured.
bool sameError(double a, double b) {
    if (!std::isfinite(a) || !std::isfinite(b)) return std::isfinite(a) == std::isfinite(b);
    return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

// One row old against new; returns whether the time moved (`same` the error).
bool printRowComparison(const std::string& label, const TradeoffRow& b, const TradeoffRow& r, size_t framesBefore,
                        size_t framesAfter, bool& same) {
    same = sameError(b.error, r.error);
    // The difference of the medians, with the interval the two 95%
    // intervals allow (new low - old high, new high - old low).
    const double diff = r.frameGpuMs - b.frameGpuMs, lo = r.frameGpuMsLo - b.frameGpuMsHi,
                 hi = r.frameGpuMsHi - b.frameGpuMsLo;
    const double ratioLo = b.frameGpuMsHi > 0 ? r.frameGpuMsLo / b.frameGpuMsHi : NAN;
    const double ratioHi = b.frameGpuMsLo > 0 ? r.frameGpuMsHi / b.frameGpuMsLo : NAN;
    const bool interval = enoughForInterval(framesBefore) && enoughForInterval(framesAfter);
    const bool timeMoved = interval && std::isfinite(ratioLo) && std::isfinite(ratioHi) &&
                           (ratioLo > kTimingBandHigh || ratioHi < kTimingBandLow);
    std::printf("%s: %s %.6g -> %.6g (%s); frame gpu median %.3f -> %.3f ms, difference %+.3f", label.c_str(),
                r.metric.c_str(), b.error, r.error, same ? "same" : "differs", b.frameGpuMs, r.frameGpuMs, diff);
    if (interval)
        std::printf(" [%+.3f, %+.3f]%s", lo, hi, timeMoved ? " (moved)" : "");
    else
        printTooFew(framesAfter, framesBefore);
    std::printf("\n");
    return timeMoved;
}

// "[lo, hi]" of an interval, as %.6g.
std::string interval(double lo, double hi) {
    char text[80];
    std::snprintf(text, sizeof(text), "[%.6g, %.6g]", lo, hi);
    return text;
}

// Whether a time's new 95% interval lies wholly outside the band of its old
// one (new low / old high above kTimingBandHigh, or new high / old low below
// kTimingBandLow): the rule the frame time uses; never without intervals.
bool intervalMoved(double oldLo, double oldHi, double newLo, double newHi, bool enough) {
    const double ratioLo = oldHi > 0 ? newLo / oldHi : NAN, ratioHi = oldLo > 0 ? newHi / oldLo : NAN;
    return enough && std::isfinite(ratioLo) && std::isfinite(ratioHi) &&
           (ratioLo > kTimingBandHigh || ratioHi < kTimingBandLow);
}

// "1, 2" of point numbers; "1 (error), 3 (both)" of ties.
std::string pointList(const std::vector<int>& points) {
    std::string s;
    for (int p : points) s += (s.empty() ? "" : ", ") + std::to_string(p);
    return s.empty() ? "none" : s;
}
std::string tieList(const std::vector<std::pair<int, std::string>>& ties) {
    std::string s;
    for (const auto& [p, axes] : ties) s += (s.empty() ? "" : ", ") + std::to_string(p) + " (" + axes + ")";
    return s.empty() ? "none" : s;
}

}  // namespace

std::string shortHash(const std::string& h) { return h.empty() ? "unreadable" : h.substr(0, 16); }

void ChangedInputs::print() const {
    if (names.empty()) {
        std::printf("inputs changed: none\n");
        return;
    }
    std::string all;
    for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
    std::printf("inputs changed (%zu): %s\n", names.size(), all.c_str());
}

void reportFileChanges(const std::string& what, const std::vector<SceneFileChange>& changes,
                       const std::string& removedWhy, ChangedInputs& inputs, const std::string& addedWhy) {
    for (const SceneFileChange& c : changes) {
        if (c.kind == SceneFileChange::Kind::Changed)
            std::printf("%s changed: %s (sha256 %s -> %s)\n", what.c_str(), c.path.c_str(),
                        shortHash(c.oldSha256).c_str(), shortHash(c.newSha256).c_str());
        else if (c.kind == SceneFileChange::Kind::Added)
            std::printf("%s added: %s (sha256 %s; %s)\n", what.c_str(), c.path.c_str(), shortHash(c.newSha256).c_str(),
                        addedWhy.c_str());
        else
            std::printf("%s removed: %s (recorded sha256 %s; %s)\n", what.c_str(), c.path.c_str(),
                        shortHash(c.oldSha256).c_str(), removedWhy.c_str());
        inputs.add(what + " " + c.path);
    }
}

void reportSelfCheck(const ExperimentRecord& record, const std::string& who, ChangedInputs& inputs) {
    const ExperimentRecord::SelfCheck& c = record.selfCheck;
    if (!c.hashed) {
        std::printf("%srecord holds no sha256 of its own (written before records kept one)\n", who.c_str());
        return;
    }
    if (c.inputsEdited) {
        std::printf("%srecord edited: its inputs no longer match the sha256 written with them (record_sha256.inputs "
                    "%s, now %s)\n",
                    who.c_str(), shortHash(c.writtenInputs).c_str(), shortHash(c.nowInputs).c_str());
        inputs.add(who + "record inputs edited");
    }
    if (c.resultsEdited) {
        std::printf("%srecord edited: its results no longer match the sha256 written with them "
                    "(record_sha256.results %s, now %s)\n",
                    who.c_str(), shortHash(c.writtenResults).c_str(), shortHash(c.nowResults).c_str());
        inputs.add(who + "record results edited");
    }
}

bool timingMoved(const RatioInterval& r) { return r.valid() && (r.low > kTimingBandHigh || r.high < kTimingBandLow); }

// An old median that prints as 0.000 ms has no ratio ("n/a (0 ms)"); an old
// series whose resamples reach a 0 ms median has a ratio but no upper bound.
RatioInterval printRatio(const std::vector<double>& now, const std::vector<double>& old, int resamples, bool markMoved) {
    if (old.empty() || now.empty()) {
        std::printf("  n/a (no frames)");
        return {};
    }
    const double before = median(old), after = median(now);
    if (!(before >= kZeroMs)) {
        std::printf("  n/a (0 ms)");
        return {};
    }
    if (!enoughForInterval(now.size()) || !enoughForInterval(old.size())) {
        printTooFew(now.size(), old.size());
        return {};
    }
    const RatioInterval r = bootstrapRatioOfMedians(now, old, resamples);
    if (!r.valid() || r.resamples < resamples || !std::isfinite(r.low) || !std::isfinite(r.high)) {
        std::printf("  x%.3f, no interval (0 ms medians among the old frames' resamples)", after / before);
        return {};
    }
    std::printf("  x%.3f [%.3f, %.3f]%s", r.ratio, r.low, r.high, markMoved && timingMoved(r) ? " (moved)" : "");
    return r;
}

void compareTimings(const std::vector<RecordedSeries>& old, const std::vector<RecordedSeries>& now) {
    std::map<std::string, const RecordedSeries*> oldSeries;
    for (const auto& s : old) oldSeries[s.name] = &s;
    for (const auto& s : now) {
        const auto it = oldSeries.find(s.name);
        if (it == oldSeries.end()) continue;
        std::printf("timing %-28s gpu median %9.3f -> %9.3f ms", s.name.c_str(), median(it->second->gpuMs), median(s.gpuMs));
        printRatio(s.gpuMs, it->second->gpuMs);
        std::printf("\n");
    }
}

int compareCounters(const std::vector<RecordedSeries>& old, const std::vector<RecordedSeries>& now) {
    std::map<std::string, const RecordedSeries*> oldSeries;
    for (const auto& s : old) oldSeries[s.name] = &s;
    int compared = 0;
    std::string moved;
    for (const auto& s : now) {
        const auto it = oldSeries.find(s.name);
        if (it == oldSeries.end()) continue;
        for (int i = 0; i < PassCounts::kCount; ++i) {
            const std::int64_t a = it->second->counts[i], b = s.counts[i];
            if (a < 0 || b < 0) continue;
            ++compared;
            if (a != b)
                moved += (moved.empty() ? "" : ", ") + std::string(PassCounts::name(i)) + "." + s.name + " " +
                         std::to_string(a) + " -> " + std::to_string(b);
        }
    }
    if (compared == 0) return 0;
    if (moved.empty()) {
        std::printf("counters: the same (%d compared, exactly)\n", compared);
        return 0;
    }
    std::printf("counters: moved: %s\n", moved.c_str());
    return 1;
}

int imageVerdict(const std::string& oldSha, const std::string& newSha) {
    if (newSha == oldSha) {
        std::printf("image: identical\n");
        return 0;
    }
    std::printf("image: differs (sha256 %s -> %s)\n", oldSha.c_str(), newSha.c_str());
    return 1;
}

std::map<int, RecordedConfig> recordedConfigs(const nlohmann::ordered_json& res, const std::string& series) {
    std::map<int, RecordedConfig> out;
    if (!res.contains("configs") || !res["configs"].is_array()) return out;
    for (const auto& c : res["configs"]) {
        if (!c.is_object() || !c.contains("config") || !c["config"].is_number_integer()) continue;
        RecordedConfig& r = out[c["config"].get<int>()];
        if (c.contains("size") && c["size"].is_string()) r.label = c["size"].get<std::string>();
        if (c.contains("lights") && c["lights"].is_number_integer())
            r.label += ", " + std::to_string(c["lights"].get<long long>()) + " lights";
        if (c.contains("knobs") && c["knobs"].is_object())
            for (const auto& [k, v] : c["knobs"].items()) r.label += ", " + k + "=" + (v.is_string() ? v.get<std::string>() : v.dump());
        if (c.contains("lpp") && c["lpp"].is_number()) r.lpp = c["lpp"].get<double>();
        if (c.contains("gpu_mem_peak_mib") && c["gpu_mem_peak_mib"].is_number())
            r.gpuMemPeakMib = c["gpu_mem_peak_mib"].get<double>();
        if (c.contains("samples") && c["samples"].is_array())
            for (const auto& s : c["samples"])
                if (s.is_object() && s.contains("gpu_ms") && s["gpu_ms"].is_object() && s["gpu_ms"].contains(series) &&
                    s["gpu_ms"][series].is_number())
                    r.gpuMs.push_back(s["gpu_ms"][series].get<double>());
    }
    return out;
}

BenchComparison compareBench(std::map<int, RecordedConfig> before, const std::vector<std::pair<int, RecordedConfig>>& after,
                             const std::string& series, int resamples) {
    BenchComparison out;
    out.series = series;
    for (const auto& [i, a] : after) {
        const auto it = before.find(i);
        if (it == before.end()) {
            std::printf("config %d (%s): not in the record\n", i, a.label.c_str());
            out.notInRecord.push_back("config " + std::to_string(i) + " (" + a.label + ")");
            continue;
        }
        const RecordedConfig& b = it->second;
        std::printf("config %d (%s): %s gpu median %9.3f -> %9.3f ms", i, a.label.c_str(), series.c_str(),
                    median(b.gpuMs), median(a.gpuMs));
        const RatioInterval r = printRatio(a.gpuMs, b.gpuMs, resamples, true);
        const bool bothLpp = std::isfinite(b.lpp) && std::isfinite(a.lpp);
        // The JSON holds LPP rounded to 6 significant digits.
        const bool sameLpp = (!std::isfinite(b.lpp) && !std::isfinite(a.lpp)) ||
                             (bothLpp && std::abs(b.lpp - a.lpp) <= 1e-5 * std::max(1.0, std::abs(b.lpp)));
        if (bothLpp) std::printf("  lpp %.4f -> %.4f", b.lpp, a.lpp);
        // Peak GPU memory is exact (logical bytes): compared to the byte.
        if (std::isfinite(b.gpuMemPeakMib) && std::isfinite(a.gpuMemPeakMib)) {
            std::printf("  gpu memory peak %.2f -> %.2f MiB%s", b.gpuMemPeakMib, a.gpuMemPeakMib,
                        b.gpuMemPeakMib == a.gpuMemPeakMib ? "" : " (differs)");
            if (b.gpuMemPeakMib != a.gpuMemPeakMib) ++out.memoryDiffer;
        } else {
            ++out.memoryUnknown;
        }
        std::printf("\n");
        if (!sameLpp) ++out.lppDiffer;
        if (timingMoved(r)) ++out.moved;
        ++out.compared;
        before.erase(it);
    }
    for (const auto& [i, b] : before) {
        std::printf("config %d: in the record, not run again\n", i);
        out.notRunAgain.push_back("config " + std::to_string(i));
    }
    return out;
}

int BenchComparison::verdict() const {
    // A record written before the memory column: said, not counted against it.
    const std::string memory = memoryUnknown > 0 ? ", peak GPU memory not compared in " + std::to_string(memoryUnknown) +
                                                       " (not in both records)"
                                                 : ", peak GPU memory equal";
    if (notInRecord.empty() && notRunAgain.empty() && lppDiffer == 0 && moved == 0 && memoryDiffer == 0) {
        std::printf("bench: the same (%zu configurations, lights per pixel equal%s, no %s timing outside [%.2f, %.2f] "
                    "with its 95%% interval)\n",
                    compared, memory.c_str(), series.c_str(), kTimingBandLow, kTimingBandHigh);
        return 0;
    }
    // A record cut short (its results lack configurations of the grid it declares) names them.
    std::string missing;
    if (!notInRecord.empty())
        missing += std::to_string(notInRecord.size()) + " configuration(s) not in the record: " + someOf(notInRecord) + "; ";
    if (!notRunAgain.empty())
        missing += std::to_string(notRunAgain.size()) + " in the record, not run again: " + someOf(notRunAgain) + "; ";
    std::printf("bench: differs (%s%d configuration(s) with other lights per pixel, %d with another peak GPU memory, "
                "%d with %s timing moved beyond [%.2f, %.2f])\n",
                missing.c_str(), lppDiffer, memoryDiffer, moved, series.c_str(), kTimingBandLow, kTimingBandHigh);
    return 1;
}

namespace {
// The counters of `now` that differ from `old`'s ("" when none): those both measured.
// `notHere` / `notRecorded` gather the counters only the record / only this run measured.
std::string movedCounters(const TradeoffTable& before, const TradeoffRow& old, const TradeoffTable& after,
                          const TradeoffRow& now, std::string& notHere, std::string& notRecorded) {
    std::string moved;
    auto check = [&](const std::string& span, int counter, double a, double b) {
        if (std::isnan(a) != std::isnan(b)) {
            const std::string name = PassCounts::name(counter) + (span.empty() ? "" : "." + span);
            std::string& list = std::isnan(b) ? notHere : notRecorded;
            list += (list.empty() ? "" : ", ") + name;
            return;
        }
        if (std::isnan(a) || a == b) return;
        char line[160];
        std::snprintf(line, sizeof(line), "%s%s%s %.17g -> %.17g", PassCounts::name(counter), span.empty() ? "" : ".",
                      span.c_str(), a, b);
        moved += (moved.empty() ? "" : ", ") + std::string(line);
    };
    for (int i = 0; i < PassCounts::kCount; ++i) {
        check("", i, old.frameCounts[static_cast<size_t>(i)], now.frameCounts[static_cast<size_t>(i)]);
        std::vector<std::string> passes = after.passes;
        for (const auto& pass : before.passes)
            if (std::find(passes.begin(), passes.end(), pass) == passes.end()) passes.push_back(pass);
        for (const auto& pass : passes) check(pass, i, before.passCount(old, pass, i), after.passCount(now, pass, i));
    }
    return moved;
}

// Whether `v` lies outside [lo, hi] beyond the records' rounding (both finite).
bool outside(double v, double lo, double hi) {
    if (!std::isfinite(v) || !std::isfinite(lo) || !std::isfinite(hi)) return false;
    const double slack = 1e-6 * std::max({1.0, std::abs(lo), std::abs(hi)});
    return v < lo - slack || v > hi + slack;
}

// A recorded median outside its own recorded 95% interval (frame_gpu_ms,
// time_ms) cannot come from a run: the record was edited or is corrupt.
bool recordInconsistent(const std::string& label, const TradeoffRow& b) {
    bool bad = false;
    auto check = [&](const char* column, double v, double lo, double hi) {
        if (!outside(v, lo, hi)) return;
        std::printf("%s: record inconsistent: %s median %.3f ms outside its own recorded 95%% CI %s (edited or corrupt)\n",
                    label.c_str(), column, v, interval(lo, hi).c_str());
        bad = true;
    };
    check("frame_gpu_ms", b.frameGpuMs, b.frameGpuMsLo, b.frameGpuMsHi);
    check("time_ms", b.timeMs, b.timeMsLo, b.timeMsHi);
    return bad;
}

// Each term of a --time sum (a+b): its gpu_ms.<pass> median old against new.
// The CSV holds no interval of a term, so a term counts as moved when its
// ratio lies outside [0.8, 1.25] and it moved by more than the two sums'
// 95% intervals are wide together (the noise the sum itself shows).
bool termsMoved(const std::string& label, const TradeoffTable& before, const TradeoffRow& b, const TradeoffTable& after,
                const TradeoffRow& r, bool enough) {
    const std::vector<std::string> terms = TradeoffTable::timeTerms(after.time);
    if (terms.size() < 2 || !enough) return false;
    const double noise = (b.timeMsHi - b.timeMsLo) + (r.timeMsHi - r.timeMsLo);
    std::string moved;
    for (const auto& term : terms) {
        const double was = before.passGpuMs(b, term), now = after.passGpuMs(r, term);
        if (!std::isfinite(was) || !std::isfinite(now) || !std::isfinite(noise) || !(was > 0)) continue;
        const double ratio = now / was;
        if ((ratio >= kTimingBandLow && ratio <= kTimingBandHigh) || std::abs(now - was) <= noise) continue;
        char text[160];
        std::snprintf(text, sizeof(text), "gpu_ms.%s median %.3f -> %.3f ms (x%.3f)", term.c_str(), was, now, ratio);
        moved += (moved.empty() ? "" : ", ") + std::string(text);
    }
    if (moved.empty()) return false;
    std::printf("%s: time term moved: %s (rule: ratio outside [%.2f, %.2f] and a change wider than the two %s "
                "intervals together)\n",
                label.c_str(), moved.c_str(), kTimingBandLow, kTimingBandHigh, after.time.c_str());
    return true;
}

// What the front used beyond the error, the frame time and the counters, one
// row old against new, each moved number on a line naming its column and the
// rule: the error's interval exactly (as the error), --time's span with its
// interval (the frame time's rule), and the row's front, dominated_by,
// tied_with and pick (counted only where the front's inputs are exact: a
// counter --cost; with GPU ms they follow the times' noise and are said, not counted).
void compareFrontInputs(const std::string& label, const TradeoffTable& before, const TradeoffRow& b,
                        const TradeoffTable& after, const TradeoffRow& r, bool enough, TradeoffComparison& out) {
    if (!sameError(b.errorLo, r.errorLo) || !sameError(b.errorHi, r.errorHi)) {
        std::printf("%s: error_ci95 %s -> %s (moved; rule: equal to 1e-9 relative, as the error)\n", label.c_str(),
                    interval(b.errorLo, b.errorHi).c_str(), interval(r.errorLo, r.errorHi).c_str());
        ++out.intervalDiffer;
    }
    if (before.time != "frame" && before.time == after.time) {
        const bool moved = intervalMoved(b.timeMsLo, b.timeMsHi, r.timeMsLo, r.timeMsHi, enough);
        std::printf("%s: time_ms (%s) median %.3f -> %.3f ms, 95%% CI %s -> %s%s\n", label.c_str(), after.time.c_str(),
                    b.timeMs, r.timeMs, interval(b.timeMsLo, b.timeMsHi).c_str(), interval(r.timeMsLo, r.timeMsHi).c_str(),
                    moved ? " (moved)" : !enough ? " (too few frames for an interval: not tested)" : "");
        if (moved) ++out.timeMoved;
        if (termsMoved(label, before, b, after, r, enough)) ++out.termsMoved;
    }
    std::string front;
    auto add = [&front](const std::string& column, const std::string& was, const std::string& is) {
        front += (front.empty() ? "" : ", ") + column + " " + (was.empty() ? "-" : was) + " -> " + (is.empty() ? "-" : is);
    };
    if (b.front != r.front) add("front", b.front, r.front);
    if (b.dominatedBy != r.dominatedBy) add("dominated_by", pointList(b.dominatedBy), pointList(r.dominatedBy));
    if (b.tiedWith != r.tiedWith) add("tied_with", tieList(b.tiedWith), tieList(r.tiedWith));
    if (b.pick != r.pick) add("pick", b.pick, r.pick);
    if (front.empty()) return;
    std::printf("%s: %s%s\n", label.c_str(), front.c_str(),
                out.exactCost ? " (moved; rule: exact, the front's cost is a counter)"
                              : " (not counted: with GPU ms the front follows the times' noise)");
    if (out.exactCost) ++out.frontMoved;
}
}  // namespace

TradeoffComparison compareTradeoff(const TradeoffTable& before, const TradeoffTable& after, int framesBefore,
                                   int framesAfter, bool exactCost) {
    std::map<std::tuple<int, std::string, std::string, std::string>, const TradeoffRow*> recorded;
    for (const auto& r : before.rows) recorded[{r.point, r.camera, r.metric, r.buffer}] = &r;
    TradeoffComparison out;
    out.exactCost = exactCost;
    out.time = before.time == after.time ? after.time : "frame";
    out.rows = after.rows.size();
    out.countersCompared = before.counted && after.counted;
    for (const auto& r : after.rows) {
        const auto it = recorded.find({r.point, r.camera, r.metric, r.buffer});
        if (it == recorded.end()) {
            std::printf("%s: not in the record\n", pointLabel(after, r).c_str());
            ++out.missing;
            continue;
        }
        const TradeoffRow& b = *it->second;
        // Rows of a record without "frames" counted the record's frames.
        const size_t nBefore = static_cast<size_t>(b.frames > 0 ? b.frames : framesBefore);
        const size_t nAfter = static_cast<size_t>(r.frames > 0 ? r.frames : framesAfter);
        bool same = true;
        if (printRowComparison(pointLabel(after, r), b, r, nBefore, nAfter, same)) ++out.moved;
        if (!same) ++out.errorDiffer;
        std::string notHere, notRecorded;
        if (const std::string moved = movedCounters(before, b, after, r, notHere, notRecorded); !moved.empty()) {
            std::printf("%s: counters moved: %s\n", pointLabel(after, r).c_str(), moved.c_str());
            ++out.countersMoved;
        }
        if (!notHere.empty())
            std::printf("%s: counters not measured here: %s\n", pointLabel(after, r).c_str(), notHere.c_str());
        if (!notRecorded.empty())
            std::printf("%s: counters missing in the record: %s\n", pointLabel(after, r).c_str(), notRecorded.c_str());
        if (!notHere.empty() || !notRecorded.empty()) ++out.countersMissing;
        if (std::isfinite(b.gpuMemPeakMib) && std::isfinite(r.gpuMemPeakMib) && b.gpuMemPeakMib != r.gpuMemPeakMib) {
            std::printf("%s: gpu memory peak %.4f -> %.4f MiB (differs)\n", pointLabel(after, r).c_str(), b.gpuMemPeakMib,
                        r.gpuMemPeakMib);
            ++out.memoryDiffer;
        }
        if (recordInconsistent(pointLabel(after, r), b)) ++out.inconsistent;
        compareFrontInputs(pointLabel(after, r), before, b, after, r,
                           enoughForInterval(nBefore) && enoughForInterval(nAfter), out);
        recorded.erase(it);
    }
    for (const auto& [key, b] : recorded) {
        std::printf("%s: in the record, not run again\n", pointLabel(before, *b).c_str());
        ++out.missing;
    }
    return out;
}

int TradeoffComparison::verdict() const {
    // With a counter --cost neither the front nor the pick read a time: the
    // times' lines are printed (a moved one says "(moved)") but not counted.
    const int timesCounted = exactCost ? 0 : moved + timeMoved + termsMoved;
    if (errorDiffer == 0 && missing == 0 && countersMoved == 0 && intervalDiffer == 0 && timesCounted == 0 &&
        frontMoved == 0 && countersMissing == 0 && inconsistent == 0 && memoryDiffer == 0 && !pickMoved) {
        if (exactCost)
            std::printf("tradeoff: the same (%zu rows, every error equal%s; every error interval equal, the front and "
                        "the pick the same; times not counted: the front's cost is a counter, %d row(s) with a time "
                        "outside [%.2f, %.2f])\n",
                        rows, countersCompared ? ", every counter equal" : "", moved + timeMoved, kTimingBandLow,
                        kTimingBandHigh);
        else
            std::printf("tradeoff: the same (%zu rows, every error equal, no frame time outside [%.2f, %.2f] with its "
                        "95%% interval%s; every error interval equal%s)\n",
                        rows, kTimingBandLow, kTimingBandHigh, countersCompared ? ", every counter equal" : "",
                        time == "frame" ? "" : (", no " + time + " time outside the band either").c_str());
        return 0;
    }
    std::printf("tradeoff: differs (%d row(s) with another error, %d with the frame time moved beyond [%.2f, %.2f], "
                "%d with a counter moved, %d with a counter measured on one side only, %d not in both; %d with another "
                "error interval, %d with the%s time moved, %d with a term of it moved, %d with another front or pick; "
                "%d inconsistent in the record, %d with another peak GPU memory; the pick %s)\n",
                errorDiffer, moved, kTimingBandLow, kTimingBandHigh, countersMoved, countersMissing, missing,
                intervalDiffer, timeMoved, time == "frame" ? " --time" : (" " + time).c_str(), termsMoved, frontMoved,
                inconsistent, memoryDiffer, pickMoved ? "moved" : "the same");
    if (exactCost) std::printf("tradeoff: the times are not counted in that verdict: the front's cost is a counter\n");
    return 1;
}

}  // namespace dw::replay
