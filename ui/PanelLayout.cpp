#include "ui/PanelLayout.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace dw::ui {

namespace {

// Sizes of n items sharing `length` (gaps already taken out) by weight, each
// at least its minimum when the length allows it (the items that would fall
// below it get the minimum, the rest share what is left by weight), else in
// proportion to the minimums. Whole pixels: positions are rounded so
// neighbours never overlap.
std::vector<float> share(float length, const std::vector<float>& weights, const std::vector<float>& minimum) {
    const size_t n = weights.size();
    std::vector<float> size(n, 0.0f);
    if (n == 0) return size;
    length = std::max(length, 0.0f);
    const float least = std::accumulate(minimum.begin(), minimum.end(), 0.0f);
    if (length < least) {
        for (size_t i = 0; i < n; ++i) size[i] = least > 0.0f ? length * minimum[i] / least : length / static_cast<float>(n);
    } else {
        std::vector<bool> pinned(n, false);
        for (bool changed = true; changed;) {
            changed = false;
            float free = length, weight = 0.0f;
            for (size_t i = 0; i < n; ++i) {
                if (pinned[i]) free -= minimum[i];
                else weight += std::max(weights[i], 1e-6f);
            }
            for (size_t i = 0; i < n; ++i) {
                if (pinned[i]) {
                    size[i] = minimum[i];
                    continue;
                }
                size[i] = free * std::max(weights[i], 1e-6f) / weight;
                if (size[i] < minimum[i]) {
                    pinned[i] = true;
                    changed = true;
                }
            }
        }
    }
    // Round the running ends, so the pieces tile the length in whole pixels.
    std::vector<float> out(n);
    float end = 0.0f, prev = 0.0f;
    for (size_t i = 0; i < n; ++i) {
        end += size[i];
        const float e = i + 1 == n ? std::floor(length) : std::floor(end + 0.5f);
        out[i] = std::max(e - prev, 0.0f);
        prev = e;
    }
    return out;
}

template <typename T, typename F>
std::vector<int> visibleIndices(const std::vector<T>& items, F&& visible) {
    std::vector<int> v;
    for (size_t i = 0; i < items.size(); ++i)
        if (visible(items[i], static_cast<int>(i))) v.push_back(static_cast<int>(i));
    return v;
}

}  // namespace

const PanelRect* PanelLayout::Arrangement::find(const std::string& panel) const {
    for (const auto& p : panels)
        if (p.panel == panel) return &p.rect;
    return nullptr;
}

void PanelLayout::reset() {
    columns_ = {
        {{{{"Scene"}, {1.0f}, 0.34f}, {{"Lights"}, {1.0f}, 0.40f}, {{"Presets"}, {1.0f}, 0.26f}}, 0.18f},
        {{{{"Viewport", "Side view"}, {0.6f, 0.4f}, 0.64f}, {{"GPU timings", "Pixel probe", "Pareto"}, {0.6f, 0.4f, 0.5f}, 0.36f}}, 0.58f},
        {{{{"Pass inspector"}, {1.0f}, 0.40f},
          {{"Parameters"}, {1.0f}, 0.38f},
          {{"Messages"}, {1.0f}, 0.22f},
          {{"Keys"}, {1.0f}, 0.25f}},
         0.24f},
    };
}

std::vector<std::string> PanelLayout::panels() const {
    std::vector<std::string> v;
    for (const auto& c : columns_)
        for (const auto& r : c.rows) v.insert(v.end(), r.panels.begin(), r.panels.end());
    return v;
}

PanelLayout::Arrangement PanelLayout::arrange(float width, float height, float top,
                                              const std::function<bool(const std::string&)>& isOpen) const {
    Arrangement a;
    auto rowVisible = [&](const Row& r, int) {
        return std::any_of(r.panels.begin(), r.panels.end(), [&](const std::string& p) { return isOpen(p); });
    };
    auto columnVisible = [&](const Column& c, int) {
        return std::any_of(c.rows.begin(), c.rows.end(), [&](const Row& r) { return rowVisible(r, 0); });
    };
    const std::vector<int> cols = visibleIndices(columns_, columnVisible);
    if (cols.empty()) return a;
    const float areaH = std::max(std::floor(height - top), 0.0f);
    auto openItems = [&](const Row& r) { return visibleIndices(r.panels, [&](const std::string& p, int) { return isOpen(p); }); };
    // A column is at least as wide as its widest row of panels side by side.
    auto columnMin = [&](const Column& c) {
        float m = kMinWidth;
        for (const auto& r : c.rows) {
            const float n = static_cast<float>(openItems(r).size());
            if (n > 0) m = std::max(m, n * kMinWidth + (n - 1.0f) * kGap);
        }
        return m;
    };
    std::vector<float> cw, cmin;
    for (int c : cols) {
        cw.push_back(columns_[c].width);
        cmin.push_back(columnMin(columns_[c]));
    }
    const std::vector<float> colW = share(width - kGap * static_cast<float>(cols.size() - 1), cw, cmin);
    float x = 0.0f;
    for (size_t ci = 0; ci < cols.size(); ++ci) {
        const Column& col = columns_[cols[ci]];
        const std::vector<int> rows = visibleIndices(col.rows, rowVisible);
        std::vector<float> rh;
        for (int r : rows) rh.push_back(col.rows[r].height);
        const std::vector<float> rowH =
            share(areaH - kGap * static_cast<float>(rows.size() - 1), rh, std::vector<float>(rows.size(), kMinHeight));
        float y = top;
        for (size_t ri = 0; ri < rows.size(); ++ri) {
            const Row& row = col.rows[rows[ri]];
            const std::vector<int> items = openItems(row);
            std::vector<float> iw;
            for (int i : items) iw.push_back(row.widths[i]);
            const std::vector<float> itemW =
                share(colW[ci] - kGap * static_cast<float>(items.size() - 1), iw, std::vector<float>(items.size(), kMinWidth));
            float ix = x;
            for (size_t ii = 0; ii < items.size(); ++ii) {
                a.panels.push_back({row.panels[items[ii]], {ix, y, itemW[ii], rowH[ri]}});
                ix += itemW[ii];
                if (ii + 1 < items.size()) {
                    a.splitters.push_back({{ix, y, kGap, rowH[ri]}, true, cols[ci], rows[ri], items[ii], items[ii + 1],
                                           itemW[ii], itemW[ii + 1], kMinWidth, kMinWidth});
                    ix += kGap;
                }
            }
            y += rowH[ri];
            if (ri + 1 < rows.size()) {
                a.splitters.push_back({{x, y, colW[ci], kGap}, false, cols[ci], rows[ri], -1, rows[ri + 1], rowH[ri],
                                       rowH[ri + 1], kMinHeight, kMinHeight});
                y += kGap;
            }
        }
        x += colW[ci];
        if (ci + 1 < cols.size()) {
            a.splitters.push_back({{x, top, kGap, areaH}, true, cols[ci], -1, -1, cols[ci + 1], colW[ci], colW[ci + 1],
                                   cmin[ci], cmin[ci + 1]});
            x += kGap;
        }
    }
    return a;
}

void PanelLayout::drag(const Splitter& s, float delta) {
    const float total = s.firstSize + s.secondSize;
    if (total <= 0.0f) return;
    float first = s.firstSize + delta;
    if (total >= s.firstMin + s.secondMin) first = std::clamp(first, s.firstMin, total - s.secondMin);
    else first = std::clamp(first, 0.0f, total);
    auto move = [&](float& a, float& b) {
        const float sum = a + b;
        a = sum * first / total;
        b = sum - a;
    };
    if (s.column < 0 || s.column >= static_cast<int>(columns_.size())) return;
    Column& col = columns_[s.column];
    if (s.row < 0) {
        if (s.next < static_cast<int>(columns_.size())) move(col.width, columns_[s.next].width);
    } else if (s.item < 0) {
        if (s.row < static_cast<int>(col.rows.size()) && s.next < static_cast<int>(col.rows.size()))
            move(col.rows[s.row].height, col.rows[s.next].height);
    } else if (s.row < static_cast<int>(col.rows.size())) {
        Row& row = col.rows[s.row];
        if (s.item < static_cast<int>(row.widths.size()) && s.next < static_cast<int>(row.widths.size()))
            move(row.widths[s.item], row.widths[s.next]);
    }
}

nlohmann::json PanelLayout::toJson() const {
    nlohmann::json cols = nlohmann::json::array();
    for (const auto& c : columns_) {
        nlohmann::json rows = nlohmann::json::array();
        for (const auto& r : c.rows) rows.push_back({{"panels", r.panels}, {"widths", r.widths}, {"height", r.height}});
        cols.push_back({{"width", c.width}, {"rows", rows}});
    }
    return {{"columns", cols}};
}

std::vector<std::string> PanelLayout::fromJson(const nlohmann::json& j) {
    // What the file has is taken where this version has the same place: a
    // column by its index, a row by its index in the column, a panel's width
    // by the panel's name in that row (a file without "panels" lists the
    // widths in this version's order). The rest keeps the default: a panel
    // this version added (Pareto, next to the timings and the probe) gets its
    // default width beside the saved ones. What the file has and this
    // version cannot place, or a weight that is not one, is dropped and said.
    PanelLayout shape;
    std::vector<std::string> dropped;
    auto weight = [&](const nlohmann::json& v, const std::string& what, float& into) {
        if (v.is_null()) return;  // not in the file: the default
        if (!v.is_number()) {
            dropped.push_back(what + " is not a number");
            return;
        }
        const double d = v.get<double>();
        if (!std::isfinite(d) || d <= 0.0 || d > 1e6) {
            dropped.push_back(what + " is not a positive weight");
            return;
        }
        into = static_cast<float>(d);
    };
    if (!j.is_object() || !j.contains("columns") || !j["columns"].is_array())
        throw std::runtime_error("expected an object with \"columns\": an array");
    const nlohmann::json& jcols = j["columns"];
    if (jcols.size() > shape.columns_.size())
        dropped.push_back("columns past the " + std::to_string(shape.columns_.size()) + " this version has");
    for (size_t c = 0; c < std::min(jcols.size(), shape.columns_.size()); ++c) {
        const nlohmann::json& jc = jcols[c];
        Column& col = shape.columns_[c];
        const std::string at = "columns[" + std::to_string(c) + "]";
        if (!jc.is_object()) {
            dropped.push_back(at + " is not an object");
            continue;
        }
        weight(jc.value("width", nlohmann::json()), at + ".width", col.width);
        const nlohmann::json& jrows = jc.value("rows", nlohmann::json::array());
        if (!jrows.is_array()) {
            dropped.push_back(at + ".rows is not an array");
            continue;
        }
        if (jrows.size() > col.rows.size())
            dropped.push_back(at + ": rows past the " + std::to_string(col.rows.size()) + " this version has");
        for (size_t r = 0; r < std::min(jrows.size(), col.rows.size()); ++r) {
            const nlohmann::json& jr = jrows[r];
            Row& row = col.rows[r];
            const std::string rat = at + ".rows[" + std::to_string(r) + "]";
            if (!jr.is_object()) {
                dropped.push_back(rat + " is not an object");
                continue;
            }
            weight(jr.value("height", nlohmann::json()), rat + ".height", row.height);
            const nlohmann::json& jw = jr.value("widths", nlohmann::json());
            const nlohmann::json& jp = jr.value("panels", nlohmann::json());
            if (jw.is_null()) continue;
            if (!jw.is_array()) {
                dropped.push_back(rat + ".widths is not an array");
                continue;
            }
            if (jp.is_null()) {
                if (jw.size() != row.widths.size()) {
                    dropped.push_back(rat + ".widths: " + std::to_string(jw.size()) + " without \"panels\", this row has " +
                                      std::to_string(row.widths.size()));
                    continue;
                }
                for (size_t i = 0; i < row.widths.size(); ++i) weight(jw[i], rat + ".widths[" + std::to_string(i) + "]", row.widths[i]);
                continue;
            }
            if (!jp.is_array() || jp.size() != jw.size()) {
                dropped.push_back(rat + ": \"panels\" and \"widths\" do not pair up");
                continue;
            }
            for (size_t k = 0; k < jp.size(); ++k) {
                const auto it = jp[k].is_string() ? std::find(row.panels.begin(), row.panels.end(), jp[k].get<std::string>())
                                                  : row.panels.end();
                if (it == row.panels.end()) {
                    dropped.push_back(rat + ": " + (jp[k].is_string() ? "the panel '" + jp[k].get<std::string>() + "'" : "a panel name") +
                                      " this version does not place there");
                    continue;
                }
                weight(jw[k], rat + ".widths[" + std::to_string(k) + "]", row.widths[static_cast<size_t>(it - row.panels.begin())]);
            }
        }
    }
    columns_ = std::move(shape.columns_);
    return dropped;
}

}  // namespace dw::ui
