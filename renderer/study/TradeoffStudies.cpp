#include "renderer/study/TradeoffStudies.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>

#include "renderer/bench/BenchGrid.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"
#include "renderer/knobs/KnobAssignment.h"

namespace dw {

namespace {

// "--study 'ssao'" or "--study-file f.json: study 'ssao'" (or "study 2" before it has a name).
std::string where(const TradeoffStudySpec& s, size_t number) {
    const std::string name = s.name.empty() ? "study " + std::to_string(number + 1) : "study '" + s.name + "'";
    return s.origin + (s.origin.empty() ? "" : ": ") + name;
}

// One knob's values from a study file: a string, number or bool, or a list of them.
std::vector<std::string> fileValues(const nlohmann::ordered_json& v, const std::string& what) {
    auto one = [&](const nlohmann::ordered_json& x) {
        if (x.is_string()) return x.get<std::string>();
        if (x.is_boolean()) return std::string(x.get<bool>() ? "true" : "false");
        if (x.is_number()) return x.dump();
        throw TradeoffStudyError(what + ": expected a value (a string, number or bool) or a list of them, got " +
                                 x.dump());
    };
    std::vector<std::string> out;
    if (!v.is_array()) return {one(v)};
    for (const auto& x : v) out.push_back(one(x));
    return out;
}

// {"KNOB": value or [values], ...} as a study's knobs.
TradeoffStudySpec fileStudy(const nlohmann::ordered_json& knobs, const std::string& name, const std::string& origin,
                            size_t number) {
    TradeoffStudySpec s;
    s.name = name;
    s.origin = origin;
    if (!knobs.is_object())
        throw TradeoffStudyError(where(s, number) + ": expected an object {\"knob\": value or [values], ...}, got " +
                                 knobs.dump());
    for (const auto& [k, v] : knobs.items()) s.knobs.push_back({k, fileValues(v, where(s, number) + ": " + k)});
    return s;
}

// The default name: the values of its one-value knobs ("ssao"), else "study N".
std::string defaultName(const TradeoffStudySpec& s, size_t number) {
    std::string name;
    for (const auto& k : s.knobs)
        if (k.values.size() == 1) name += (name.empty() ? "" : "/") + k.values.front();
    return name.empty() ? "study " + std::to_string(number + 1) : name;
}

void checkKnobs(const TradeoffStudySpec& s, size_t number) {
    if (s.knobs.empty()) throw TradeoffStudyError(where(s, number) + ": an empty study (give KNOB=V1,V2,...)");
    for (size_t k = 0; k < s.knobs.size(); ++k) {
        const auto& knob = s.knobs[k];
        if (knob.name.empty()) throw TradeoffStudyError(where(s, number) + ": a knob without a name");
        if (knob.values.empty()) throw TradeoffStudyError(where(s, number) + ": " + knob.name + " has no values");
        for (const auto& v : knob.values)
            if (v.empty()) throw TradeoffStudyError(where(s, number) + ": " + knob.name + ": an empty value");
        for (size_t j = 0; j < k; ++j)
            if (s.knobs[j].name == knob.name)
                throw TradeoffStudyError(where(s, number) + ": " + knob.name + " is given twice");
    }
}

// "ao.method=ssao, ssao.samples=8": a point's knob values (the study axis left out).
std::string pointText(const TradeoffSweep& sweep, const std::vector<size_t>& at) {
    std::string text;
    for (size_t a = 1; a < sweep.axes.size(); ++a)
        text += (text.empty() ? "" : ", ") + sweep.axes[a].name + "=" + sweep.axes[a].values[at[a]];
    return text;
}

// Each of the study's knobs read against `current` (its canonical name, each
// value as the knob writes it); an unknown knob or a value it does not take refused.
std::vector<KnobAssignment> readStudy(const TradeoffStudySpec& s, size_t number, const KnobRegistry& current,
                                      std::vector<std::vector<KnobAssignment>>& values) {
    std::vector<KnobAssignment> first;
    for (const auto& knob : s.knobs) {
        std::vector<KnobAssignment> read;
        for (const auto& v : knob.values) {
            try {
                read.push_back(readKnobAssignment(current, knob.name, v));
            } catch (const Error& e) {
                throw TradeoffStudyError(where(s, number) + ": " + e.what());
            }
            if (read.back().knob != read.front().knob || read.back().id != read.front().id)
                throw TradeoffStudyError(where(s, number) + ": " + knob.name + " reads as two knobs");
        }
        for (const auto& f : first)
            if (f.id == read.front().id)
                throw TradeoffStudyError(where(s, number) + ": " + knob.name + " is " + f.knob + ", given twice");
        first.push_back(read.front());
        values.push_back(std::move(read));
    }
    return first;
}

// The next combination of a study's value positions (the last knob fastest); false after the last.
bool nextDigits(std::vector<size_t>& digit, const std::vector<std::vector<KnobAssignment>>& values, size_t v0) {
    for (size_t k = digit.size(); k-- > 0;) {
        if (++digit[k] < values[v0 + k].size()) return true;
        digit[k] = 0;
    }
    return false;
}

// `text`'s position in the axis' values, added when new.
size_t valueAt(TradeoffAxis& axis, const std::string& text) {
    const auto it = std::find(axis.values.begin(), axis.values.end(), text);
    if (it != axis.values.end()) return static_cast<size_t>(it - axis.values.begin());
    axis.values.push_back(text);
    return axis.values.size() - 1;
}

// A key JSON gives twice in one object is kept once (the last) by the
// parser, losing a study or a knob's values silently: refused as --study
// refuses the same, from the parser's events (the text already parsed once).
void refuseDuplicateKeys(const std::string& text, const std::string& origin) {
    struct Level {
        std::vector<std::string> keys;
        bool object = false;
    };
    std::vector<Level> open;
    std::string study;  // the study the keys below the top level belong to
    size_t studies = 0;
    auto callback = [&](int, int eventCode, nlohmann::json& parsed) {
        using E = nlohmann::json::parse_event_t;
        const E event = static_cast<E>(eventCode);
        if (event == E::object_start || event == E::array_start) {
            if (open.size() == 1 && !open.front().object) study = "study " + std::to_string(++studies);
            open.push_back({{}, event == E::object_start});
        } else if (event == E::object_end || event == E::array_end) {
            if (!open.empty()) open.pop_back();
        } else if (event == E::key && !open.empty()) {
            const std::string key = parsed.get<std::string>();
            std::vector<std::string>& keys = open.back().keys;
            if (std::find(keys.begin(), keys.end(), key) != keys.end()) {
                if (open.size() == 1) throw TradeoffStudyError(origin + ": two studies are named '" + key + "'");
                throw TradeoffStudyError(origin + ": " + study + ": " + key + " is given twice");
            }
            keys.push_back(key);
            if (open.size() == 1) study = "study '" + key + "'";
        }
        return true;
    };
    const nlohmann::json checked = parseJsonWithEvents(text, origin, callback);
    (void)checked;
}

}  // namespace

TradeoffStudySpec TradeoffStudies::parse(const std::string& text) {
    TradeoffStudySpec s;
    s.origin = "--study";
    size_t start = 0;
    for (bool first = true;; first = false) {
        const size_t colon = text.find(':', start);
        const std::string part = text.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
        const size_t eq = part.find('=');
        if (part.empty()) {
            throw TradeoffStudyError("--study '" + text + "': an empty study or part (expected [NAME:]KNOB=V1,V2[:KNOB=V...])");
        } else if (first && eq == std::string::npos && colon != std::string::npos) {
            s.name = part;  // NAME: before the knobs
        } else if (eq == std::string::npos) {
            throw TradeoffStudyError("--study: expected [NAME:]KNOB=V1,V2[:KNOB=V...], got '" + text + "'");
        } else {
            const std::string knob = part.substr(0, eq);
            if (knob.empty()) throw TradeoffStudyError("--study: a knob without a name in '" + text + "'");
            try {
                s.knobs.push_back({knob, splitList(part.substr(eq + 1), "--study " + knob)});
            } catch (const TradeoffStudyError&) {
                throw;
            } catch (const Error& e) {
                throw TradeoffStudyError(e.what());
            }
        }
        if (colon == std::string::npos) break;
        start = colon + 1;
    }
    if (s.knobs.empty()) throw TradeoffStudyError("--study: an empty study '" + text + "' (give KNOB=V1,V2,...)");
    return s;
}

std::vector<TradeoffStudySpec> TradeoffStudies::readFile(const std::string& path) {
    const std::string origin = "--study-file " + path;
    const std::string text = readWholeFile(path, "no such study file", "cannot read the study file");
    const nlohmann::ordered_json j = parseOrderedJson(text, path);
    refuseDuplicateKeys(text, origin);
    std::vector<TradeoffStudySpec> out;
    if (j.is_object()) {
        for (const auto& [name, knobs] : j.items()) out.push_back(fileStudy(knobs, name, origin, out.size()));
    } else if (j.is_array()) {
        for (const auto& knobs : j) out.push_back(fileStudy(knobs, "", origin, out.size()));
    } else {
        throw TradeoffStudyError(origin + ": expected {\"NAME\": {\"knob\": [values], ...}, ...} or a list of "
                                 "{\"knob\": [values], ...}");
    }
    if (out.empty()) throw TradeoffStudyError(origin + ": no studies");
    return out;
}

std::vector<TradeoffStudySpec> TradeoffStudies::named(std::vector<TradeoffStudySpec> studies) {
    if (studies.empty()) throw TradeoffStudyError("no studies");
    for (size_t i = 0; i < studies.size(); ++i) {
        checkKnobs(studies[i], i);
        if (studies[i].name.empty()) studies[i].name = defaultName(studies[i], i);
        for (size_t j = 0; j < i; ++j)
            if (studies[j].name == studies[i].name)
                throw TradeoffStudyError(where(studies[i], i) + ": two studies are named '" + studies[i].name +
                                         "' (name them: --study NAME:KNOB=...)");
    }
    return studies;
}

TradeoffSweep TradeoffStudies::sweep(const std::vector<TradeoffStudySpec>& studies, const KnobRegistry& current) {
    TradeoffSweep sweep;
    sweep.axes.push_back({"study", {}, {}});
    std::vector<int> ids;  // per knob axis (from 1), the knob's id
    std::vector<std::vector<KnobAssignment>> values;  // per study knob, in study order
    std::vector<std::vector<size_t>> axisOf;           // per study, per knob: its axis
    for (size_t i = 0; i < studies.size(); ++i) {
        const std::vector<KnobAssignment> knobs = readStudy(studies[i], i, current, values);
        axisOf.emplace_back();
        for (size_t k = 0; k < knobs.size(); ++k) {
            const auto it = std::find(ids.begin(), ids.end(), knobs[k].id);
            if (it == ids.end()) {
                ids.push_back(knobs[k].id);
                sweep.axes.push_back({knobs[k].knob, {}, {}});
            }
            axisOf.back().push_back(1 + static_cast<size_t>(std::find(ids.begin(), ids.end(), knobs[k].id) - ids.begin()));
        }
        sweep.axes[0].values.push_back(studies[i].name);
    }
    // Each study's grid, the last knob fastest; the knobs it does not name at their current values.
    size_t v0 = 0;
    for (size_t i = 0; i < studies.size(); ++i) {
        const size_t n = studies[i].knobs.size();
        std::vector<size_t> digit(n, 0);
        do {
            std::vector<size_t> at(sweep.axes.size(), SIZE_MAX);
            at[0] = i;
            for (size_t k = 0; k < n; ++k)
                at[axisOf[i][k]] = valueAt(sweep.axes[axisOf[i][k]], values[v0 + k][digit[k]].text);
            for (size_t a = 1; a < at.size(); ++a)
                if (at[a] == SIZE_MAX) at[a] = valueAt(sweep.axes[a], current.format(ids[a - 1]));
            sweep.listed.push_back(at);
        } while (nextDigits(digit, values, v0));
        v0 += n;
    }
    std::map<std::vector<size_t>, size_t> seen;  // a point's knob positions -> its study
    for (const auto& at : sweep.listed) {
        std::vector<size_t> knobs(at.begin() + 1, at.end());
        const auto [it, fresh] = seen.emplace(knobs, at[0]);
        if (!fresh)
            throw TradeoffStudyError(studies[at[0]].origin + ": the point " + pointText(sweep, at) + " is given twice (" +
                                     (it->second == at[0] ? "in study '" + studies[at[0]].name + "'"
                                                          : "in studies '" + studies[it->second].name + "' and '" +
                                                                studies[at[0]].name + "'") +
                                     ")");
    }
    return sweep;
}

}  // namespace dw
