#include "ui/TimingsPanel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unordered_map>
#include <vector>

#include "ui/Widgets.h"

namespace dw::ui {

unsigned passColor(const std::string& name) {
    unsigned h = 2166136261u;
    for (char c : name) h = (h ^ static_cast<unsigned char>(c)) * 16777619u;
    float r, g, b;
    ImGui::ColorConvertHSVtoRGB(static_cast<float>(h % 360) / 360.0f, 0.55f, 0.9f, r, g, b);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, 0.85f));
}

std::vector<float> axisTicks(float bottom, float top, bool logScale, int count) {
    std::vector<float> ticks;
    if (!(top > 0.0f) || !std::isfinite(top) || count < 1) return ticks;
    if (logScale) {
        bottom = std::max(bottom, top * 1e-6f);
        const int lo = static_cast<int>(std::floor(std::log10(bottom))), hi = static_cast<int>(std::ceil(std::log10(top)));
        const int every = std::max(1, (hi - lo + count - 1) / count);
        // Within two decades, 2 and 5 times the powers of ten as well, so a
        // narrow range (20 to 80 ms) still has labelled lines.
        const bool fine = hi - lo <= 2;
        for (int e = lo; e <= hi; e += every)
            for (float m : {1.0f, 2.0f, 5.0f}) {
                if (m != 1.0f && !fine) continue;
                const float v = m * std::pow(10.0f, static_cast<float>(e));
                if (v >= bottom * 0.999f && v <= top * 1.001f) ticks.push_back(v);
            }
        if (ticks.size() < 2) {
            // Not even two: the range's ends, to 2 significant digits.
            auto round2 = [](float v) {
                const float mag = std::pow(10.0f, std::floor(std::log10(v)) - 1.0f);
                return std::round(v / mag) * mag;
            };
            const float b = round2(bottom * 1.05f), t = round2(top * 0.95f);
            ticks.clear();
            ticks.push_back(b);
            if (t > b) ticks.push_back(t);
        }
        return ticks;
    }
    const float raw = top / static_cast<float>(count);
    const float mag = std::pow(10.0f, std::floor(std::log10(raw)));
    const float norm = raw / mag;
    const float step = (norm <= 1.0f ? 1.0f : norm <= 2.0f ? 2.0f : norm <= 5.0f ? 5.0f : 10.0f) * mag;
    for (int i = 0; static_cast<float>(i) * step <= top * 1.0001f && i < 1000; ++i) ticks.push_back(static_cast<float>(i) * step);
    return ticks;
}

void TimingsPanel::watchForChanges(UiState& state, RenderSession& session) {
    PassTimer& timer = session.pipeline().timer();
    KnobRegistry& knobs = session.knobs();
    // Another scene or render size: another configuration, so the statistics
    // start over from its first frame (UiState::configSince, set by the frame
    // loop when it rendered it; it stays: in an idle window it may be the only one).
    const bool newScene = session.scene().source != sceneSource;
    if (state.configSince != configSeen || newScene) {
        if (state.configSince != configSeen) timer.clearHistoryBefore(state.configSince);
        configSeen = state.configSince;
        sceneSource = session.scene().source;
        if (state.measure.active()) state.measure.cancel(knobs, "cancelled: the scene or the render size changed");
        else if (newScene) state.measure = ChangeMeasurement();
        // A measurement renders both sides of a change itself, so a new
        // render size (the auto scale stepping) keeps the change and the
        // value being typed; another scene's knobs start over.
        if (newScene) {
            change.reset();
            watcher.reset(knobs);
            return;
        }
    }
    // The AOV cost guard put the knobs back: no change of the user's (the
    // refused one is not measurable either: measure would render it).
    if (state.knobsPutBack != putBackSeen) {
        putBackSeen = state.knobsPutBack;
        if (state.measure.active()) state.measure.cancel(knobs, "cancelled: the AOV cost guard put the knobs back");
        // The last change stays measurable only if its values still hold.
        if (change)
            for (size_t i = 0; i < change->knobs.size(); ++i)
                if (knobs.value(change->knobs[i]) != change->after[i]) {
                    change.reset();
                    break;
                }
        watcher.reset(knobs);
        return;
    }
    // While a measurement runs it sets the knobs itself.
    if (state.measure.active()) return;
    // A value is committed when no widget is being edited (a slider let go,
    // a typed value entered): never each keystroke of "64".
    if (auto c = watcher.update(knobs, ImGui::IsAnyItemActive())) {
        // A change measured already (the Pareto panel's fit budget measures
        // the one it applies) keeps its verdict; any other's was of an earlier change.
        const ChangeMeasurement& m = state.measure;
        const bool measured = m.state() == ChangeMeasurement::State::Done && m.change().knobs == c->knobs &&
                              m.change().before == c->before && m.change().after == c->after;
        change = std::move(c);
        if (!measured) state.measure = ChangeMeasurement();
    }
}

void TimingsPanel::startMeasure(UiState& state, RenderSession& session) {
    if (!change) return;
    // Which passes the change can reach: those reading a changed knob (the
    // pipeline learnt them when it made the passes) and everything downstream.
    const std::set<std::string> reached = passesReachedBy(session.pipeline(), change->knobs);
    session.pipeline().timer().setPaused(false);  // paused, the frames' times would never be recorded
    state.measure.start(*change, measureSettings, reached);
}

void TimingsPanel::toolbar(UiState& state, PassTimer& timer, RenderSession& session) {
    // Items go on the line while they fit and wrap when not, so every one
    // (the CSV export last) stays reachable in a narrow panel.
    const ImGuiStyle& style = ImGui::GetStyle();
    auto checkboxWidth = [&](const char* label) {
        return ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x;
    };
    ImGui::Checkbox("record", &state.timingCapture);
    if (ImGui::IsItemHovered())
        tooltip("render every frame and time it (the resolution scale holds still);\n"
                          "off: a frame is rendered only when something it shows changed");
    sameLineIfFits(checkboxWidth("pause"));
    bool paused = timer.paused();
    if (ImGui::Checkbox("pause", &paused)) timer.setPaused(paused);
    sameLineIfFits(110.0f + style.ItemInnerSpacing.x + ImGui::CalcTextSize("frames").x);
    ImGui::SetNextItemWidth(110);
    ImGui::SliderInt("frames", &window, 30, static_cast<int>(PassTimer::kHistory));
    sameLineIfFits(checkboxWidth("stacked"));
    ImGui::Checkbox("stacked", &stacked);
    if (ImGui::IsItemHovered()) tooltip("areas stacked up to the frame total; off: one line per pass");
    sameLineIfFits(checkboxWidth("log"));
    ImGui::Checkbox("log", &logScale);
    if (ImGui::IsItemHovered()) tooltip("logarithmic y axis (passes drawn as lines)");
    sameLineIfFits(checkboxWidth("own CPU"));
    bool isolate = timer.isolateCpu();
    if (ImGui::Checkbox("own CPU", &isolate)) {
        timer.setIsolateCpu(isolate);
        // Frames timed the other way (some still in flight) no longer compare.
        timer.clearHistoryBefore(session.pipeline().frameIndex());
        if (state.measure.active()) state.measure.cancel(session.knobs(), "cancelled: own CPU timing was switched");
    }
    if (ImGui::IsItemHovered())
        tooltip("Adds a CPU column: the time a pass spends issuing its own work.\n"
                          "Before each pass the frame waits (on a GL fence) for the GPU to finish\n"
                          "the passes before it, so no pass is charged for waiting on another.\n"
                          "Frames get slower while this is on; the history starts over.");
    sameLineIfFits(checkboxWidth("counters"));
    bool counting = timer.counting();
    if (ImGui::Checkbox("counters", &counting)) timer.setCounting(counting);
    noteItem("timings.counters");
    if (ImGui::IsItemHovered())
        tooltip("Adds each pass's cost counters of the last frame: fragment shader invocations,\n"
                "samples passed (depth and stencil), primitives and vertices submitted, compute\n"
                "invocations and the bytes of its declared resources. Exact: they repeat bit for\n"
                "bit (docs/bench.md says which driver counts what).");
    // The file field and its button together: at least 120 px of field.
    const float exportW = ImGui::CalcTextSize("export CSV").x + style.FramePadding.x * 2.0f;
    sameLineIfFits(120.0f + style.ItemSpacing.x + exportW);
    ImGui::SetNextItemWidth(std::clamp(ImGui::GetContentRegionAvail().x - exportW - style.ItemSpacing.x, 120.0f, 360.0f));
    ImGui::InputText("##csv", csvPath, sizeof(csvPath));
    if (ImGui::IsItemHovered()) tooltip("CSV file; a bare name goes to %s", state.exportDir.c_str());
    sameLineIfFits(exportW);
    if (ImGui::Button("export CSV")) {
        // A bare name goes to the export folder, not wherever the app was started.
        std::filesystem::path path(csvPath);
        if (path.is_relative() && !state.exportDir.empty()) path = std::filesystem::path(state.exportDir) / path;
        try {
            std::error_code ec;
            std::filesystem::create_directories(path.parent_path(), ec);
            timer.writeCsv(path.string());
            state.log.done("timings saved to " + std::filesystem::absolute(path).string(), state.time, "export timings");
        } catch (const std::exception& e) {
            state.log.error(e.what(), state.time, "export timings");
        }
    }
    noteItem("timings.export");
}

void TimingsPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    watchForChanges(state, session);
    PassTimer& timer = session.pipeline().timer();
    toolbar(state, timer, session);
    changeBar(state, session);

    std::vector<std::string> passes;
    for (const auto& rec : state.report.passes)
        if (timer.find(rec.name)) passes.push_back(rec.name);
    graph(state, timer, passes);
    changeCost(state, session);
    table(timer, passes, state.report);
    // CPU frame time of the whole app loop (UI included), beside the GPU numbers.
    if (!state.cpuFrameMs.empty()) {
        std::vector<float> cpu(state.cpuFrameMs.begin(), state.cpuFrameMs.end());
        const TimingStats c = computeStats(cpu);
        char overlay[96];
        std::snprintf(overlay, sizeof(overlay), "app CPU frame: median %.2f ms, max %.2f ms", c.median, c.max);
        ImGui::PlotLines("##cpu", cpu.data(), static_cast<int>(cpu.size()), 0, overlay, 0.0f, c.max * 1.2f,
                         ImVec2(ImGui::GetContentRegionAvail().x, 36));
    }
    ImGui::End();
}

namespace {

// Every shown pass's samples aligned on the frames of the whole frame's series.
struct GraphSeries {
    size_t n = 0;                            // frames (the newest of the whole frame's, at most the window)
    std::vector<float> totals;               // the whole frame's GPU ms, per frame
    std::vector<std::uint64_t> frames;       // their frame indices
    std::vector<std::string> shown;          // the passes drawn
    std::vector<std::vector<float>> values;  // GPU ms per shown pass and frame (0: no sample)
};

GraphSeries graphSeries(PassTimer& timer, const std::vector<std::string>& passes, int window,
                        const std::set<std::string>& hidden, const std::string& solo) {
    GraphSeries g;
    const PassTimer::Series* total = timer.find(PassTimer::kFrameSeries);
    g.n = total ? std::min(total->samples.size(), static_cast<size_t>(window)) : 0;
    const size_t n = g.n;
    std::unordered_map<std::uint64_t, size_t> column;
    g.totals.assign(n, 0.0f);
    g.frames.assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
        const TimingSample& t = total->samples[total->samples.size() - n + i];
        column[t.frame] = i;
        g.totals[i] = t.gpuMs;
        g.frames[i] = t.frame;
    }
    for (const auto& p : passes)
        if (solo.empty() ? !hidden.count(p) : p == solo) g.shown.push_back(p);
    g.values.assign(g.shown.size(), std::vector<float>(n, 0.0f));
    for (size_t p = 0; p < g.shown.size(); ++p)
        for (const auto& t : timer.find(g.shown[p])->samples) {
            auto it = column.find(t.frame);
            if (it != column.end()) g.values[p][it->second] = t.gpuMs;
        }
    return g;
}

// The plot's box (p0 top left, p1 bottom right, in screen pixels), its y
// range in ms (a log axis from `bottom`), and where a frame's column and a
// time are drawn.
struct GraphBox {
    ImVec2 p0, p1, size;
    float bottom = 0.0f, top = 1.0f;
    bool logScale = false;
    size_t columns = 0;
    float Y(float ms) const {
        float t;
        if (logScale) t = (std::log10(std::max(ms, bottom)) - std::log10(bottom)) / (std::log10(top) - std::log10(bottom));
        else t = ms / top;
        return p1.y - size.y * std::clamp(t, 0.0f, 1.0f);
    }
    float X(size_t i) const {
        return columns > 1 ? p0.x + size.x * static_cast<float>(i) / static_cast<float>(columns - 1) : p0.x;
    }
};

// The y range: up to the 95th percentile (one slow frame, a resize or a
// shader compile, does not flatten the rest; taller values are clipped).
void graphRange(const GraphSeries& g, bool stack, bool drawTotal, GraphBox& box) {
    const size_t n = g.n;
    std::vector<float> heights, positives;
    for (size_t i = 0; i < n; ++i) {
        float sum = 0.0f, hi = 0.0f;
        for (const auto& v : g.values) {
            sum += v[i];
            hi = std::max(hi, v[i]);
            if (v[i] > 0.0f) positives.push_back(v[i]);
        }
        heights.push_back(stack ? std::max(sum, drawTotal ? g.totals[i] : 0.0f) : std::max(hi, drawTotal ? g.totals[i] : 0.0f));
        if (drawTotal && g.totals[i] > 0.0f) positives.push_back(g.totals[i]);
    }
    std::sort(heights.begin(), heights.end());
    float top = n ? heights[std::min(n - 1, n * 95 / 100)] * 1.15f : 1.0f;
    top = std::max(top, 1e-3f);
    float bottom = 0.0f;
    if (box.logScale) {
        std::sort(positives.begin(), positives.end());
        bottom = positives.empty() ? top * 1e-3f : std::max(positives.front() * 0.7f, top * 1e-5f);
        if (bottom >= top) bottom = top * 0.1f;
    }
    box.top = top;
    box.bottom = bottom;
}

// Axis: ticks, grid lines and labels left of the plot.
void graphAxis(const GraphBox& box, ImDrawList* dl, float labelH) {
    for (float t : axisTicks(box.bottom, box.top, box.logScale)) {
        const float y = box.Y(t);
        dl->AddLine(ImVec2(box.p0.x, y), ImVec2(box.p1.x, y), IM_COL32(70, 70, 78, 255));
        char label[32];
        std::snprintf(label, sizeof(label), t >= 100.0f || t == 0.0f ? "%.0f ms" : t >= 1.0f ? "%.3g ms" : "%.2g ms", t);
        const float w = ImGui::CalcTextSize(label).x;
        dl->AddText(ImVec2(box.p0.x - w - 4.0f, y - labelH * 0.5f), IM_COL32(170, 170, 175, 255), label);
    }
}

// Each shown pass, stacked areas or lines, and the whole frame in white;
// with fewer than two columns, a line saying the results are awaited.
void graphLines(const GraphSeries& g, const GraphBox& box, bool stack, bool drawTotal, ImDrawList* dl) {
    const size_t columns = box.columns;
    if (columns < 2) {
        dl->AddText(ImVec2(box.p0.x + 6, box.p0.y + 4), IM_COL32(160, 160, 160, 255), "waiting for timer results");
        return;
    }
    auto X = [&](size_t i) { return box.X(i); };
    auto Y = [&](float ms) { return box.Y(ms); };
    std::vector<float> base(columns, 0.0f);
    dl->PushClipRect(box.p0, box.p1, true);
    for (size_t p = 0; p < g.shown.size(); ++p) {
        const unsigned col = passColor(g.shown[p]);
        for (size_t i = 0; i + 1 < columns; ++i) {
            const float lo0 = stack ? base[i] : 0.0f, lo1 = stack ? base[i + 1] : 0.0f;
            const float hi0 = lo0 + g.values[p][i], hi1 = lo1 + g.values[p][i + 1];
            if (stack)
                dl->AddQuadFilled(ImVec2(X(i), Y(lo0)), ImVec2(X(i), Y(hi0)), ImVec2(X(i + 1), Y(hi1)), ImVec2(X(i + 1), Y(lo1)), col);
            else
                dl->AddLine(ImVec2(X(i), Y(hi0)), ImVec2(X(i + 1), Y(hi1)), col, 1.5f);
        }
        if (stack)
            for (size_t i = 0; i < columns; ++i) base[i] += g.values[p][i];
    }
    if (drawTotal)
        for (size_t i = 0; i + 1 < columns; ++i)
            dl->AddLine(ImVec2(X(i), Y(g.totals[i])), ImVec2(X(i + 1), Y(g.totals[i + 1])), IM_COL32(255, 255, 255, 200), 1.0f);
    dl->PopClipRect();
}

// Hover readout: the frame under the mouse (`mx`), every shown pass and the total.
void graphReadout(const GraphSeries& g, const GraphBox& box, bool single, bool drawTotal, float mx, ImDrawList* dl) {
    const size_t n = g.n;
    // With one frame both columns are that frame.
    const size_t i = single ? 0
                            : std::min(n - 1, static_cast<size_t>(std::lround((mx - box.p0.x) / box.size.x *
                                                                              static_cast<float>(n - 1))));
    dl->AddLine(ImVec2(box.X(i), box.p0.y), ImVec2(box.X(i), box.p1.y), IM_COL32(255, 255, 255, 110));
    ImGui::BeginTooltip();
    ImGui::Text("frame %llu", static_cast<unsigned long long>(g.frames[i]));
    for (size_t p = g.shown.size(); p-- > 0;) {
        ImGui::ColorButton(("##t" + g.shown[p]).c_str(), ImGui::ColorConvertU32ToFloat4(passColor(g.shown[p])),
                           ImGuiColorEditFlags_NoTooltip, ImVec2(9, 9));
        ImGui::SameLine();
        ImGui::Text("%-16s %9.3f ms", g.shown[p].c_str(), g.values[p][i]);
    }
    if (drawTotal) ImGui::Text("%-16s %9.3f ms", "whole frame", g.totals[i]);
    ImGui::EndTooltip();
}

}  // namespace

void TimingsPanel::graph(UiState& state, PassTimer& timer, const std::vector<std::string>& passes) {
    // Align every pass's samples on the frames of the total.
    GraphSeries g = graphSeries(timer, passes, window, hidden, solo);
    const size_t n = g.n;
    const bool stack = stacked && !logScale && solo.empty();
    const bool drawTotal = solo.empty();

    char caption[160];
    std::snprintf(caption, sizeof(caption), "%s, GPU ms per pass%s, %zu frame%s%s", timer.paused() ? "paused" : "live",
                  drawTotal ? " (white: whole frame)" : "", n, n == 1 ? "" : "s",
                  solo.empty() ? "" : (" - only " + solo).c_str());
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", caption);
    ImGui::PopStyleColor();

    const float axisW = 52.0f, labelH = ImGui::GetTextLineHeight();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    GraphBox box;
    box.size = ImVec2(std::max(avail.x - axisW, 40.0f), std::max(avail.y * 0.42f, 80.0f));
    box.p0 = ImVec2(at.x + axisW, at.y + labelH * 0.5f);
    box.p1 = ImVec2(box.p0.x + box.size.x, box.p0.y + box.size.y);
    box.logScale = logScale;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(box.p0, box.p1, IM_COL32(22, 22, 26, 255));
    graphRange(g, stack, drawTotal, box);
    // One frame (an idle window rendered once) is drawn across the plot,
    // as two columns of the same values.
    const bool single = n == 1;
    if (single) {
        g.totals.push_back(g.totals[0]);
        for (auto& v : g.values) v.push_back(v[0]);
    }
    box.columns = single ? 2 : n;
    graphAxis(box, dl, labelH);
    graphLines(g, box, stack, drawTotal, dl);
    ImGui::SetCursorScreenPos(at);
    ImGui::InvisibleButton("##plot", ImVec2(axisW + box.size.x, box.size.y + labelH));
    if (ImGui::IsItemHovered() && n >= 1) {
        const float mx = ImGui::GetIO().MousePos.x;
        if (mx >= box.p0.x && mx <= box.p1.x) graphReadout(g, box, single, drawTotal, mx, dl);
    }
    ImGui::TextDisabled("older  <-  frames  ->  newest");
    (void)state;
}

namespace {

// A fixed column wide enough for "99999.999" and its header, with padding.
float numberColumnWidth(const char* header) {
    return std::max(ImGui::CalcTextSize("99999.999").x, ImGui::CalcTextSize(header).x) + ImGui::GetStyle().CellPadding.x * 2.0f + 6.0f;
}

float nameColumnWidth(const std::vector<std::string>& names, float extra) {
    float w = ImGui::CalcTextSize("whole frame").x;
    for (const auto& n : names) w = std::max(w, ImGui::CalcTextSize(n.c_str()).x);
    return w + extra;
}

}  // namespace

void TimingsPanel::table(PassTimer& timer, const std::vector<std::string>& passes, const FrameReport& report) {
    const bool cpu = timer.isolateCpu();
    const bool counted = timer.counting();
    const int columns = (cpu ? 8 : 7) + (counted ? PassCounts::kCount : 0);
    // The rest of the panel but the app CPU plot under it; it scrolls both
    // ways when the panel is smaller than its rows and columns.
    const float height = std::max(ImGui::GetContentRegionAvail().y - 46.0f, 5.0f * ImGui::GetFrameHeight());
    if (!ImGui::BeginTable("stats", columns,
                           ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollY | ImGuiTableFlags_ScrollX |
                               ImGuiTableFlags_BordersInnerV,
                           ImVec2(0.0f, height)))
        return;
    ImGui::TableSetupScrollFreeze(1, 1);
    ImGui::TableSetupColumn("show", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFrameHeight() + 4.0f);
    ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthFixed, nameColumnWidth(passes, 24.0f));
    for (const char* h : {"last", "median", "mean", "min", "max"}) ImGui::TableSetupColumn(h, ImGuiTableColumnFlags_WidthFixed, numberColumnWidth(h));
    if (cpu) ImGui::TableSetupColumn("own CPU", ImGuiTableColumnFlags_WidthFixed, numberColumnWidth("own CPU"));
    for (int i = 0; counted && i < PassCounts::kCount; ++i)
        ImGui::TableSetupColumn(PassCounts::name(i), ImGuiTableColumnFlags_WidthFixed, numberColumnWidth("1234567890"));
    ImGui::TableHeadersRow();
    auto statsRow = [&](const std::string& name, unsigned color, bool pass) {
        const TimingStats g = timer.gpuStats(name, static_cast<size_t>(window));
        const TimingStats c = timer.cpuStats(name, static_cast<size_t>(window));
        const PassTimer::Series* s = timer.find(name);
        ImGui::PushID(name.c_str());
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        if (pass) {
            bool show = !hidden.count(name);
            if (ImGui::Checkbox("##show", &show)) {
                if (show) hidden.erase(name);
                else hidden.insert(name);
            }
            if (ImGui::IsItemHovered()) tooltip("show %s in the graph", name.c_str());
        }
        ImGui::TableNextColumn();
        ImGui::ColorButton("##c", ImGui::ColorConvertU32ToFloat4(color), ImGuiColorEditFlags_NoTooltip, ImVec2(10, 10));
        ImGui::SameLine();
        if (pass) {
            if (ImGui::Selectable(name.c_str(), solo == name)) solo = solo == name ? std::string() : name;
            if (ImGui::IsItemHovered()) {
                // What the pass did (PassRecord::stats: the shadow maps' casters D/N and triangles).
                const PassRecord* rec = report.find(name);
                const std::string what = solo == name ? "click: show every pass again" : "click: show only " + name;
                const bool line = rec && !rec->stats.empty();
                tooltip("%s%s%s", line ? rec->stats.c_str() : "", line ? "\n" : "", what.c_str());
            }
        } else {
            ImGui::TextUnformatted("whole frame");
        }
        ImGui::TableNextColumn();
        if (s && !s->samples.empty()) numberCell(s->samples.back().gpuMs);
        else ImGui::TextDisabled("...");
        for (float v : {g.median, g.mean, g.min, g.max}) {
            ImGui::TableNextColumn();
            numberCell(v);
        }
        if (cpu) {
            ImGui::TableNextColumn();
            numberCell(c.median);
        }
        // The last harvested frame's counters: exact, no statistics needed.
        for (int i = 0; counted && i < PassCounts::kCount; ++i) {
            ImGui::TableNextColumn();
            const std::int64_t v = s && !s->samples.empty() ? s->samples.back().counts[i] : -1;
            if (v >= 0) ImGui::Text("%lld", static_cast<long long>(v));
            else ImGui::TextDisabled("-");
        }
        ImGui::PopID();
    };
    for (const auto& p : passes) statsRow(p, passColor(p), true);
    statsRow(PassTimer::kFrameSeries, IM_COL32(255, 255, 255, 255), false);
    ImGui::EndTable();
}

void TimingsPanel::changeBar(UiState& state, RenderSession& session) {
    // Under the toolbar, so the action is on show at any panel size; the
    // verdict goes under the graph.
    ChangeMeasurement& m = state.measure;
    const bool shown = m.state() != ChangeMeasurement::State::Idle;
    if (!change && !shown) {
        wrappedColored(kDimColor, "cost of a change: change a knob, then measure it here");
        return;
    }
    const std::string what = shown ? m.change().what : change->what;
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("change: %s", what.c_str());
    ImGui::PopStyleColor();
    const ImGuiStyle& style = ImGui::GetStyle();
    if (m.active()) {
        // One measured frame a UI frame: the window stays responsive, and
        // the measurement can be cancelled at any frame.
        const float cancelW = ImGui::CalcTextSize("cancel").x + style.FramePadding.x * 2.0f;
        ImGui::ProgressBar(m.progress(), ImVec2(std::max(ImGui::GetContentRegionAvail().x - cancelW - style.ItemSpacing.x, 80.0f), 0.0f),
                           m.status().c_str());
        noteItem("timings.progress");
        sameLineIfFits(cancelW);
        if (ImGui::Button("cancel")) m.cancel(session.knobs());
        noteItem("timings.cancel");
        return;
    }
    if (!change) return;
    const bool measured = m.state() == ChangeMeasurement::State::Done && m.change().what == change->what;
    if (ImGui::Button(measured ? "measure again" : "measure")) startMeasure(state, session);
    noteItem("timings.measure");
    if (ImGui::IsItemHovered())
        tooltip("renders the frames before and after the change in turns (B B A A ...), one a UI frame,\n"
                          "the first frame of each turn left out, and compares each pass's GPU times");
    sameLineIfFits(90.0f + style.ItemInnerSpacing.x + ImGui::CalcTextSize("frames per side").x);
    ImGui::SetNextItemWidth(90.0f);
    ImGui::InputInt("frames per side", &measureSettings.framesPerSide, 2, 10);
    measureSettings.framesPerSide = std::clamp(measureSettings.framesPerSide, 2, 150);
    if (m.state() == ChangeMeasurement::State::Cancelled) ImGui::TextDisabled("%s", m.status().c_str());
    if (measured) ImGui::TextDisabled("measured: the verdict is under the graph");
}

void TimingsPanel::changeCost(UiState& state, RenderSession& session) {
    (void)session;
    ChangeMeasurement& m = state.measure;
    if (m.state() != ChangeMeasurement::State::Done || !change || m.change().what != change->what) return;
    const std::string header = "Cost of the change: " + m.change().what + "###cost";
    if (!ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
    const ImGuiStyle& style = ImGui::GetStyle();
    if (m.state() != ChangeMeasurement::State::Done) return;
    const ChangeVerdict& v = m.verdict();
    const PassVerdict* total = v.find(PassTimer::kFrameSeries);
    ImGui::TextWrapped("median GPU ms of %d frames a side, interleaved; %s", total ? std::max(total->beforeFrames, total->afterFrames) : 0,
                       v.method().c_str());
    noteItem("timings.method");
    std::vector<std::string> names;
    for (const auto& p : v.passes) names.push_back(p.pass);
    const float changeWidth = ImGui::CalcTextSize("+0000.0 ms (+000%, 99.7% CI +000% to +000%) (n.s.)").x;
    const float tableWidth = nameColumnWidth(names, 8.0f) + numberColumnWidth("before") + numberColumnWidth("after") +
                             changeWidth + 8.0f * style.CellPadding.x;
    if (ImGui::GetContentRegionAvail().x < tableWidth) {
        // Too narrow for the table's columns: the numbers were cut to a digit
        // until scrolled sideways. Each pass on its own lines instead, wrapped.
        changeCostLines(v);
        return;
    }
    // Every row shown (the panel scrolls).
    const float rowH = ImGui::GetTextLineHeight() + style.CellPadding.y * 2.0f;
    const float tableH = rowH * static_cast<float>(v.passes.size() + 1) + style.ScrollbarSize + 6.0f;
    if (!ImGui::BeginTable("cost", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX | ImGuiTableFlags_BordersInnerV,
                           ImVec2(0.0f, tableH)))
        return;
    ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthFixed, nameColumnWidth(names, 8.0f));
    ImGui::TableSetupColumn("before", ImGuiTableColumnFlags_WidthFixed, numberColumnWidth("before"));
    ImGui::TableSetupColumn("after", ImGuiTableColumnFlags_WidthFixed, numberColumnWidth("after"));
    ImGui::TableSetupColumn("change", ImGuiTableColumnFlags_WidthFixed, changeWidth);
    ImGui::TableHeadersRow();
    for (const PassVerdict& c : v.passes) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(c.pass == PassTimer::kFrameSeries ? "whole frame" : c.pass.c_str());
        ImGui::TableNextColumn();
        if (c.beforeFrames) numberCell(c.beforeMs);
        else ImGui::TextDisabled("-");
        ImGui::TableNextColumn();
        if (c.afterFrames) numberCell(c.afterMs);
        else ImGui::TextDisabled("-");
        ImGui::TableNextColumn();
        const std::string d = c.describe();
        if (c.significant) ImGui::TextColored(c.afterMs > c.beforeMs ? kErrorColor : kOkColor, "%s", d.c_str());
        else ImGui::TextDisabled("%s (%s)", d.c_str(), c.influenced ? "n.s." : "not reached");
        noteItem("timings.cost_change." + c.pass);
        if (ImGui::IsItemHovered())
            tooltip("%s: %s%s", c.pass.c_str(), d.c_str(),
                              c.significant ? ""
                              : c.influenced ? ", not significant at the adjusted level"
                                             : ",\nnot flagged: it reads no changed knob and nothing a pass reading one writes");
    }
    ImGui::EndTable();
    noteItem("timings.cost_table");
}

void TimingsPanel::changeCostLines(const ChangeVerdict& v) {
    ImGui::BeginGroup();
    for (const PassVerdict& c : v.passes) {
        const std::string name = c.pass == PassTimer::kFrameSeries ? "whole frame" : c.pass;
        auto ms = [](bool have, double value) {
            char t[32];
            std::snprintf(t, sizeof(t), "%.3f", value);
            return have ? std::string(t) : std::string("-");
        };
        ImGui::TextWrapped("%s: %s -> %s ms", name.c_str(), ms(c.beforeFrames > 0, c.beforeMs).c_str(),
                           ms(c.afterFrames > 0, c.afterMs).c_str());
        const std::string d = c.describe() + (c.significant ? "" : c.influenced ? " (n.s.)" : " (not reached)");
        ImGui::Indent(ImGui::GetFontSize());
        wrappedColored(c.significant ? (c.afterMs > c.beforeMs ? kErrorColor : kOkColor) : kDimColor, d);
        noteItem("timings.cost_change." + c.pass);
        ImGui::Unindent(ImGui::GetFontSize());
    }
    ImGui::EndGroup();
    noteItem("timings.cost_table");
}

std::string gpuFrameText(const PassTimer& timer, const UiState& state) {
    const PassTimer::Series* total = timer.find(PassTimer::kFrameSeries);
    char text[160];
    const auto latest = static_cast<unsigned long long>(state.report.frameIndex);
    if (state.framesRendered == 0 || state.report.passes.empty()) return "GPU -";
    const TimingSample* newest = total && !total->samples.empty() ? &total->samples.back() : nullptr;
    if (newest && newest->frame == state.report.frameIndex) {
        std::snprintf(text, sizeof(text), "GPU %.2f ms", newest->gpuMs);
    } else if (newest && newest->frame >= state.configSince && newest->frame < state.report.frameIndex) {
        std::snprintf(text, sizeof(text), "GPU %.2f ms (frame %llu; %llu pending)", newest->gpuMs,
                      static_cast<unsigned long long>(newest->frame), latest);
    } else {
        std::snprintf(text, sizeof(text), "GPU ... ms (frame %llu pending)", latest);
    }
    return text;
}

nlohmann::json timingsReport(const PassTimer& timer, const UiState& state) {
    const PassTimer::Series* total = timer.find(PassTimer::kFrameSeries);
    const ChangeMeasurement& m = state.measure;
    nlohmann::json passes = nlohmann::json::array();
    for (const PassVerdict& p : m.verdict().passes)
        passes.push_back({{"pass", p.pass},
                          {"before_ms", p.beforeMs},
                          {"after_ms", p.afterMs},
                          {"before_frames", p.beforeFrames},
                          {"after_frames", p.afterFrames},
                          {"influenced", p.influenced},
                          {"significant", p.significant},
                          {"confidence", p.confidence},
                          {"text", p.describe()}});
    nlohmann::json cost = {{"state", m.stateName()},
                           {"status", m.status()},
                           {"what", m.change().what},
                           {"frames_rendered", m.framesRendered()},
                           {"frames_scheduled", m.framesScheduled()},
                           {"compared", m.verdict().compared},
                           {"per_pass_confidence", m.verdict().perPassConfidence},
                           {"influenced", std::vector<std::string>(m.influenced().begin(), m.influenced().end())},
                           {"passes", passes}};
    nlohmann::json series = nlohmann::json::object();
    for (const auto& s : timer.series()) {
        if (s.samples.empty()) continue;
        series[s.name] = {{"frame", s.samples.back().frame}, {"gpu_ms", s.samples.back().gpuMs}};
        // The counters' columns, as the table shows them (the newest frame's).
        const PassCounts& c = s.samples.back().counts;
        for (int i = 0; c.measured() && i < PassCounts::kCount; ++i)
            if (c[i] >= 0) series[s.name]["counters"][PassCounts::name(i)] = c[i];
    }
    return {{"gpu_text", gpuFrameText(timer, state)},
            {"counting", timer.counting()},
            {"config_since", state.configSince},
            {"pending_frames", timer.pendingFrames()},
            {"timings_pending", state.timingsPending},
            {"oldest_timed_frame", total && !total->samples.empty() ? static_cast<long long>(total->samples.front().frame) : -1},
            {"newest", series},
            {"cost", cost}};
}

}  // namespace dw::ui
