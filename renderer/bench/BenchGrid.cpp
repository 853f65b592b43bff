#include "renderer/bench/BenchGrid.h"

#include <algorithm>
#include <charconv>

#include "renderer/Error.h"
#include "renderer/OptionLimits.h"

namespace dw {

std::vector<std::string> splitList(const std::string& text, const std::string& what) {
    std::vector<std::string> items;
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (item.empty()) throw Error(what + ": empty item in '" + text + "'");
        items.push_back(item);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return items;
}

BenchShard BenchShard::parse(const std::string& text) {
    const size_t slash = text.find('/');
    auto number = [&](const std::string& part, int& out) {
        auto [p, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
        return ec == std::errc() && p == part.data() + part.size() && !part.empty();
    };
    BenchShard s;
    if (slash == std::string::npos || !number(text.substr(0, slash), s.index) || !number(text.substr(slash + 1), s.count) ||
        !limits::kShards.holds(s.count) || s.index < 0 || s.index >= s.count)
        throw Error("--shard expects i/n with 0 <= i < n (e.g. 0/4), n from " + std::to_string(limits::kShards.min) + " to " +
                    std::to_string(limits::kShards.max) + ", got '" + text + "'");
    return s;
}

std::vector<BenchConfig> BenchGrid::configs(int sceneLights) const {
    const std::vector<int> counts = lights.empty() ? std::vector<int>{sceneLights} : lights;
    std::vector<BenchConfig> out;
    for (const auto& [w, h] : sizes)
        for (int n : counts) {
            // The knob axes as an odometer, the last axis turning fastest.
            std::vector<size_t> digit(knobAxes.size(), 0);
            while (true) {
                BenchConfig c;
                c.index = static_cast<int>(out.size());
                c.width = w;
                c.height = h;
                c.lights = n;
                for (size_t a = 0; a < knobAxes.size(); ++a) c.knobValues.push_back(knobAxes[a].values[digit[a]]);
                c.knobAt = digit;
                out.push_back(std::move(c));
                size_t a = knobAxes.size();
                while (a > 0 && ++digit[a - 1] == knobAxes[a - 1].values.size()) digit[--a] = 0;
                if (a == 0) break;
            }
        }
    return out;
}

std::vector<int> BenchGrid::groupsAlong(const std::vector<BenchConfig>& configs, const std::string& axis) const {
    std::vector<std::vector<std::string>> keys;  // group number -> the config's other axis values
    std::vector<int> groups;
    for (const auto& c : configs) {
        std::vector<std::string> key;
        if (axis != "size") key.push_back(c.size());
        if (axis != "lights") key.push_back(std::to_string(c.lights));
        for (size_t k = 0; k < knobAxes.size(); ++k)
            if (axis != knobAxes[k].knob) key.push_back(c.knobValues[k]);
        if (axis.empty()) key.push_back(std::to_string(c.index));  // no axis: a group per configuration
        auto it = std::find(keys.begin(), keys.end(), key);
        if (it == keys.end()) it = keys.insert(keys.end(), key);
        groups.push_back(static_cast<int>(it - keys.begin()));
    }
    return groups;
}

size_t BenchGrid::count() const {
    size_t n = sizes.size() * (lights.empty() ? 1 : lights.size());
    for (const auto& a : knobAxes) n *= a.values.size();
    return n;
}

BenchKnobAxis BenchGrid::parseSweep(const std::string& text) {
    const size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw Error("--sweep expects knob=value,value,... (e.g. lighting.strategy=volumes,fullscreen), got '" + text + "'");
    BenchKnobAxis axis;
    axis.knob = text.substr(0, eq);
    axis.values = splitList(text.substr(eq + 1), "--sweep " + axis.knob);
    checkAxis(axis);
    return axis;
}

void BenchGrid::checkAxis(const BenchKnobAxis& axis) {
    if (axis.knob.empty()) throw Error("--sweep expects knob=value,value,...: an axis has no name");
    if (axis.values.empty()) throw Error("--sweep " + axis.knob + ": no values");
    for (size_t i = 0; i < axis.values.size(); ++i) {
        if (axis.values[i].empty()) throw Error("--sweep " + axis.knob + ": an empty value");
        for (size_t j = 0; j < i; ++j)
            if (axis.values[i] == axis.values[j])
                throw Error("--sweep " + axis.knob + ": '" + axis.values[i] + "' is given twice");
    }
}

}  // namespace dw
