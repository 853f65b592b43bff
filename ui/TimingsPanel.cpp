#include "ui/TimingsPanel.h"

#include <imgui.h>

#include <algorithm>
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

void TimingsPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    PassTimer& timer = session.pipeline().timer();
    bool paused = timer.paused();
    if (ImGui::Checkbox("pause", &paused)) timer.setPaused(paused);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120);
    ImGui::SliderInt("window", &window, 30, static_cast<int>(PassTimer::kHistory));
    ImGui::SameLine();
    ImGui::Checkbox("stacked", &stacked);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(140);
    ImGui::InputText("##csv", csvPath, sizeof(csvPath));
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

    // Align every pass's samples on the frames of the total.
    const PassTimer::Series* total = timer.find(PassTimer::kFrameSeries);
    std::vector<std::string> passes;
    for (const auto& rec : state.report.passes)
        if (timer.find(rec.name)) passes.push_back(rec.name);
    const size_t n = total ? std::min(total->samples.size(), static_cast<size_t>(window)) : 0;
    std::unordered_map<std::uint64_t, size_t> column;
    std::vector<float> totals(n, 0.0f);
    for (size_t i = 0; i < n; ++i) {
        const TimingSample& t = total->samples[total->samples.size() - n + i];
        column[t.frame] = i;
        totals[i] = t.gpuMs;
    }
    std::vector<std::vector<float>> values(passes.size(), std::vector<float>(n, 0.0f));
    for (size_t p = 0; p < passes.size(); ++p)
        for (const auto& t : timer.find(passes[p])->samples) {
            auto it = column.find(t.frame);
            if (it != column.end()) values[p][it->second] = t.gpuMs;
        }

    const ImVec2 size(ImGui::GetContentRegionAvail().x, std::max(ImGui::GetContentRegionAvail().y * 0.5f, 90.0f));
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(at, ImVec2(at.x + size.x, at.y + size.y), IM_COL32(22, 22, 26, 255));
    // Scale to the 95th percentile so one slow frame (shader warm-up, a
    // resize) does not flatten the rest; taller frames are clipped.
    std::vector<float> heights(n, 0.0f);
    for (size_t i = 0; i < n; ++i) {
        float sum = 0.0f;
        for (const auto& v : values) sum += v[i];
        heights[i] = stacked ? std::max(sum, totals[i]) : totals[i];
    }
    std::sort(heights.begin(), heights.end());
    float top = n ? heights[std::min(n - 1, n * 95 / 100)] : 0.0f;
    top = std::max(top * 1.25f, 0.01f);
    if (n >= 2) {
        auto X = [&](size_t i) { return at.x + size.x * static_cast<float>(i) / static_cast<float>(n - 1); };
        auto Y = [&](float ms) { return at.y + size.y - size.y * std::min(ms / top, 1.0f); };
        std::vector<float> base(n, 0.0f);
        for (size_t p = 0; p < passes.size(); ++p) {
            const unsigned col = passColor(passes[p]);
            for (size_t i = 0; i + 1 < n; ++i) {
                const float lo0 = stacked ? base[i] : 0.0f, lo1 = stacked ? base[i + 1] : 0.0f;
                const float hi0 = lo0 + values[p][i], hi1 = lo1 + values[p][i + 1];
                if (stacked)
                    dl->AddQuadFilled(ImVec2(X(i), Y(lo0)), ImVec2(X(i), Y(hi0)), ImVec2(X(i + 1), Y(hi1)),
                                      ImVec2(X(i + 1), Y(lo1)), col);
                else
                    dl->AddLine(ImVec2(X(i), Y(hi0)), ImVec2(X(i + 1), Y(hi1)), col, 1.5f);
            }
            if (stacked)
                for (size_t i = 0; i < n; ++i) base[i] += values[p][i];
        }
        for (size_t i = 0; i + 1 < n; ++i)
            dl->AddLine(ImVec2(X(i), Y(totals[i])), ImVec2(X(i + 1), Y(totals[i + 1])), IM_COL32(255, 255, 255, 200), 1.0f);
    }
    char label[64];
    std::snprintf(label, sizeof(label), "%.2f ms", top);
    dl->AddText(ImVec2(at.x + 4, at.y + 2), IM_COL32(200, 200, 200, 255), label);
    dl->AddText(ImVec2(at.x + 4, at.y + size.y - 16), IM_COL32(160, 160, 160, 255),
                paused ? "paused" : (n ? "GPU ms per pass (white: whole frame)" : "waiting for timer results"));
    ImGui::Dummy(size);

    if (ImGui::BeginTable("stats", 7, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
        for (const char* h : {"pass", "last", "median", "mean", "min", "max", "CPU median"}) ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        auto statsRow = [&](const std::string& name, unsigned color) {
            const TimingStats g = timer.gpuStats(name, static_cast<size_t>(window));
            const TimingStats c = timer.cpuStats(name, static_cast<size_t>(window));
            const PassTimer::Series* s = timer.find(name);
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::ColorButton(("##" + name).c_str(), ImGui::ColorConvertU32ToFloat4(color), ImGuiColorEditFlags_NoTooltip, ImVec2(10, 10));
            ImGui::SameLine();
            ImGui::TextUnformatted(name.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", s && !s->samples.empty() ? s->samples.back().gpuMs : 0.0f);
            for (float v : {g.median, g.mean, g.min, g.max, c.median}) {
                ImGui::TableNextColumn();
                ImGui::Text("%.3f", v);
            }
        };
        for (const auto& p : passes) statsRow(p, passColor(p));
        statsRow(PassTimer::kFrameSeries, IM_COL32(255, 255, 255, 255));
        ImGui::EndTable();
    }
    // CPU frame time of the whole app loop (UI included), beside the GPU numbers.
    if (!state.cpuFrameMs.empty()) {
        std::vector<float> cpu(state.cpuFrameMs.begin(), state.cpuFrameMs.end());
        const TimingStats c = computeStats(cpu);
        char overlay[96];
        std::snprintf(overlay, sizeof(overlay), "CPU frame: median %.2f ms, max %.2f ms", c.median, c.max);
        ImGui::PlotLines("##cpu", cpu.data(), static_cast<int>(cpu.size()), 0, overlay, 0.0f, c.max * 1.2f,
                         ImVec2(ImGui::GetContentRegionAvail().x, 40));
    }
    ImGui::End();
}

}  // namespace dw::ui
