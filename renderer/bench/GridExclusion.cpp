#include "renderer/bench/GridExclusion.h"

#include <algorithm>

#include "renderer/Error.h"
#include "renderer/bench/BenchGrid.h"

namespace dw {

void GridExclusion::add(const std::string& text) {
    Corner corner;
    corner.text = text;
    for (const auto& item : splitList(text, "--exclude")) {
        const size_t eq = item.find('=');
        if (eq == std::string::npos) {
            if (corner.conditions.empty())
                throw Error("--exclude expects axis=value[,value...], e.g. lighting.strategy=fullscreen,lights=10000; got '" +
                            text + "'");
            corner.conditions.back().second.push_back(item);
            continue;
        }
        const std::string axis = item.substr(0, eq), value = item.substr(eq + 1);
        if (axis.empty() || value.empty()) throw Error("--exclude: expected axis=value, got '" + item + "' in '" + text + "'");
        auto it = std::find_if(corner.conditions.begin(), corner.conditions.end(),
                               [&](const auto& c) { return c.first == axis; });
        if (it != corner.conditions.end()) throw Error("--exclude '" + text + "' names " + axis + " twice");
        corner.conditions.push_back({axis, {value}});
    }
    corners_.push_back(std::move(corner));
}

void GridExclusion::resolve(const Axes& axes,
                            const std::function<std::string(const std::string&, const std::string&)>& canonical) {
    for (auto& corner : corners_)
        for (auto& [axis, values] : corner.conditions) {
            auto a = std::find_if(axes.begin(), axes.end(), [&](const auto& x) { return x.first == axis; });
            if (a == axes.end()) {
                std::string names;
                for (const auto& x : axes) names += (names.empty() ? "" : ", ") + x.first;
                throw Error("--exclude " + corner.text + ": '" + axis + "' is not an axis of this sweep (" + names + ")");
            }
            for (auto& v : values) {
                const std::string given = v;
                if (canonical) v = canonical(axis, v);
                if (std::find(a->second.begin(), a->second.end(), v) == a->second.end()) {
                    std::string all;
                    for (const auto& x : a->second) all += (all.empty() ? "" : ", ") + x;
                    throw Error("--exclude " + corner.text + ": " + axis + " is never '" + given + "' in this sweep (" +
                                all + ")");
                }
            }
        }
}

bool GridExclusion::excludes(const std::function<std::string(const std::string&)>& valueOf) const {
    for (const auto& corner : corners_) {
        bool all = true;
        for (const auto& [axis, values] : corner.conditions)
            if (std::find(values.begin(), values.end(), valueOf(axis)) == values.end()) {
                all = false;
                break;
            }
        if (all) return true;
    }
    return false;
}

}  // namespace dw
