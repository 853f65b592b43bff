#include "app/ReplaySearch.h"

#include <cmath>
#include <cstdio>
#include <deque>
#include <map>

#include "renderer/OptionText.h"
#include "renderer/study/TradeoffStudy.h"

namespace dw::replay {

namespace {

const TradeoffRow* pickedRow(const TradeoffTable& t) {
    for (const auto& r : t.rows)
        if (r.pick == "pick") return &r;
    return nullptr;
}

bool hasPick(const TradeoffTable& t) {
    for (const auto& r : t.rows)
        if (!r.pick.empty()) return true;
    return false;
}

// `cost` a counter (--cost fragments|...): its value over the table's time span follows.
std::string pointText(const TradeoffTable& t, const TradeoffRow* r, const std::string& cost = "gpu_ms") {
    if (!r) return "none fits";
    if (cost != "gpu_ms") {
        char text[64];
        std::snprintf(text, sizeof(text), "%.17g", t.costOf(*r, t.time, cost));
        return pointText(t, r) + ", " + cost + " " + text;
    }
    std::string values;
    for (size_t a = 0; a < t.axes.size() && a < r->axisValues.size(); ++a)
        values += (values.empty() ? "" : ", ") + t.axes[a] + "=" + r->axisValues[a];
    return "point " + std::to_string(r->point) + (values.empty() ? "" : " (" + values + ")") + ", " + r->metric + " " +
           figureText(r->error) + " [" + figureText(r->errorLo) + ", " + figureText(r->errorHi) + "], time " +
           figureText(r->timeMs) + " ms [" + figureText(r->timeMsLo) + ", " + figureText(r->timeMsHi) + "]";
}

// The found evaluation's row of a search table (settings' search_found_evaluation), or nullptr.
const TradeoffRow* foundRow(const TradeoffTable& t, int evaluation) {
    for (const auto& r : t.rows)
        if (r.point == evaluation && (r.camera == TradeoffTable::kAllCameras || r.camera == "0")) return &r;
    return nullptr;
}

// A row's settings: every axis but the walk's own (step, proposal), with its camera, metric and buffer.
std::string settingsKey(const TradeoffTable& t, const TradeoffRow& r) {
    std::string key = r.camera + "|" + r.metric + "|" + r.buffer;
    for (size_t a = 0; a < t.axes.size() && a < r.axisValues.size(); ++a)
        if (t.axes[a] != "step" && t.axes[a] != "proposal") key += "|" + t.axes[a] + "=" + r.axisValues[a];
    return key;
}

// Every evaluation both walks measured with the same settings, compared as
// replay compares a sweep's rows (ReplayReport: errors, counters, times,
// front); the new walk's rows take the record's point numbers. Evaluations
// of one walk only are counted and said, not compared. Returns the verdict.
int compareEvaluations(const TradeoffTable& before, const TradeoffTable& after, int framesBefore, int framesAfter,
                       bool exactCost) {
    // A walk measures some settings more than once (the current point of
    // each step): the k-th measurement of a setting in one walk meets the
    // k-th in the other.
    std::map<std::string, std::deque<const TradeoffRow*>> recorded;
    for (const auto& r : before.rows) recorded[settingsKey(before, r)].push_back(&r);
    TradeoffTable was = before, now = after;
    was.rows.clear();
    now.rows.clear();
    size_t onlyNow = 0, onlyRecord = 0;
    for (const auto& r : after.rows) {
        const auto it = recorded.find(settingsKey(after, r));
        if (it == recorded.end() || it->second.empty()) {
            ++onlyNow;
            continue;
        }
        was.rows.push_back(*it->second.front());
        now.rows.push_back(r);
        now.rows.back().point = it->second.front()->point;
        it->second.pop_front();
    }
    for (const auto& [key, rows] : recorded) onlyRecord += rows.size();
    std::printf("search: %zu evaluation(s) with the same settings in both walks compared; %zu only in the record, "
                "%zu only in this walk (not compared)\n",
                now.rows.size(), onlyRecord, onlyNow);
    return compareTradeoff(was, now, framesBefore, framesAfter, exactCost).verdict();
}

}  // namespace

bool reportPick(const TradeoffTable& before, const TradeoffTable& after) {
    if (!hasPick(before) && !hasPick(after)) return false;
    const TradeoffRow* was = pickedRow(before);
    const TradeoffRow* now = pickedRow(after);
    const bool moved = (was == nullptr) != (now == nullptr) || (was && now && was->point != now->point);
    if (!moved)
        std::printf("pick: the same: %s -> %s\n", pointText(before, was).c_str(), pointText(after, now).c_str());
    else
        std::printf("pick: moved: %s -> %s\n", pointText(before, was).c_str(), pointText(after, now).c_str());
    return moved;
}

BudgetSearchResult replaySearch(const ExperimentRecord& old, const std::string& path, const RecordedTradeoff& again,
                                const std::optional<std::string>& newRecord, const BenchFields& machine, bool& moved) {
    BudgetSearchOptions so;
    so.base = again.options;
    so.maxEvals = again.maxEvals;
    so.aoRays = again.aoRays;
    so.referenceSeed = again.referenceSeed;
    so.referencePixels = {again.refSpp, reference::pixelFilterNamed(again.refFilter)};
    TradeoffStudyProgress progress;
    progress.warning = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    BudgetSearchResult found = BudgetSearch::run(so, progress);

    const TradeoffTable before = old.tradeoffTable(path);
    auto setting = [&](const char* key) {
        const auto& s = old.tradeoffResults;
        if (!s.contains("settings") || !s["settings"].contains(key) || !s["settings"][key].is_string()) return -1;
        try {
            return std::stoi(s["settings"][key].get<std::string>());
        } catch (const std::exception&) {
            return -1;
        }
    };
    const int wasEvaluation = setting("search_found_evaluation");
    const TradeoffRow* was = foundRow(before, wasEvaluation);
    const TradeoffRow* now = foundRow(found.table, found.foundEvaluation);
    std::string changes;
    for (size_t k = 0; k < found.knobs.size(); ++k) {
        const std::string then = was ? before.axisValue(*was, found.knobs[k]) : "";
        if (then != found.found[k])
            changes += (changes.empty() ? "" : ", ") + found.knobs[k] + " " + (then.empty() ? "?" : then) + " -> " + found.found[k];
    }
    moved = !changes.empty();
    std::printf("search: %s (%d -> %d evaluation(s)): %s -> %s\n",
                moved ? ("moved: " + changes).c_str() : "the same settings found", setting("search_evaluations"),
                found.evaluations, pointText(before, was, again.options.cost).c_str(),
                pointText(found.table, now, again.options.cost).c_str());
    const int evaluations = compareEvaluations(before, found.table, old.frames, again.options.frames,
                                               again.options.cost != "gpu_ms");
    if (evaluations != 0) moved = true;
    if (newRecord) {
        const TradeoffRunner start(again.options);
        ExperimentRecord::forTradeoff(again, start.scene(), BudgetSearch::asResult(found), machine).write(*newRecord);
    }
    return found;
}

}  // namespace dw::replay
