#include "renderer/bench/TradeoffSweep.h"

#include <algorithm>
#include <cmath>

#include "renderer/Error.h"

namespace dw {

size_t TradeoffSweep::count() const {
    if (axes.empty()) return 0;
    if (!listed.empty()) return listed.size();
    size_t n = 1;
    for (const auto& a : axes) n = oneAtATime ? n + (a.values.size() - 1) : n * a.values.size();
    return n;
}

// Every combination, the last axis fastest: each point's value positions.
std::vector<std::vector<size_t>> TradeoffSweep::gridChoices() const {
    std::vector<std::vector<size_t>> all;
    std::vector<size_t> at(axes.size(), 0);
    const size_t n = count();
    for (size_t i = 0; i < n; ++i) {
        all.push_back(at);
        for (size_t a = axes.size(); a-- > 0;) {
            if (++at[a] < axes[a].values.size()) break;
            at[a] = 0;
        }
    }
    return all;
}

// The centre first, then each axis' other values in order, the rest at the centre.
std::vector<std::vector<size_t>> TradeoffSweep::oneAtATimeChoices() const {
    if (centre.size() != axes.size()) throw Error("a one-at-a-time sweep needs a centre value per axis");
    std::vector<size_t> middle;
    for (size_t a = 0; a < axes.size(); ++a) {
        const auto it = std::find(axes[a].values.begin(), axes[a].values.end(), centre[a]);
        if (it == axes[a].values.end())
            throw Error("a one-at-a-time sweep's centre '" + centre[a] + "' is not a value of " + axes[a].name);
        middle.push_back(static_cast<size_t>(it - axes[a].values.begin()));
    }
    std::vector<std::vector<size_t>> all{middle};
    for (size_t a = 0; a < axes.size(); ++a)
        for (size_t v = 0; v < axes[a].values.size(); ++v) {
            if (v == middle[a]) continue;
            std::vector<size_t> p = middle;
            p[a] = v;
            all.push_back(std::move(p));
        }
    return all;
}

// The listed points, each position checked against its axis.
std::vector<std::vector<size_t>> TradeoffSweep::listedChoices() const {
    for (size_t i = 0; i < listed.size(); ++i) {
        if (listed[i].size() != axes.size())
            throw Error("listed point " + std::to_string(i) + " has " + std::to_string(listed[i].size()) +
                        " value(s) for " + std::to_string(axes.size()) + " axes");
        for (size_t a = 0; a < axes.size(); ++a)
            if (listed[i][a] >= axes[a].values.size())
                throw Error("listed point " + std::to_string(i) + ": " + axes[a].name + " has no value " +
                            std::to_string(listed[i][a]));
    }
    return listed;
}

std::vector<TradeoffPoint> TradeoffSweep::points() const {
    if (axes.empty()) throw Error("tradeoff needs at least one axis (--sweep, --presets or --knobs)");
    const std::vector<std::vector<size_t>> all = !listed.empty() ? listedChoices()
                                                 : oneAtATime      ? oneAtATimeChoices()
                                                                   : gridChoices();
    std::vector<TradeoffPoint> out;
    for (size_t i = 0; i < all.size(); ++i) {
        std::vector<std::string> values;
        for (size_t a = 0; a < axes.size(); ++a) values.push_back(axes[a].values[all[i][a]]);
        const bool excluded = exclusion.excludes([&](const std::string& axis) {
            for (size_t a = 0; a < axes.size(); ++a)
                if (axes[a].name == axis) return values[a];
            return std::string();
        });
        if (!excluded) out.push_back({static_cast<int>(i), std::move(values), all[i]});
    }
    if (out.empty())
        throw Error("the sweep is empty after --exclude: every one of its " + std::to_string(all.size()) +
                    " point(s) is left out");
    return out;
}

TradeoffSweep TradeoffSweep::aroundCurrent(const KnobRegistry& current) {
    TradeoffSweep s;
    s.oneAtATime = true;
    for (const KnobSpec& spec : current.specs()) {
        if (!spec.tradeoff) continue;
        const int id = *current.find(spec.name);
        const double v = current.value(id);
        std::vector<double> raw;
        if (spec.type == KnobType::Bool) {
            raw = {0.0, 1.0};
        } else if (spec.type == KnobType::Enum) {
            for (size_t i = 0; i < spec.choices.size(); ++i) raw.push_back(static_cast<double>(i));
        } else if (v != 0.0) {
            for (double f : {0.25, 0.5, 1.0, 2.0, 4.0}) raw.push_back(v * f);
        } else {
            for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) raw.push_back(spec.minValue + f * (spec.maxValue - spec.minValue));
        }
        TradeoffAxis axis;
        axis.name = spec.name;
        for (double r : raw) {
            r = std::clamp(r, spec.minValue, spec.maxValue);
            if (spec.type == KnobType::Int) r = std::round(r);
            const std::string text = current.formatValue(id, r);
            if (std::find(axis.values.begin(), axis.values.end(), text) == axis.values.end()) axis.values.push_back(text);
        }
        const std::string centre = current.format(id);
        if (std::find(axis.values.begin(), axis.values.end(), centre) == axis.values.end()) axis.values.push_back(centre);
        if (axis.values.size() < 2) continue;
        s.centre.push_back(centre);
        s.axes.push_back(std::move(axis));
    }
    return s;
}

}  // namespace dw
