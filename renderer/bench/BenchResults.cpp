#include "renderer/bench/BenchResults.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "renderer/Error.h"
#include "renderer/bench/CsvLine.h"
#include "renderer/io/TextFile.h"

namespace dw {

namespace {

// The shortest text that reads back as the same double: a CSV read back (by
// bench merge, --resume) holds the run's numbers to the last digit, so merged
// shards give the unsharded run's figures exactly (%.4f rounded the lights
// per pixel and the timings).
std::string number(double v) {
    if (!std::isfinite(v)) return "";
    char text[64];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, v);
    return ec == std::errc() ? std::string(text, end) : "";
}

const char* const kLeading[] = {"config", "size", "lights"};

// The counter columns of a row, from field `first` on: empty is not measured.
template <typename Fail>
PassCounts countsOf(const std::vector<std::string>& f, size_t first, const Fail& fail) {
    PassCounts c;
    for (int i = 0; i < PassCounts::kCount; ++i) {
        const std::string& text = f[first + static_cast<size_t>(i)];
        if (text.empty()) continue;
        long long v = -1;
        auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec != std::errc() || p != text.data() + text.size() || v < 0)
            fail(std::string(PassCounts::name(i)) + ": expected a count (a whole number, at least 0) or nothing, got '" +
                 text + "'");
        c.v[static_cast<size_t>(i)] = v;
    }
    return c;
}
const char* const kTrailing[] = {"lpp", "lpp_lit", "sample", "seq", "frame", "pass", "gpu_ms", "cpu_ms"};
// After kTrailing (and before the counters); a CSV written before it has none.
const char* const kMemoryColumn = "gpu_mem_peak_mib";

// A gpu_mem_peak_mib field: MiB (finite, at least 0), or NaN when empty.
template <typename Fail>
double mibOf(const std::string& text, const Fail& fail) {
    if (text.empty()) return std::numeric_limits<double>::quiet_NaN();
    double v = 0.0;
    auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || p != text.data() + text.size() || !(std::isfinite(v) && v >= 0.0))
        fail(std::string(kMemoryColumn) + ": expected MiB (a finite number, at least 0) or nothing, got '" + text + "'");
    return v;
}

}  // namespace

const BenchConfigResult* BenchResults::find(int config) const {
    auto it = std::lower_bound(configs.begin(), configs.end(), config,
                               [](const BenchConfigResult& c, int i) { return c.config.index < i; });
    return it != configs.end() && it->config.index == config ? &*it : nullptr;
}

std::string BenchResults::counterMismatch() const {
    std::map<std::pair<int, std::string>, const BenchSample*> first;
    for (const auto& s : samples) {
        if (!s.counts.measured()) continue;
        auto [it, fresh] = first.emplace(std::make_pair(s.config, s.series), &s);
        if (fresh || s.counts == it->second->counts) continue;
        for (int i = 0; i < PassCounts::kCount; ++i)
            if (s.counts[i] != it->second->counts[i])
                return "configuration " + std::to_string(s.config) + ", sample " + std::to_string(s.sample) + ": " +
                       s.series + "'s " + PassCounts::name(i) + " " + std::to_string(s.counts[i]) + " (sample " +
                       std::to_string(it->second->sample) + ": " + std::to_string(it->second->counts[i]) + ")";
    }
    return "";
}

std::vector<std::string> BenchResults::seriesOf(int config) const {
    std::vector<std::string> names;
    for (const auto& s : samples)
        if (s.config == config && std::find(names.begin(), names.end(), s.series) == names.end()) names.push_back(s.series);
    return names;
}

double gpuMemPeakMib(const std::vector<BenchSample>& samples, int config) {
    double peak = std::numeric_limits<double>::quiet_NaN();
    for (const BenchSample& s : samples)
        if (s.config == config && !std::isnan(s.gpuMemPeakMib)) peak = std::isnan(peak) ? s.gpuMemPeakMib : std::max(peak, s.gpuMemPeakMib);
    return peak;
}

std::string BenchResults::csvHeader(const std::vector<std::string>& knobAxes, bool counted) {
    std::string h;
    for (const char* c : kLeading) h += std::string(h.empty() ? "" : ",") + c;
    for (const auto& k : knobAxes) h += "," + csvField(k);
    for (const char* c : kTrailing) h += std::string(",") + c;
    h += std::string(",") + kMemoryColumn;
    for (int i = 0; counted && i < PassCounts::kCount; ++i) h += std::string(",") + PassCounts::name(i);
    return h;
}

std::string BenchResults::csv() const { return csvHeader(knobAxes, counted) + "\n" + csvRows(samples); }

std::string BenchResults::csvRows(const std::vector<BenchSample>& rows) const {
    std::ostringstream out;
    for (const auto& s : rows) {
        const BenchConfigResult* c = find(s.config);
        if (!c) throw Error("a sample names configuration " + std::to_string(s.config) + ", which the results do not hold");
        out << c->config.index << "," << c->config.size() << "," << c->config.lights;
        for (const auto& v : c->config.knobValues) out << "," << csvField(v);
        out << "," << number(c->lpp) << "," << number(c->lppLit) << "," << s.sample << "," << s.seq << "," << s.frame << ","
            << csvField(s.series) << "," << number(s.gpuMs) << "," << number(s.cpuMs) << "," << number(s.gpuMemPeakMib);
        for (int i = 0; counted && i < PassCounts::kCount; ++i)
            out << "," << (s.counts[i] >= 0 ? std::to_string(s.counts[i]) : std::string());
        out << "\n";
    }
    return out.str();
}

BenchResults BenchResults::parseCsv(const std::string& whole, const std::string& path, bool cutLastLine) {
    const std::string text =
        cutLastLine && !whole.empty() && whole.back() != '\n' && whole.find('\n') != std::string::npos
            ? whole.substr(0, whole.rfind('\n') + 1)
            : whole;
    std::istringstream in(text);
    std::string line;
    if (!std::getline(in, line)) throw FileError(path, "empty file (expected the bench CSV header)");
    std::vector<std::string> header = splitCsvLine(line);
    // The counter columns, when there, come last.
    bool counted = header.size() > PassCounts::kCount;
    for (int i = 0; counted && i < PassCounts::kCount; ++i)
        counted = header[header.size() - PassCounts::kCount + static_cast<size_t>(i)] == PassCounts::name(i);
    const size_t columns = header.size();
    if (counted) header.resize(header.size() - PassCounts::kCount);
    const bool memory = !header.empty() && header.back() == kMemoryColumn;
    if (memory) header.pop_back();
    const size_t lead = std::size(kLeading), trail = std::size(kTrailing);
    bool ok = header.size() >= lead + trail;
    for (size_t i = 0; ok && i < lead; ++i) ok = header[i] == kLeading[i];
    for (size_t i = 0; ok && i < trail; ++i) ok = header[header.size() - trail + i] == kTrailing[i];
    if (!ok) throw FileError(path, "line 1: not a bench samples CSV (expected " + csvHeader({"<knob>..."}) + ")");

    BenchResults r;
    r.counted = counted;
    r.knobAxes.assign(header.begin() + static_cast<std::ptrdiff_t>(lead), header.end() - static_cast<std::ptrdiff_t>(trail));
    const size_t knobs = r.knobAxes.size();
    std::map<int, BenchConfigResult> configs;
    std::set<std::tuple<int, int, std::string>> once;  // (config, sample, series): each once
    // Every line bench writes ends in a newline: a last line without one was cut.
    const bool complete = text.empty() || text.back() == '\n';
    int lineNo = 1;
    while (std::getline(in, line)) {
        ++lineNo;
        if (!complete && in.peek() == std::char_traits<char>::eof() && !line.empty())
            throw FileError(path, "line " + std::to_string(lineNo) + ": the last line has no end (is the file cut short?)");
        if (line.empty() || line == "\r") continue;
        const std::vector<std::string> f = splitCsvLine(line);
        auto fail = [&](const std::string& what) -> void {
            throw FileError(path, "line " + std::to_string(lineNo) + ": " + what);
        };
        if (f.size() != columns) fail("expected " + std::to_string(columns) + " fields, got " + std::to_string(f.size()));
        auto integer = [&](size_t i) {
            long long v = 0;
            auto [p, ec] = std::from_chars(f[i].data(), f[i].data() + f[i].size(), v);
            if (ec != std::errc() || p != f[i].data() + f[i].size() || f[i].empty())
                fail(header[i] + ": expected a whole number, got '" + f[i] + "'");
            return v;
        };
        auto real = [&](size_t i) {
            if (f[i].empty()) return std::numeric_limits<double>::quiet_NaN();
            char* end = nullptr;
            const double v = std::strtod(f[i].c_str(), &end);
            if (end != f[i].c_str() + f[i].size()) fail(header[i] + ": expected a number, got '" + f[i] + "'");
            return v;
        };
        BenchConfigResult c;
        c.config.index = static_cast<int>(integer(0));
        const size_t x = f[1].find('x');
        int w = 0, h = 0;
        if (x == std::string::npos || std::from_chars(f[1].data(), f[1].data() + x, w).ec != std::errc() ||
            std::from_chars(f[1].data() + x + 1, f[1].data() + f[1].size(), h).ec != std::errc())
            fail("size: expected WIDTHxHEIGHT, got '" + f[1] + "'");
        c.config.width = w;
        c.config.height = h;
        c.config.lights = static_cast<int>(integer(2));
        for (size_t k = 0; k < knobs; ++k) c.config.knobValues.push_back(f[lead + k]);
        const size_t t = lead + knobs;
        c.lpp = real(t);
        c.lppLit = real(t + 1);
        auto [it, inserted] = configs.emplace(c.config.index, c);
        if (!inserted) {
            const BenchConfig& seen = it->second.config;
            if (seen.size() != c.config.size() || seen.lights != c.config.lights || seen.knobValues != c.config.knobValues)
                fail("configuration " + std::to_string(c.config.index) + " differs from its earlier rows");
        }
        BenchSample s;
        s.config = c.config.index;
        s.sample = static_cast<int>(integer(t + 2));
        s.seq = integer(t + 3);
        s.frame = static_cast<std::uint64_t>(integer(t + 4));
        s.series = f[t + 5];
        // A time is a finite number of milliseconds, never negative.
        auto time = [&](size_t i) {
            const double v = real(i);
            if (!std::isfinite(v) || v < 0.0)
                fail(header[i] + ": expected milliseconds (a finite number, at least 0), got '" + f[i] + "'");
            return v;
        };
        s.gpuMs = time(t + 6);
        s.cpuMs = time(t + 7);
        if (memory) s.gpuMemPeakMib = mibOf(f[t + 8], fail);
        if (counted) s.counts = countsOf(f, t + 8 + (memory ? 1 : 0), fail);
        if (!once.emplace(s.config, s.sample, s.series).second)
            fail("configuration " + std::to_string(s.config) + ", sample " + std::to_string(s.sample) + ", " + s.series +
                 " is there twice (a file joined twice?)");
        r.samples.push_back(std::move(s));
    }
    for (auto& [index, c] : configs) r.configs.push_back(std::move(c));
    return r;
}

BenchResults BenchResults::readCsv(const std::string& path, bool cutLastLine) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw FileError(path, "is a folder, not a bench samples CSV");
    return parseCsv(readWholeFile(path, "cannot open the bench CSV", "cannot open the bench CSV"), path, cutLastLine);
}

void writeBenchFile(const std::string& path, const std::string& text, const std::string& what) {
    // A file whole or not at all (a failed write leaves the old one, and no
    // part); a device or a pipe in place (writeFileAtomically says which).
    try {
        writeFileAtomically(path, text);
    } catch (const FileError& e) {
        const std::string said = e.what(), why = said.substr(said.find(": cannot save: ") == std::string::npos
                                                                  ? said.size()
                                                                  : said.find(": cannot save: ") + 15);
        throw FileError(path, "writing the " + what + " failed (" + (why.empty() ? "disk full, or not writable" : why) + ")");
    }
}

void BenchResults::writeCsv(const std::string& path) const { writeBenchFile(path, csv(), "bench CSV"); }

BenchResults BenchResults::merge(std::vector<BenchResults> parts, const std::vector<std::string>& names) {
    if (parts.empty()) throw Error("nothing to merge");
    BenchResults all;
    all.knobAxes = parts.front().knobAxes;
    all.machine = parts.front().machine;
    all.settings = parts.front().settings;
    for (const auto& part : parts) all.counted = all.counted || part.counted;
    std::map<int, size_t> owner;  // configuration -> the part it came from
    for (size_t p = 0; p < parts.size(); ++p) {
        const std::string name = p < names.size() ? names[p] : "part " + std::to_string(p);
        if (parts[p].knobAxes != all.knobAxes)
            throw Error(name + " sweeps other knobs than " + (names.empty() ? "the first part" : names.front()) +
                        " (columns " + csvHeader(parts[p].knobAxes) + ")");
        for (auto& c : parts[p].configs) {
            auto [it, inserted] = owner.emplace(c.config.index, p);
            if (!inserted) {
                const std::string other = it->second < names.size() ? names[it->second] : "another part";
                throw Error("configuration " + std::to_string(c.config.index) + " is in both " + other + " and " + name +
                            " (shards of one grid never share one)");
            }
            all.configs.push_back(std::move(c));
        }
        for (auto& s : parts[p].samples) all.samples.push_back(std::move(s));
    }
    std::sort(all.configs.begin(), all.configs.end(),
              [](const BenchConfigResult& a, const BenchConfigResult& b) { return a.config.index < b.config.index; });
    // Within a configuration keep the recorded order of its rows.
    std::stable_sort(all.samples.begin(), all.samples.end(), [](const BenchSample& a, const BenchSample& b) {
        return a.config != b.config ? a.config < b.config : a.sample < b.sample;
    });
    return all;
}

}  // namespace dw
