#include "renderer/bench/TradeoffTable.h"
#include "renderer/io/TextFile.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "renderer/Error.h"
#include "renderer/bench/BenchResults.h"
#include "renderer/bench/CsvLine.h"
#include "renderer/bench/ParetoFront.h"

namespace dw {

namespace {

const char* const kMiddle[] = {"metric",  "buffer",       "error",           "error_lo",       "error_hi",
                               "frames",  "frame_gpu_ms", "frame_gpu_ms_lo", "frame_gpu_ms_hi"};
const char* const kMetrics[] = {"flip", "rms", "psnr", "ssim", "temporal"};
// After pareto (a CSV written before them ends at pareto).
const char* const kTail[] = {"time", "time_ms", "time_ms_lo", "time_ms_hi", "front", "dominated_by", "tied_with", "pick"};
const char* const kFronts[] = {"", "pareto", "indistinguishable", "dominated"};
const char* const kPicks[] = {"", "pick", "tied", "fits", "over"};
// After pick; a CSV written before it has none.
const char* const kMemoryColumn = "gpu_mem_peak_mib";
const std::string kPassPrefix = "gpu_ms.";
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The shortest text that reads back to the same double; "" for NaN.
std::string number(double v) { return csvNumber(v); }

bool isWholeNumber(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Cameras in order: numbers by value, then other names, "all" last.
bool cameraBefore(const std::string& a, const std::string& b) {
    auto rank = [](const std::string& c) { return c == TradeoffTable::kAllCameras ? 2 : isWholeNumber(c) ? 0 : 1; };
    const int ra = rank(a), rb = rank(b);
    if (ra != rb) return ra < rb;
    if (ra == 0 && a.size() != b.size()) return a.size() < b.size();  // no leading zeros are written
    return a < b;
}

std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ",") + csvField(n);
    return s;
}

}  // namespace

TradeoffRow::TradeoffRow() : gpuMemPeakMib(kNaN) { frameCounts.fill(kNaN); }

std::string TradeoffTable::axisValue(const TradeoffRow& row, const std::string& axis) const {
    for (size_t i = 0; i < axes.size() && i < row.axisValues.size(); ++i)
        if (axes[i] == axis) return row.axisValues[i];
    return "";
}

double TradeoffTable::passGpuMs(const TradeoffRow& row, const std::string& pass) const {
    for (size_t i = 0; i < passes.size() && i < row.passGpuMs.size(); ++i)
        if (passes[i] == pass) return row.passGpuMs[i];
    return kNaN;
}

bool TradeoffTable::lowerIsBetter(const std::string& metric) { return metric != "psnr" && metric != "ssim"; }

std::vector<std::string> TradeoffTable::timeTerms(const std::string& time) {
    std::vector<std::string> terms;
    size_t start = 0;
    while (true) {
        const size_t plus = time.find('+', start);
        const std::string term = time.substr(start, plus == std::string::npos ? std::string::npos : plus - start);
        if (term.empty())
            throw Error("--time " + time + ": expected frame, a pass, PASS/NAME or a sum of them (pass+pass), got an empty term");
        if (std::find(terms.begin(), terms.end(), term) != terms.end())
            throw Error("--time " + time + ": '" + term + "' is named twice");
        terms.push_back(term);
        if (plus == std::string::npos) break;
        start = plus + 1;
    }
    if (terms.size() > 1 && std::find(terms.begin(), terms.end(), "frame") != terms.end())
        throw Error("--time " + time + ": frame is the whole frame; it is not summed with passes");
    return terms;
}

double TradeoffTable::timeOf(const TradeoffRow& row, const std::string& t) const {
    if (t == time && t != "frame") return row.timeMs;
    return t == "frame" ? row.frameGpuMs : passGpuMs(row, t);
}

void TradeoffTable::rankBy(const std::string& t) {
    if (t == time && t != "frame") return;  // carried (frame: always its columns')
    const std::vector<std::string> terms = timeTerms(t);
    if (terms.size() > 1)
        throw Error("--time " + t + ": the rows carry " + (rows.empty() ? std::string("no time") : "time " + time) +
                    ", not this sum; a sum's interval needs the per-frame sums: run tradeoff again with --time " + t);
    if (t != "frame" && std::find(passes.begin(), passes.end(), t) == passes.end())
        throw Error("--time " + t + ": no pass of that name was timed (expected frame or one of: " +
                    (passes.empty() ? std::string("none") : joined(passes)) + ")");
    for (auto& r : rows) {
        r.timeMs = t == "frame" ? r.frameGpuMs : passGpuMs(r, t);
        r.timeMsLo = t == "frame" ? r.frameGpuMsLo : kNaN;
        r.timeMsHi = t == "frame" ? r.frameGpuMsHi : kNaN;
    }
    time = t;
}

double TradeoffTable::passCount(const TradeoffRow& row, const std::string& pass, int counter) const {
    for (size_t i = 0; i < passes.size() && i < row.passCounts.size(); ++i)
        if (passes[i] == pass) return row.passCounts[i][static_cast<size_t>(counter)];
    return kNaN;
}

double TradeoffTable::costOf(const TradeoffRow& row, const std::string& t, const std::string& cost) const {
    if (cost == "gpu_ms") return timeOf(row, t);
    const int counter = PassCounts::index(cost);
    if (counter < 0) return kNaN;
    if (t == "frame") return row.frameCounts[static_cast<size_t>(counter)];
    double sum = 0.0;  // a sum of passes: the sum of their counts (NaN when one is not counted)
    for (const auto& term : timeTerms(t)) sum += passCount(row, term, counter);
    return sum;
}

bool TradeoffTable::isCost(const std::string& cost) { return cost == "gpu_ms" || PassCounts::index(cost) >= 0; }

std::string TradeoffTable::costNames() {
    std::string s = "gpu_ms";
    for (int i = 0; i < PassCounts::kCount; ++i) s += std::string(", ") + PassCounts::name(i);
    return s;
}

bool TradeoffTable::hasCounter(int counter) const {
    return std::any_of(rows.begin(), rows.end(),
                       [&](const TradeoffRow& r) { return !std::isnan(r.frameCounts[static_cast<size_t>(counter)]); });
}

void TradeoffTable::checkCost(const std::string& cost) const {
    if (!isCost(cost)) throw Error("--cost " + cost + ": expected one of " + costNames());
    if (cost != "gpu_ms" && !hasCounter(PassCounts::index(cost)))
        throw Error("--cost " + cost + ": no point has " + cost +
                    " counted (measured without counters, or the driver lacks GL_ARB_pipeline_statistics_query)");
}

void TradeoffTable::markParetoFront(const std::string& t, const std::string& cost) {
    if (rows.empty()) throw Error("no points to compare: the sweep is empty");
    rankBy(t);
    checkCost(cost);
    markFront([this, &cost](size_t i) { return intervalEvidence(rows[i], cost); }, FrontRule::intervals);
}

FrontEvidence TradeoffTable::intervalEvidence(const TradeoffRow& r, const std::string& cost) const {
    FrontEvidence e;
    if (cost == "gpu_ms") {
        e.cost = {r.timeMs, r.timeMsLo, r.timeMsHi, {}, false};
    } else {
        const double c = costOf(r, time, cost);
        e.cost = {c, c, c, {}, true};
    }
    const bool lower = lowerIsBetter(r.metric);
    e.error = lower ? FrontAxis{r.error, r.errorLo, r.errorHi, {}, false}
                    : FrontAxis{-r.error, -r.errorHi, -r.errorLo, {}, false};
    return e;
}

void TradeoffTable::markFront(const RowEvidence& evidence, FrontRule rule, double alpha) {
    if (rows.empty()) throw Error("no points to compare: the sweep is empty");
    std::map<std::tuple<std::string, std::string, std::string>, std::vector<size_t>> groups;
    for (size_t i = 0; i < rows.size(); ++i) groups[{rows[i].camera, rows[i].metric, rows[i].buffer}].push_back(i);
    frontRules.clear();
    frontCostTests.clear();
    for (const auto& [key, members] : groups) {
        std::vector<FrontEvidence> points;
        points.reserve(members.size());
        for (size_t i : members) points.push_back(evidence(i));
        const FrontDecision d = decideFront(points, rule, alpha);
        frontRules[std::get<0>(key)] = d.rule;
        frontCostTests[std::get<0>(key)] = {d.testedTime, d.exactCost, d.untestedTime, rule == FrontRule::intervals};
        for (size_t k = 0; k < members.size(); ++k) {
            TradeoffRow& r = rows[members[k]];
            r.front = d.front[k];
            r.pareto = r.front == "pareto";
            r.dominatedBy.clear();
            for (size_t q : d.dominatedBy[k]) r.dominatedBy.push_back(rows[members[q]].point);
            r.tiedWith.clear();
            for (const FrontTie& tie : d.tiedWith[k])
                r.tiedWith.emplace_back(rows[members[tie.other]].point, tie.time && tie.error ? "both" : tie.axes());
            r.errorTies.clear();
            r.timeTies.clear();
            for (size_t q = 0; q < members.size(); ++q) {
                if (q == k || r.front.empty() || d.front[q].empty()) continue;
                if (d.errorTied(k, q)) r.errorTies.push_back(rows[members[q]].point);
                if (d.timeOrder[k][q] == Order::notApart || d.timeOrder[k][q] == Order::identical)
                    r.timeTies.push_back(rows[members[q]].point);
            }
        }
    }
}

namespace {

// "0, 1 and 3".
std::string pointList(const std::vector<int>& points) {
    std::string s;
    for (size_t i = 0; i < points.size(); ++i)
        s += (i == 0 ? "" : i + 1 == points.size() ? " and " : ", ") + std::to_string(points[i]);
    return s;
}

// One axis's line: which points (of `rows`) cannot be told apart on it.
// The cost axis is `costName`; told how it was compared by `tests`.
std::string tiesLine(const std::vector<const TradeoffRow*>& rows, bool error, const std::string& costName,
                     const TradeoffTable::CostTests& tests) {
    const std::string axis = error ? "error" : costName;
    std::vector<int> points;
    std::vector<std::string> pairs;
    size_t tied = 0;
    for (const TradeoffRow* r : rows) {
        points.push_back(r->point);
        for (int q : error ? r->errorTies : r->timeTies)
            if (q > r->point) {
                pairs.push_back(std::to_string(r->point) + " and " + std::to_string(q));
                ++tied;
            }
    }
    const size_t all = points.size() * (points.size() - 1) / 2;
    if (all == 0) return "";
    if (!error && tests.exact > 0) {  // a counter: exact, compared by value; ties are equal counts
        std::string s = axis + " (an exact counter, compared by value, not tested): ";
        if (tied == 0) return s + "every pair of points differs";
        for (size_t k = 0; k < pairs.size(); ++k) s += (k ? "; " : "equal: ") + pairs[k];
        return s;
    }
    if (!error && !tests.intervals && tests.tested == 0 && tests.untested > 0)
        return axis + ": not tested (no paired resamples: fewer than 6 rounds, or a time missing), so no pair is told apart on it";
    if (tied == all) return axis + ": points " + pointList(points) + " cannot be told apart (no pair differs with confidence)";
    if (tied == 0) return axis + ": every pair of points told apart";
    std::string s;
    for (const auto& p : pairs) s += (s.empty() ? "" : "; ") + p;
    return axis + ": cannot be told apart: " + s;
}

}  // namespace

std::vector<std::string> TradeoffTable::frontSummary(const std::string& camera, const std::string& costName) const {
    std::vector<const TradeoffRow*> shown;
    for (const auto& r : rows)
        if (r.camera == camera && !r.front.empty()) shown.push_back(&r);
    std::vector<std::string> lines;
    if (shown.empty()) return lines;
    for (bool error : {true, false})
        if (std::string l = tiesLine(shown, error, costName,
                                     frontCostTests.count(camera) ? frontCostTests.at(camera) : CostTests{});
            !l.empty())
            lines.push_back(l);
    std::string dominated;
    for (const TradeoffRow* r : shown)
        if (r->front == "dominated")
            dominated += (dominated.empty() ? "" : "; ") + std::to_string(r->point) + " (by " + pointList(r->dominatedBy) + ")";
    lines.push_back("dominated: " + (dominated.empty() ? std::string("none (no point is confidently beaten on both axes)") : dominated));
    return lines;
}

std::vector<std::string> TradeoffTable::columns(const std::vector<std::string>& axes,
                                                const std::vector<std::string>& passes, bool counted) {
    std::vector<std::string> c = {"point"};
    c.insert(c.end(), axes.begin(), axes.end());
    c.push_back("camera");
    c.insert(c.end(), std::begin(kMiddle), std::end(kMiddle));
    for (const auto& p : passes) c.push_back(kPassPrefix + p);
    for (int i = 0; counted && i < PassCounts::kCount; ++i) {
        c.push_back(PassCounts::name(i));
        for (const auto& p : passes)
            if (hasCounterColumns(p)) c.push_back(std::string(PassCounts::name(i)) + "." + p);
    }
    c.push_back("pareto");
    c.insert(c.end(), std::begin(kTail), std::end(kTail));
    c.push_back(kMemoryColumn);
    return c;
}

std::vector<std::string> TradeoffTable::columns() const { return columns(axes, passes, counted); }

std::string TradeoffTable::csv() const {
    std::ostringstream out;
    out << joined(columns()) << "\n";
    for (const auto& r : rows) {
        if (r.axisValues.size() != axes.size())
            throw Error("point " + std::to_string(r.point) + " has " + std::to_string(r.axisValues.size()) +
                        " axis values for " + std::to_string(axes.size()) + " axes");
        out << r.point;
        for (const auto& v : r.axisValues) out << "," << csvField(v);
        out << "," << csvField(r.camera) << "," << csvField(r.metric) << "," << csvField(r.buffer) << ","
            << number(r.error) << "," << number(r.errorLo) << "," << number(r.errorHi) << "," << r.frames << ","
            << number(r.frameGpuMs) << "," << number(r.frameGpuMsLo) << "," << number(r.frameGpuMsHi);
        for (size_t p = 0; p < passes.size(); ++p) out << "," << number(p < r.passGpuMs.size() ? r.passGpuMs[p] : kNaN);
        for (size_t i = 0; counted && i < PassCounts::kCount; ++i) {
            out << "," << number(r.frameCounts[i]);
            for (size_t p = 0; p < passes.size(); ++p)
                if (hasCounterColumns(passes[p])) out << "," << number(p < r.passCounts.size() ? r.passCounts[p][i] : kNaN);
        }
        out << "," << (r.pareto ? 1 : 0) << "," << csvField(time) << "," << number(r.timeMs) << ","
            << number(r.timeMsLo) << "," << number(r.timeMsHi) << "," << r.front << ",";
        for (size_t k = 0; k < r.dominatedBy.size(); ++k) out << (k ? " " : "") << r.dominatedBy[k];
        out << ",";
        for (size_t k = 0; k < r.tiedWith.size(); ++k) out << (k ? " " : "") << r.tiedWith[k].first << ":" << r.tiedWith[k].second;
        out << "," << r.pick << "," << number(r.gpuMemPeakMib) << "\n";
    }
    return out.str();
}

namespace {

FileError cellError(const std::string& path, int lineNo, size_t column, const std::string& what) {
    return FileError(path, "line " + std::to_string(lineNo) + ", column " + std::to_string(column + 1) + ": " + what);
}

// Where the columns of a tradeoff CSV are: point, the axes, camera, the
// fixed middle (metric .. frame_gpu_ms_hi), a gpu_ms.<pass> each, pareto.
struct CsvLayout {
    std::vector<std::string> header;
    size_t cameraCol = 0, middle = 0, passStart = 0, countStart = 0, paretoCol = 0;
    std::vector<std::string> passes;  // the gpu_ms.<pass> columns' passes
    bool tail = false;  // the columns after pareto (time ... pick); a CSV written before them has none
    bool memory = false;  // gpu_mem_peak_mib after pick; a CSV written before it has none
};

// The counters' columns between the passes' gpu_ms.<pass> and pareto: each
// counter's frame column, then one per pass (not a span) in the passes' order.
template <typename At>
void checkCounterHeader(const CsvLayout& l, const std::vector<std::string>& passes, const At& at) {
    const std::vector<std::string>& header = l.header;
    size_t col = l.countStart;
    for (int i = 0; i < PassCounts::kCount; ++i)
        for (size_t p = 0; p <= passes.size(); ++p) {
            if (p > 0 && !TradeoffTable::hasCounterColumns(passes[p - 1])) continue;
            const std::string want = p == 0 ? PassCounts::name(i) : PassCounts::name(i) + ("." + passes[p - 1]);
            if (col >= l.paretoCol || header[col] != want)
                throw at(col, "expected the counter column '" + want + "', got '" + header[col] + "'");
            ++col;
        }
    if (col != l.paretoCol) throw at(col, "expected 'pareto', got '" + header[col] + "'");
}

// The header line: names unique and non-empty, the fixed columns where they
// belong; the axes and passes into `t`.
CsvLayout parseHeader(const std::string& line, const std::string& path, const std::string& expected, TradeoffTable& t) {
    CsvLayout l;
    l.header = splitCsvLine(line);
    const std::vector<std::string>& header = l.header;
    auto at = [&](size_t column, const std::string& what) { return cellError(path, 1, column, what); };
    for (size_t i = 0; i < header.size(); ++i) {
        if (header[i].empty()) throw at(i, "a column without a name");
        for (size_t j = 0; j < i; ++j)
            if (header[j] == header[i])
                throw at(i, "the column '" + header[i] + "' is there twice (also column " + std::to_string(j + 1) + ")");
    }
    if (header[0] != "point")
        throw at(0, "expected 'point', got '" + header[0] + "' (not a tradeoff CSV; expected " + expected + ")");
    const auto cameraIt = std::find(header.begin(), header.end(), "camera");
    if (cameraIt == header.end()) throw at(header.size() - 1, "no 'camera' column (expected " + expected + ")");
    l.cameraCol = static_cast<size_t>(cameraIt - header.begin());
    t.axes.assign(header.begin() + 1, cameraIt);
    size_t col = l.cameraCol + 1;
    for (const char* name : kMiddle) {
        if (col >= header.size()) throw at(col, "expected the column '" + std::string(name) + "', the line ends");
        if (header[col] != name) throw at(col, "expected the column '" + std::string(name) + "', got '" + header[col] + "'");
        ++col;
    }
    const auto pareto = std::find(header.begin() + static_cast<std::ptrdiff_t>(col), header.end(), "pareto");
    if (pareto == header.end())
        throw at(header.size() - 1, "expected a 'pareto' column after the passes' gpu_ms.<pass>, got '" + header.back() + "'");
    l.paretoCol = static_cast<size_t>(pareto - header.begin());
    l.tail = l.paretoCol + 1 < header.size();
    if (l.tail) {
        size_t k = l.paretoCol + 1;
        for (const char* name : kTail) {
            if (k >= header.size()) throw at(k, "expected the column '" + std::string(name) + "', the line ends");
            if (header[k] != name) throw at(k, "expected the column '" + std::string(name) + "', got '" + header[k] + "'");
            ++k;
        }
        l.memory = k < header.size() && header[k] == kMemoryColumn;
        if (l.memory) ++k;
        if (k != header.size())
            throw at(k, "expected no column after 'pick' but " + std::string(kMemoryColumn) + ", got '" + header[k] + "'");
    }
    for (; col < l.paretoCol && header[col] != PassCounts::name(0); ++col) {
        if (header[col].rfind(kPassPrefix, 0) != 0 || header[col].size() == kPassPrefix.size())
            throw at(col, "expected a pass's column gpu_ms.<pass> or 'pareto', got '" + header[col] + "'");
        t.passes.push_back(header[col].substr(kPassPrefix.size()));
    }
    l.middle = l.cameraCol + 1;                   // "metric"
    l.passStart = l.middle + std::size(kMiddle);  // the first gpu_ms.<pass>
    l.countStart = col;
    l.passes = t.passes;
    t.counted = col < l.paretoCol;
    if (t.counted) checkCounterHeader(l, t.passes, at);
    return l;
}

// One data line's fields as a row; each field checked for its column.
TradeoffRow parseRow(const std::vector<std::string>& f, int lineNo, const CsvLayout& l, size_t passCount,
                     const std::string& path) {
    const std::vector<std::string>& header = l.header;
    auto at = [&](size_t column, const std::string& what) { return cellError(path, lineNo, column, what); };
    auto whole = [&](size_t i) {
        int v = 0;
        auto [p, ec] = std::from_chars(f[i].data(), f[i].data() + f[i].size(), v);
        if (f[i].empty() || ec != std::errc() || p != f[i].data() + f[i].size() || v < 0)
            throw at(i, header[i] + ": expected a whole number, at least 0, got '" + f[i] + "'");
        return v;
    };
    auto real = [&](size_t i, bool time) {
        if (f[i].empty()) return kNaN;
        double v = 0.0;
        auto [p, ec] = std::from_chars(f[i].data(), f[i].data() + f[i].size(), v);
        if (ec != std::errc() || p != f[i].data() + f[i].size() || std::isnan(v))
            throw at(i, header[i] + ": expected a number or nothing, got '" + f[i] + "'");
        if (time && !(std::isfinite(v) && v >= 0.0))
            throw at(i, header[i] + ": expected milliseconds (a finite number, at least 0), got '" + f[i] + "'");
        return v;
    };
    auto named = [&](size_t i) {
        if (f[i].empty()) throw at(i, header[i] + ": empty");
        return f[i];
    };
    TradeoffRow r;
    r.point = whole(0);
    r.axisValues.assign(f.begin() + 1, f.begin() + static_cast<std::ptrdiff_t>(l.cameraCol));
    for (size_t a = 0; a < r.axisValues.size(); ++a)
        if (r.axisValues[a].empty()) throw at(a + 1, header[a + 1] + ": empty");
    r.camera = named(l.cameraCol);
    r.metric = named(l.middle);
    if (std::find(std::begin(kMetrics), std::end(kMetrics), r.metric) == std::end(kMetrics))
        throw at(l.middle, "metric: expected flip, rms, psnr, ssim or temporal, got '" + r.metric + "'");
    r.buffer = named(l.middle + 1);
    r.error = real(l.middle + 2, false);
    r.errorLo = real(l.middle + 3, false);
    r.errorHi = real(l.middle + 4, false);
    r.frames = whole(l.middle + 5);
    r.frameGpuMs = real(l.middle + 6, true);
    r.frameGpuMsLo = real(l.middle + 7, true);
    r.frameGpuMsHi = real(l.middle + 8, true);
    for (size_t p = 0; p < passCount; ++p) r.passGpuMs.push_back(real(l.passStart + p, true));
    r.passCounts.assign(passCount, CounterValues{});
    for (auto& c : r.passCounts) c.fill(kNaN);
    const bool counted = l.countStart < l.paretoCol;
    size_t col = l.countStart;
    for (size_t i = 0; counted && i < PassCounts::kCount; ++i)
        for (size_t p = 0; p <= passCount; ++p) {
            if (p > 0 && !TradeoffTable::hasCounterColumns(l.passes[p - 1])) continue;
            const double v = real(col, false);
            if (!std::isnan(v) && !(std::isfinite(v) && v >= 0.0))
                throw at(col, header[col] + ": expected a count (at least 0) or nothing, got '" + f[col] + "'");
            (p == 0 ? r.frameCounts[i] : r.passCounts[p - 1][i]) = v;
            ++col;
        }
    const size_t last = l.paretoCol;
    if (f[last] != "0" && f[last] != "1") throw at(last, "pareto: expected 0 or 1, got '" + f[last] + "'");
    r.pareto = f[last] == "1";
    return r;
}

// Whole numbers separated by spaces ("2 3"); each may carry ":<one of axes>" when `axes` is given.
std::vector<std::pair<int, std::string>> pointsField(const std::string& text, const std::vector<std::string>& axes,
                                                     const std::function<FileError(const std::string&)>& bad) {
    std::vector<std::pair<int, std::string>> out;
    std::istringstream in(text);
    std::string item;
    while (in >> item) {
        const size_t colon = item.find(':');
        const std::string n = item.substr(0, colon), axis = colon == std::string::npos ? "" : item.substr(colon + 1);
        if (!isWholeNumber(n) || n.size() > 9) throw bad("expected a point's number, got '" + item + "'");
        if (axes.empty() != axis.empty() || (!axes.empty() && std::find(axes.begin(), axes.end(), axis) == axes.end()))
            throw bad(axes.empty() ? "expected a point's number, got '" + item + "'"
                                   : "expected N:time, N:error or N:both, got '" + item + "'");
        out.emplace_back(std::stoi(n), axis);
    }
    return out;
}

// The columns after pareto (time .. pick) into `r`; the time's name into `time`.
void parseTail(const std::vector<std::string>& f, int lineNo, const CsvLayout& l, const std::string& path, TradeoffRow& r,
               std::string& time) {
    const std::vector<std::string>& header = l.header;
    const size_t c = l.paretoCol + 1;
    auto at = [&](size_t column, const std::string& what) { return cellError(path, lineNo, column, what); };
    auto ms = [&](size_t i) {
        if (f[i].empty()) return kNaN;
        double v = 0.0;
        auto [p, ec] = std::from_chars(f[i].data(), f[i].data() + f[i].size(), v);
        if (ec != std::errc() || p != f[i].data() + f[i].size() || !(std::isfinite(v) && v >= 0.0))
            throw at(i, header[i] + ": expected milliseconds (a finite number, at least 0), got '" + f[i] + "'");
        return v;
    };
    auto oneOf = [&](size_t i, const auto& names) {
        if (std::find(std::begin(names), std::end(names), f[i]) == std::end(names))
            throw at(i, header[i] + ": unexpected '" + f[i] + "'");
        return f[i];
    };
    if (f[c].empty()) throw at(c, "time: empty");
    time = f[c];
    r.timeMs = ms(c + 1);
    r.timeMsLo = ms(c + 2);
    r.timeMsHi = ms(c + 3);
    r.front = oneOf(c + 4, kFronts);
    for (const auto& [point, axis] : pointsField(f[c + 5], {}, [&](const std::string& w) { return at(c + 5, "dominated_by: " + w); }))
        r.dominatedBy.push_back(point);
    r.tiedWith = pointsField(f[c + 6], {"time", "error", "both"}, [&](const std::string& w) { return at(c + 6, "tied_with: " + w); });
    r.pick = oneOf(c + 7, kPicks);
    if (l.memory && !f[c + 8].empty()) {
        double v = 0.0;
        auto [p, ec] = std::from_chars(f[c + 8].data(), f[c + 8].data() + f[c + 8].size(), v);
        if (ec != std::errc() || p != f[c + 8].data() + f[c + 8].size() || !(std::isfinite(v) && v >= 0.0))
            throw at(c + 8, header[c + 8] + ": expected MiB (a finite number, at least 0) or nothing, got '" + f[c + 8] + "'");
        r.gpuMemPeakMib = v;
    }
    for (const auto& [point, axes] : r.tiedWith) {  // what a CSV keeps of the ties (not the dominated points')
        if (axes != "time") r.errorTies.push_back(point);
        if (axes != "error") r.timeTies.push_back(point);
    }
}

// A point keeps its axis values on every line, and no row key comes twice.
class RowChecks {
public:
    RowChecks(const CsvLayout& l, const std::string& path) : l_(l), path_(path) {}
    void check(const TradeoffRow& r, int lineNo) {
        auto [it, first] = pointAxes_.emplace(r.point, r.axisValues);
        if (first) {
            pointLine_[r.point] = lineNo;
        } else if (it->second != r.axisValues) {
            size_t a = 0;
            while (it->second[a] == r.axisValues[a]) ++a;
            throw cellError(path_, lineNo, a + 1,
                            "point " + std::to_string(r.point) + " has " + l_.header[a + 1] + " '" + r.axisValues[a] +
                                "' here and '" + it->second[a] + "' on line " + std::to_string(pointLine_[r.point]));
        }
        auto [s, fresh] = seen_.emplace(std::make_tuple(r.point, r.camera, r.metric, r.buffer), lineNo);
        if (!fresh)
            throw cellError(path_, lineNo, 0,
                            "point " + std::to_string(r.point) + ", camera " + r.camera + ", " + r.metric + " on " +
                                r.buffer + " is there twice (also line " + std::to_string(s->second) +
                                "; a file joined twice?)");
    }

private:
    const CsvLayout& l_;
    const std::string& path_;
    std::map<int, std::vector<std::string>> pointAxes_;  // point -> its axis values
    std::map<int, int> pointLine_;                       // point -> where first seen
    std::map<std::tuple<int, std::string, std::string, std::string>, int> seen_;  // row key -> line
};

}  // namespace

TradeoffTable TradeoffTable::parseCsv(const std::string& text, const std::string& path) {
    std::istringstream in(text);
    std::string line;
    const std::string expected = joined(columns({"<axis>..."}, {"<pass>..."}));  // counters optional
    if (!std::getline(in, line) || line.empty() || line == "\r")
        throw FileError(path, "line 1: empty (expected the tradeoff CSV header " + expected + ")");
    TradeoffTable t;
    const CsvLayout layout = parseHeader(line, path, expected, t);
    RowChecks checks(layout, path);
    // Every line tradeoff writes ends in a newline: a last line without one was cut.
    const bool complete = text.back() == '\n';
    int lineNo = 1;
    while (std::getline(in, line)) {
        ++lineNo;
        if (line.empty() || line == "\r") continue;
        if (!complete && in.peek() == std::char_traits<char>::eof())
            throw FileError(path, "line " + std::to_string(lineNo) + ": the last line has no end (is the file cut short?)");
        const std::vector<std::string> f = splitCsvLine(line);
        if (f.size() != layout.header.size())
            throw cellError(path, lineNo, std::min(f.size(), layout.header.size()),
                            "expected " + std::to_string(layout.header.size()) + " fields, got " + std::to_string(f.size()));
        TradeoffRow r = parseRow(f, lineNo, layout, t.passes.size(), path);
        if (layout.tail) {
            std::string time;
            parseTail(f, lineNo, layout, path, r, time);
            if (t.rows.empty()) t.time = time;
            else if (time != t.time)
                throw cellError(path, lineNo, layout.paretoCol + 1,
                                "time: '" + time + "' here and '" + t.time + "' on the lines before (one time a table)");
        } else {  // written before the time columns: the front ranked by frame time
            r.timeMs = r.frameGpuMs;
            r.timeMsLo = r.frameGpuMsLo;
            r.timeMsHi = r.frameGpuMsHi;
        }
        checks.check(r, lineNo);
        t.rows.push_back(std::move(r));
    }
    return t;
}

TradeoffTable TradeoffTable::readCsv(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw FileError(path, "is a folder, not a tradeoff CSV");
    return parseCsv(readWholeFile(path, "cannot open the tradeoff CSV", "cannot open the tradeoff CSV"), path);
}

void TradeoffTable::writeCsv(const std::string& path) const { writeBenchFile(path, csv(), "tradeoff CSV"); }

TradeoffTable TradeoffTable::merge(const std::vector<TradeoffTable>& parts, const std::vector<std::string>& names,
                                   const std::string& time, const std::string& cost) {
    if (parts.empty()) throw Error("nothing to merge");
    auto nameOf = [&](size_t p) { return p < names.size() ? names[p] : "part " + std::to_string(p + 1); };
    TradeoffTable all;
    all.axes = parts.front().axes;
    // The time the rows carry: the parts' when they agree (else none: frame or one pass only).
    all.time = parts.front().time;
    for (const auto& part : parts)
        if (part.time != all.time) all.time.clear();
    for (const auto& part : parts) all.counted = all.counted || part.counted;
    for (const auto& part : parts)
        for (const auto& pass : part.passes)
            if (std::find(all.passes.begin(), all.passes.end(), pass) == all.passes.end()) all.passes.push_back(pass);
    std::map<std::tuple<int, std::string, std::string, std::string>, size_t> owner;
    std::map<int, std::pair<std::vector<std::string>, size_t>> pointAxes;
    for (size_t p = 0; p < parts.size(); ++p) {
        const TradeoffTable& part = parts[p];
        if (part.axes != all.axes)
            throw Error(nameOf(p) + " sweeps other axes (" + joined(part.axes) + ") than " + nameOf(0) + " (" +
                        joined(all.axes) + ")");
        for (const auto& r : part.rows) {
            auto [o, fresh] = owner.emplace(std::make_tuple(r.point, r.camera, r.metric, r.buffer), p);
            if (!fresh)
                throw Error("point " + std::to_string(r.point) + ", camera " + r.camera + " is in both " + nameOf(o->second) +
                            " and " + nameOf(p) + (o->second == p ? " twice" : "") +
                            " (shards of one sweep never share a point)");
            auto [a, first] = pointAxes.emplace(r.point, std::make_pair(r.axisValues, p));
            if (!first && a->second.first != r.axisValues)
                throw Error("point " + std::to_string(r.point) + " is a different configuration in " +
                            nameOf(a->second.second) + " and " + nameOf(p) + " (not shards of one sweep)");
            TradeoffRow row = r;
            row.pick.clear();  // a shard's budget pick is not the whole sweep's
            row.passGpuMs.assign(all.passes.size(), kNaN);
            CounterValues none;
            none.fill(kNaN);
            row.passCounts.assign(all.passes.size(), none);
            for (size_t k = 0; k < part.passes.size() && k < r.passGpuMs.size(); ++k) {
                const auto to = static_cast<size_t>(
                    std::find(all.passes.begin(), all.passes.end(), part.passes[k]) - all.passes.begin());
                row.passGpuMs[to] = r.passGpuMs[k];
                if (k < r.passCounts.size()) row.passCounts[to] = r.passCounts[k];
            }
            all.rows.push_back(std::move(row));
        }
    }
    std::stable_sort(all.rows.begin(), all.rows.end(), [](const TradeoffRow& a, const TradeoffRow& b) {
        if (a.point != b.point) return a.point < b.point;
        if (a.camera != b.camera) return cameraBefore(a.camera, b.camera);
        return false;
    });
    all.markParetoFront(time, cost);
    return all;
}

}  // namespace dw
