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
        for (int e = lo; e <= hi; e += every) {
            const float v = std::pow(10.0f, static_cast<float>(e));
            if (v >= bottom * 0.999f && v <= top * 1.001f) ticks.push_back(v);
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
    const KnobRegistry& knobs = session.knobs();
    auto snapshot = [&] {
        knobValues.clear();
        for (size_t i = 0; i < knobs.size(); ++i) knobValues.push_back(knobs.value(static_cast<int>(i)));
        knobGeneration = knobs.generation();
    };
    // Another scene or render size: another configuration, so the statistics
    // start over. A new size is in force from the frame this UI frame
    // rendered (the render comes before the panels), which stays: in an idle
    // window it may be the only one.
    if (session.scene().source != sceneSource || state.renderSize != renderSize) {
        if (!sceneSource.empty()) {
            if (session.scene().source != sceneSource) timer.clearHistory();
            else timer.clearHistoryBefore(state.report.frameIndex);
        }
        firstUsableFrame = state.report.frameIndex + 3;
        sceneSource = session.scene().source;
        renderSize = state.renderSize;
        cost.clear();
        costsAtFrame = ~0ull;
        snapshot();
        return;
    }
    if (knobs.generation() == knobGeneration) return;
    std::string what;
    int changed = 0;
    for (size_t i = 0; i < knobs.size() && i < knobValues.size(); ++i) {
        const double now = knobs.value(static_cast<int>(i));
        if (now == knobValues[i]) continue;
        if (changed++ == 0)
            what = knobs.spec(static_cast<int>(i)).name + " " + knobs.formatValue(static_cast<int>(i), knobValues[i]) + " -> " +
                   knobs.format(static_cast<int>(i));
    }
    if (changed > 1) what += " and " + std::to_string(changed - 1) + " more";
    if (changed > 0 && state.report.frameIndex > 0) {
        cost.mark(timer, state.report.frameIndex - 1, what, static_cast<size_t>(window), 3, firstUsableFrame);
        costsAtFrame = ~0ull;
    }
    snapshot();
}

void TimingsPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    watchForChanges(state, session);
    PassTimer& timer = session.pipeline().timer();
    ImGui::Checkbox("record", &state.timingCapture);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("render every frame and time it (the resolution scale holds still);\n"
                          "off: a frame is rendered only when something it shows changed");
    ImGui::SameLine();
    bool paused = timer.paused();
    if (ImGui::Checkbox("pause", &paused)) timer.setPaused(paused);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110);
    ImGui::SliderInt("frames", &window, 30, static_cast<int>(PassTimer::kHistory));
    ImGui::SameLine();
    ImGui::Checkbox("stacked", &stacked);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("areas stacked up to the frame total; off: one line per pass");
    ImGui::SameLine();
    ImGui::Checkbox("log", &logScale);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("logarithmic y axis (passes drawn as lines)");
    ImGui::SameLine();
    bool isolate = timer.isolateCpu();
    if (ImGui::Checkbox("own CPU", &isolate)) {
        timer.setIsolateCpu(isolate);
        timer.clearHistory();
        cost.clear();
        costsAtFrame = ~0ull;
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Adds a CPU column: the time a pass spends issuing its own work.\n"
                          "Before each pass the frame waits (on a GL fence) for the GPU to finish\n"
                          "the passes before it, so no pass is charged for waiting on another.\n"
                          "Frames get slower while this is on; the history starts over.");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - 90.0f, 60.0f));
    ImGui::InputText("##csv", csvPath, sizeof(csvPath));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("CSV file; a bare name goes to %s", state.exportDir.c_str());
    ImGui::SameLine();
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

    std::vector<std::string> passes;
    for (const auto& rec : state.report.passes)
        if (timer.find(rec.name)) passes.push_back(rec.name);
    graph(state, timer, passes);
    if (cost.active()) changeCost(timer);
    table(timer, passes);
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

void TimingsPanel::graph(UiState& state, PassTimer& timer, const std::vector<std::string>& passes) {
    // Align every pass's samples on the frames of the total.
    const PassTimer::Series* total = timer.find(PassTimer::kFrameSeries);
    const size_t n = total ? std::min(total->samples.size(), static_cast<size_t>(window)) : 0;
    std::unordered_map<std::uint64_t, size_t> column;
    std::vector<float> totals(n, 0.0f);
    std::vector<std::uint64_t> frames(n, 0);
    for (size_t i = 0; i < n; ++i) {
        const TimingSample& t = total->samples[total->samples.size() - n + i];
        column[t.frame] = i;
        totals[i] = t.gpuMs;
        frames[i] = t.frame;
    }
    std::vector<std::string> shown;
    for (const auto& p : passes)
        if (solo.empty() ? !hidden.count(p) : p == solo) shown.push_back(p);
    std::vector<std::vector<float>> values(shown.size(), std::vector<float>(n, 0.0f));
    for (size_t p = 0; p < shown.size(); ++p)
        for (const auto& t : timer.find(shown[p])->samples) {
            auto it = column.find(t.frame);
            if (it != column.end()) values[p][it->second] = t.gpuMs;
        }
    const bool stack = stacked && !logScale && solo.empty();
    const bool drawTotal = solo.empty();

    char caption[160];
    std::snprintf(caption, sizeof(caption), "%s, GPU ms per pass%s, %zu frame%s%s", timer.paused() ? "paused" : "live",
                  drawTotal ? " (white: whole frame)" : "", n, n == 1 ? "" : "s",
                  solo.empty() ? "" : (" - only " + solo).c_str());
    ImGui::TextDisabled("%s", caption);

    const float axisW = 52.0f, labelH = ImGui::GetTextLineHeight();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const ImVec2 size(std::max(avail.x - axisW, 40.0f), std::max(avail.y * 0.42f, 80.0f));
    const ImVec2 p0(at.x + axisW, at.y + labelH * 0.5f), p1(p0.x + size.x, p0.y + size.y);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(p0, p1, IM_COL32(22, 22, 26, 255));

    // The y range: up to the 95th percentile (one slow frame, a resize or a
    // shader compile, does not flatten the rest; taller values are clipped).
    std::vector<float> heights, positives;
    for (size_t i = 0; i < n; ++i) {
        float sum = 0.0f, hi = 0.0f;
        for (const auto& v : values) {
            sum += v[i];
            hi = std::max(hi, v[i]);
            if (v[i] > 0.0f) positives.push_back(v[i]);
        }
        heights.push_back(stack ? std::max(sum, drawTotal ? totals[i] : 0.0f) : std::max(hi, drawTotal ? totals[i] : 0.0f));
        if (drawTotal && totals[i] > 0.0f) positives.push_back(totals[i]);
    }
    std::sort(heights.begin(), heights.end());
    float top = n ? heights[std::min(n - 1, n * 95 / 100)] * 1.15f : 1.0f;
    top = std::max(top, 1e-3f);
    float bottom = 0.0f;
    if (logScale) {
        std::sort(positives.begin(), positives.end());
        bottom = positives.empty() ? top * 1e-3f : std::max(positives.front() * 0.7f, top * 1e-5f);
        if (bottom >= top) bottom = top * 0.1f;
    }
    auto Y = [&](float ms) {
        float t;
        if (logScale) t = (std::log10(std::max(ms, bottom)) - std::log10(bottom)) / (std::log10(top) - std::log10(bottom));
        else t = ms / top;
        return p1.y - size.y * std::clamp(t, 0.0f, 1.0f);
    };
    // One frame (an idle window rendered once) is drawn across the plot,
    // as two columns of the same values.
    const bool single = n == 1;
    if (single) {
        totals.push_back(totals[0]);
        for (auto& v : values) v.push_back(v[0]);
    }
    const size_t columns = single ? 2 : n;
    auto X = [&](size_t i) {
        return columns > 1 ? p0.x + size.x * static_cast<float>(i) / static_cast<float>(columns - 1) : p0.x;
    };

    // Axis: ticks, grid lines and labels left of the plot.
    for (float t : axisTicks(bottom, top, logScale)) {
        const float y = Y(t);
        dl->AddLine(ImVec2(p0.x, y), ImVec2(p1.x, y), IM_COL32(70, 70, 78, 255));
        char label[32];
        std::snprintf(label, sizeof(label), t >= 100.0f || t == 0.0f ? "%.0f ms" : t >= 1.0f ? "%.3g ms" : "%.2g ms", t);
        const float w = ImGui::CalcTextSize(label).x;
        dl->AddText(ImVec2(p0.x - w - 4.0f, y - labelH * 0.5f), IM_COL32(170, 170, 175, 255), label);
    }
    if (columns >= 2) {
        std::vector<float> base(columns, 0.0f);
        dl->PushClipRect(p0, p1, true);
        for (size_t p = 0; p < shown.size(); ++p) {
            const unsigned col = passColor(shown[p]);
            for (size_t i = 0; i + 1 < columns; ++i) {
                const float lo0 = stack ? base[i] : 0.0f, lo1 = stack ? base[i + 1] : 0.0f;
                const float hi0 = lo0 + values[p][i], hi1 = lo1 + values[p][i + 1];
                if (stack)
                    dl->AddQuadFilled(ImVec2(X(i), Y(lo0)), ImVec2(X(i), Y(hi0)), ImVec2(X(i + 1), Y(hi1)), ImVec2(X(i + 1), Y(lo1)), col);
                else
                    dl->AddLine(ImVec2(X(i), Y(hi0)), ImVec2(X(i + 1), Y(hi1)), col, 1.5f);
            }
            if (stack)
                for (size_t i = 0; i < columns; ++i) base[i] += values[p][i];
        }
        if (drawTotal)
            for (size_t i = 0; i + 1 < columns; ++i)
                dl->AddLine(ImVec2(X(i), Y(totals[i])), ImVec2(X(i + 1), Y(totals[i + 1])), IM_COL32(255, 255, 255, 200), 1.0f);
        dl->PopClipRect();
    } else {
        dl->AddText(ImVec2(p0.x + 6, p0.y + 4), IM_COL32(160, 160, 160, 255), "waiting for timer results");
    }
    ImGui::SetCursorScreenPos(at);
    ImGui::InvisibleButton("##plot", ImVec2(axisW + size.x, size.y + labelH));
    // Hover readout: the frame under the mouse, every shown pass and the total.
    if (ImGui::IsItemHovered() && n >= 1) {
        const float mx = ImGui::GetIO().MousePos.x;
        if (mx >= p0.x && mx <= p1.x) {
            // With one frame both columns are that frame.
            const size_t i = single ? 0
                                    : std::min(n - 1, static_cast<size_t>(std::lround((mx - p0.x) / size.x *
                                                                                      static_cast<float>(n - 1))));
            dl->AddLine(ImVec2(X(i), p0.y), ImVec2(X(i), p1.y), IM_COL32(255, 255, 255, 110));
            ImGui::BeginTooltip();
            ImGui::Text("frame %llu", static_cast<unsigned long long>(frames[i]));
            for (size_t p = shown.size(); p-- > 0;) {
                ImGui::ColorButton(("##t" + shown[p]).c_str(), ImGui::ColorConvertU32ToFloat4(passColor(shown[p])),
                                   ImGuiColorEditFlags_NoTooltip, ImVec2(9, 9));
                ImGui::SameLine();
                ImGui::Text("%-16s %9.3f ms", shown[p].c_str(), values[p][i]);
            }
            if (drawTotal) ImGui::Text("%-16s %9.3f ms", "whole frame", totals[i]);
            ImGui::EndTooltip();
        }
    }
    ImGui::TextDisabled("older  <-  frames  ->  newest");
    (void)state;
}

void TimingsPanel::table(PassTimer& timer, const std::vector<std::string>& passes) {
    const bool cpu = timer.isolateCpu();
    const int columns = cpu ? 8 : 7;
    // The rest of the panel but the app CPU plot under it.
    const float height = std::max(ImGui::GetContentRegionAvail().y - 46.0f, 3.0f * ImGui::GetFrameHeight());
    if (!ImGui::BeginTable("stats", columns, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_ScrollY,
                           ImVec2(0.0f, height)))
        return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("show", ImGuiTableColumnFlags_WidthFixed, 34.0f);
    for (const char* h : {"pass", "last", "median", "mean", "min", "max"}) ImGui::TableSetupColumn(h);
    if (cpu) ImGui::TableSetupColumn("own CPU");
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
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("show %s in the graph", name.c_str());
        }
        ImGui::TableNextColumn();
        ImGui::ColorButton("##c", ImGui::ColorConvertU32ToFloat4(color), ImGuiColorEditFlags_NoTooltip, ImVec2(10, 10));
        ImGui::SameLine();
        if (pass) {
            if (ImGui::Selectable(name.c_str(), solo == name)) solo = solo == name ? std::string() : name;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip(solo == name ? "click: show every pass again" : "click: show only %s", name.c_str());
        } else {
            ImGui::TextUnformatted(name.c_str());
        }
        ImGui::TableNextColumn();
        ImGui::Text("%.3f", s && !s->samples.empty() ? s->samples.back().gpuMs : 0.0f);
        for (float v : {g.median, g.mean, g.min, g.max}) {
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", v);
        }
        if (cpu) {
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", c.median);
        }
        ImGui::PopID();
    };
    for (const auto& p : passes) statsRow(p, passColor(p), true);
    statsRow(PassTimer::kFrameSeries, IM_COL32(255, 255, 255, 255), false);
    ImGui::EndTable();
}

void TimingsPanel::changeCost(PassTimer& timer) {
    const int after = cost.afterFrames(timer);
    char header[256];
    std::snprintf(header, sizeof(header), "Cost of the change: %s###cost", cost.what().c_str());
    if (!ImGui::CollapsingHeader(header, ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (after == 0) {
        ImGui::TextDisabled("waiting for frames after the change (the first 3 are left out)");
        return;
    }
    const PassTimer::Series* total = timer.find(PassTimer::kFrameSeries);
    const std::uint64_t newest = total && !total->samples.empty() ? total->samples.back().frame : 0;
    if (newest != costsAtFrame) {
        costs = cost.costs(timer);  // a bootstrap per pass: only when new frames came in
        costsAtFrame = newest;
    }
    int before = 0;
    for (const auto& c : costs) before = std::max(before, c.beforeFrames);
    ImGui::TextWrapped("median GPU ms, %d frames before against %d after; 95%% bootstrap interval of the ratio%s", before, after,
                       before < 10 ? ". Few frames before: turn on record before changing a knob for a steadier baseline" : "");
    if (!ImGui::BeginTable("cost", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) return;
    for (const char* h : {"pass", "before", "after", "change"}) ImGui::TableSetupColumn(h);
    ImGui::TableHeadersRow();
    for (const PassChangeCost& c : costs) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(c.pass.c_str());
        ImGui::TableNextColumn();
        if (c.beforeFrames) ImGui::Text("%.3f", c.beforeMs);
        else ImGui::TextDisabled("-");
        ImGui::TableNextColumn();
        if (c.afterFrames) ImGui::Text("%.3f", c.afterMs);
        else ImGui::TextDisabled("-");
        ImGui::TableNextColumn();
        const std::string d = c.describe();
        if (c.significant()) ImGui::TextColored(c.afterMs > c.beforeMs ? kErrorColor : kOkColor, "%s", d.c_str());
        else ImGui::TextDisabled("%s (n.s.)", d.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s: %s%s", c.pass.c_str(), d.c_str(), c.significant() ? "" : ", not significant");
    }
    ImGui::EndTable();
}

}  // namespace dw::ui
