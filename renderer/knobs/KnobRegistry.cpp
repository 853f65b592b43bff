#include "renderer/knobs/KnobRegistry.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <set>
#include <sstream>

#include "renderer/Error.h"
#include "renderer/io/FloatCheck.h"

namespace dw {

namespace {

// Edit distance, to suggest the knob a user probably meant.
size_t distance(const std::string& a, const std::string& b) {
    std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::mutex& warningMutex() {
    static std::mutex m;
    return m;
}

KnobRegistry::WarningHandler& warningHandler() {
    static KnobRegistry::WarningHandler handler;
    return handler;
}

void warn(const std::string& text) {
    KnobRegistry::WarningHandler handler;
    {
        std::lock_guard<std::mutex> lock(warningMutex());
        handler = warningHandler();
        if (!handler) {
            // Settings are applied more than once per run (validated, then
            // applied, per configuration): one line per rename is enough.
            static std::set<std::string> said;
            if (said.insert(text).second) std::fprintf(stderr, "warning: %s\n", text.c_str());
            return;
        }
    }
    handler(text);
}

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// The shortest text that reads back as the same float (std::to_chars without a
// precision is the shortest round trip), so presets, --dump-knobs and the
// panels never show noise such as 0.0039215688593685627 or lose a digit.
std::string formatNumber(double v) {
    std::array<char, 64> buf{};
    const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), static_cast<float>(v));
    if (ec != std::errc()) return std::to_string(v);
    return std::string(buf.data(), end);
}

// Float knobs hold float values (passes read them as float): the value a
// preset writes is then exactly the value it reads back.
double toKnobPrecision(KnobType type, double v) {
    return type == KnobType::Float ? static_cast<double>(static_cast<float>(v)) : v;
}

std::string lowerCase(std::string text) {
    for (char& ch : text) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return text;
}

}  // namespace

std::string KnobAlias::warning() const {
    if (knob.empty()) return "knob '" + oldName + "' is now '" + newName + "' (" + note + "); the old name still works";
    return "knob '" + knob + "': value '" + oldName + "' is now '" + newName + "' (" + note + "); the old value still works";
}

void KnobRegistry::addAlias(std::string oldName, std::string newName, std::string note) {
    if (find(oldName)) throw Error("knob alias '" + oldName + "' names a declared knob");
    aliases_.push_back({{}, std::move(oldName), std::move(newName), std::move(note)});
}

std::string KnobRegistry::canonicalName(const std::string& name) const {
    for (const KnobAlias& a : aliases_)
        if (a.knob.empty() && a.oldName == name) {
            warn(a.warning());
            return a.newName;
        }
    return name;
}

std::string KnobRegistry::aliasTarget(const std::string& name) const {
    for (const KnobAlias& a : aliases_)
        if (a.knob.empty() && a.oldName == name) return a.newName;
    return {};
}

void KnobRegistry::addValueAlias(std::string knob, std::string oldValue, std::string newValue, std::string note) {
    aliases_.push_back({std::move(knob), std::move(oldValue), std::move(newValue), std::move(note)});
}

KnobRegistry::WarningHandler KnobRegistry::setWarningHandler(WarningHandler handler) {
    std::lock_guard<std::mutex> lock(warningMutex());
    std::swap(warningHandler(), handler);
    return handler;
}

int KnobRegistry::add(KnobSpec spec) {
    if (find(spec.name)) throw Error("knob '" + spec.name + "' is declared twice");
    spec.defaultValue = toKnobPrecision(spec.type, spec.defaultValue);
    specs_.push_back(std::move(spec));
    values_.push_back(specs_.back().defaultValue);
    return static_cast<int>(specs_.size() - 1);
}

int KnobRegistry::require(const std::string& name, KnobType type) const {
    static const char* names[] = {"bool", "int", "float", "enum"};
    const std::optional<int> id = find(name);
    if (!id) throw Error("knob '" + name + "' is read by a pass but declared by none");
    if (specs_[*id].type != type)
        throw Error("knob '" + name + "' is a " + names[static_cast<int>(specs_[*id].type)] + ", read as a " +
                    names[static_cast<int>(type)]);
    return *id;
}

BoolKnob KnobRegistry::addBool(std::string name, bool def, std::string pass, std::string description) {
    KnobSpec s;
    s.name = std::move(name);
    s.type = KnobType::Bool;
    s.defaultValue = def ? 1.0 : 0.0;
    s.maxValue = 1.0;
    s.pass = std::move(pass);
    s.description = std::move(description);
    return {add(std::move(s))};
}

IntKnob KnobRegistry::addInt(std::string name, int def, int min, int max, std::string pass,
                             std::string description, std::string unit, bool tradeoff) {
    KnobSpec s;
    s.name = std::move(name);
    s.type = KnobType::Int;
    s.defaultValue = def;
    s.minValue = min;
    s.maxValue = max;
    s.pass = std::move(pass);
    s.description = std::move(description);
    s.unit = std::move(unit);
    s.tradeoff = tradeoff;
    return {add(std::move(s))};
}

FloatKnob KnobRegistry::addFloat(std::string name, double def, double min, double max, std::string pass,
                                 std::string description, std::string unit, bool tradeoff, bool logarithmic) {
    KnobSpec s;
    s.name = std::move(name);
    s.type = KnobType::Float;
    s.defaultValue = def;
    s.minValue = min;
    s.maxValue = max;
    s.pass = std::move(pass);
    s.description = std::move(description);
    s.unit = std::move(unit);
    s.tradeoff = tradeoff;
    s.logarithmic = logarithmic;
    return {add(std::move(s))};
}

EnumKnob KnobRegistry::addEnum(std::string name, std::vector<std::string> choices, int def, std::string pass,
                               std::string description, bool tradeoff) {
    KnobSpec s;
    s.name = std::move(name);
    s.type = KnobType::Enum;
    s.defaultValue = def;
    s.minValue = 0;
    s.maxValue = static_cast<double>(choices.size()) - 1;
    s.choices = std::move(choices);
    s.pass = std::move(pass);
    s.description = std::move(description);
    s.tradeoff = tradeoff;
    return {add(std::move(s))};
}

EnumKnob KnobRegistry::addEnum(std::string name, std::vector<std::string> choices, const std::string& defaultChoice,
                               std::string pass, std::string description, bool tradeoff) {
    const auto it = std::find(choices.begin(), choices.end(), defaultChoice);
    if (it == choices.end()) throw Error("knob '" + name + "': the default '" + defaultChoice + "' is not one of its choices");
    const int def = static_cast<int>(it - choices.begin());
    return addEnum(std::move(name), std::move(choices), def, std::move(pass), std::move(description), tradeoff);
}

void KnobRegistry::addChoice(EnumKnob k, std::string choice, const std::string& what, bool makeDefault) {
    KnobSpec& s = specs_.at(k.id);
    if (s.type != KnobType::Enum) throw Error("knob '" + s.name + "' is not an enum: cannot add choice '" + choice + "'");
    if (std::find(s.choices.begin(), s.choices.end(), choice) != s.choices.end())
        throw Error("knob '" + s.name + "' already has the choice '" + choice + "'");
    s.description += "; " + choice + ": " + what;
    s.choices.push_back(std::move(choice));
    s.maxValue = static_cast<double>(s.choices.size()) - 1;
    if (makeDefault) {
        s.defaultValue = s.maxValue;
        values_[k.id] = s.defaultValue;
        ++generation_;
    }
}

int KnobRegistry::choiceIndex(EnumKnob k, const std::string& name) const {
    const KnobSpec& s = specs_[k.id];
    const auto it = std::find(s.choices.begin(), s.choices.end(), name);
    if (it == s.choices.end()) {
        std::string all;
        for (const auto& c : s.choices) all += (all.empty() ? "" : ", ") + c;
        throw Error("knob '" + s.name + "' has no choice '" + name + "' (choices: " + all + ")");
    }
    return static_cast<int>(it - s.choices.begin());
}

std::string KnobRegistry::choiceDefineName(const std::string& knob, const std::string& choice) {
    std::string out = knob + "_" + choice;
    for (char& c : out) {
        const auto u = static_cast<unsigned char>(c);
        c = std::isalnum(u) ? static_cast<char>(std::toupper(u)) : '_';
    }
    return out;
}

std::vector<std::string> KnobRegistry::choiceDefines(EnumKnob k) const {
    const KnobSpec& s = specs_[k.id];
    std::vector<std::string> defines;
    for (size_t i = 0; i < s.choices.size(); ++i)
        defines.push_back(choiceDefineName(s.name, s.choices[i]) + "=" + std::to_string(i));
    return defines;
}

std::optional<int> KnobRegistry::find(const std::string& name) const {
    for (size_t i = 0; i < specs_.size(); ++i)
        if (specs_[i].name == name) {
            if (readLog_) readLog_->push_back(static_cast<int>(i));
            return static_cast<int>(i);
        }
    return std::nullopt;
}

void KnobRegistry::set(int id, double v) {
    const KnobSpec& s = specs_[id];
    if (!std::isfinite(v)) v = s.defaultValue;
    if (s.type != KnobType::Float) v = std::round(v);
    v = toKnobPrecision(s.type, std::clamp(v, s.minValue, s.maxValue));
    if (values_[id] != v) {
        values_[id] = v;
        ++generation_;
    }
}

void KnobRegistry::resetAll() {
    for (size_t i = 0; i < specs_.size(); ++i) reset(static_cast<int>(i));
}

void KnobRegistry::copyValues(const KnobRegistry& other) {
    if (other.specs_.size() != specs_.size()) throw Error("KnobRegistry::copyValues: different declarations");
    for (size_t i = 0; i < specs_.size(); ++i) set(static_cast<int>(i), other.values_[i]);
}

void KnobRegistry::setFromString(const std::string& givenName, const std::string& givenText) {
    std::string name = givenName, rawText = givenText;
    for (const KnobAlias& a : aliases_)
        if (a.knob.empty() && a.oldName == name) {
            warn(a.warning());
            name = a.newName;
            break;
        }
    for (const KnobAlias& a : aliases_)
        if (a.knob == name && lowerCase(a.oldName) == lowerCase(trimmed(rawText))) {
            warn(a.warning());
            rawText = a.newName;
            break;
        }
    const auto id = find(name);
    if (!id) {
        std::string best;
        size_t bestD = 1000;
        for (const auto& s : specs_) {
            const size_t d = distance(name, s.name);
            if (d < bestD) {
                bestD = d;
                best = s.name;
            }
        }
        throw Error("unknown knob '" + name + "'" + (bestD <= 4 ? " (did you mean '" + best + "'?)" : "") +
                    "; 'deferred-workbench list knobs' lists them");
    }
    const KnobSpec& s = specs_[*id];
    const std::string text = trimmed(rawText);
    double v = 0.0;
    switch (s.type) {
        case KnobType::Bool: {
            // Any case: TRUE, True and true alike (as 1, on and yes).
            std::string lower = text;
            for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
            if (lower == "true" || lower == "1" || lower == "on" || lower == "yes") v = 1.0;
            else if (lower == "false" || lower == "0" || lower == "off" || lower == "no") v = 0.0;
            else
                throw Error("knob '" + name + "' is a bool: expected true or false (or 1/0, on/off, yes/no), got '" +
                            text + "'");
            break;
        }
        case KnobType::Enum: {
            const auto it = std::find(s.choices.begin(), s.choices.end(), text);
            if (it == s.choices.end()) {
                std::string list;
                for (const auto& c : s.choices) list += (list.empty() ? "" : ", ") + c;
                throw Error("knob '" + name + "' takes one of: " + list + "; got '" + text + "'");
            }
            v = static_cast<double>(it - s.choices.begin());
            break;
        }
        case KnobType::Int:
        case KnobType::Float: {
            const char* first = text.data();
            const char* last = text.data() + text.size();
            auto [ptr, ec] = std::from_chars(first, last, v);
            if (ec == std::errc::result_out_of_range)
                throw Error("knob '" + name + "' = " + text + " is beyond the range of a 64-bit number");
            if (ec != std::errc() || ptr != last || !std::isfinite(v))
                throw Error("knob '" + name + "' expects a number, got '" + text + "'");
            if (const std::string problem = floatProblem(v); !problem.empty())
                throw Error("knob '" + name + "' = " + text + ": " + problem);
            if (s.type == KnobType::Int && v != std::floor(v))
                throw Error("knob '" + name + "' expects a whole number, got '" + text + "'");
            if (v < s.minValue || v > s.maxValue)
                throw Error("knob '" + name + "' = " + text + " is out of range " + formatRange(*id));
            break;
        }
    }
    set(*id, v);
}

void KnobRegistry::applyAssignment(const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw Error("--set expects name=value, got '" + assignment + "'");
    setFromString(trimmed(assignment.substr(0, eq)), assignment.substr(eq + 1));
}

std::string KnobRegistry::formatValue(int id, double v) const {
    const KnobSpec& s = specs_[id];
    switch (s.type) {
        case KnobType::Bool: return v != 0.0 ? "true" : "false";
        case KnobType::Enum: return s.choices[static_cast<size_t>(v)];
        case KnobType::Int: return std::to_string(static_cast<long long>(v));
        case KnobType::Float: return formatNumber(v);
    }
    return {};
}

std::string KnobRegistry::formatRange(int id) const {
    const KnobSpec& s = specs_[id];
    switch (s.type) {
        case KnobType::Bool: return "true|false";
        case KnobType::Enum: {
            std::string list;
            for (const auto& c : s.choices) list += (list.empty() ? "" : "|") + c;
            return list;
        }
        default: return "[" + formatNumber(s.minValue) + ", " + formatNumber(s.maxValue) + "]";
    }
}

}  // namespace dw
