#include "ui/InspectorPanel.h"

#include <imgui.h>

#include <algorithm>

#include "renderer/inspect/OutputReadback.h"
#include "ui/ImageViewer.h"
#include "ui/Widgets.h"

namespace dw::ui {

void InspectorPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    const OutputRegistry& outputs = session.pipeline().outputs();
    PassTimer& timer = session.pipeline().timer();
    listed.clear();
    char head[160];
    std::snprintf(head, sizeof(head), "frame %llu, %dx%d. Click an output to view it in the viewport; 'side' shows it beside.",
                  static_cast<unsigned long long>(state.report.frameIndex), state.renderSize.x, state.renderSize.y);
    wrappedColored(kDimColor, head);
    if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_Resizable)) {
        ImGui::TableSetupColumn("pass / output", ImGuiTableColumnFlags_WidthStretch, 0.5f);
        ImGui::TableSetupColumn("GPU ms", ImGuiTableColumnFlags_WidthFixed, 56.0f);
        ImGui::TableSetupColumn("what happened", ImGuiTableColumnFlags_WidthStretch, 0.5f);
        ImGui::TableHeadersRow();
        for (const auto& rec : state.report.passes) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            const bool openNode = ImGui::TreeNodeEx(rec.name.c_str(), ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_SpanFullWidth,
                                                    "%s %s", rec.ran ? "+" : "-", rec.name.c_str());
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s: %s", rec.name.c_str(), rec.ran ? "ran" : ("skipped: " + rec.reason).c_str());
            ImGui::TableNextColumn();
            if (rec.ran) ImGui::Text("%.3f", timer.gpuStats(rec.name, 60).median);
            else ImGui::TextDisabled("-");
            ImGui::TableNextColumn();
            if (rec.ran) ImGui::TextWrapped("%s", rec.stats.empty() ? "ran" : rec.stats.c_str());
            else wrappedColored(kDimColor, "skipped: " + rec.reason);
            for (const auto& o : outputs.all()) {
                if (o.pass != rec.name) continue;
                listed.push_back(o.decl.name);
                if (!openNode) continue;
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::PushID(o.decl.name.c_str());
                const bool selected = state.viewport.output == o.decl.name && state.viewport.mode == DisplayMode::Deferred;
                ImGui::Indent(8.0f);
                // In a narrow column the part that tells outputs apart (".albedo",
                // not "gbuffer" eight times); the whole name is the tooltip.
                std::string label = o.decl.name;
                if (const size_t dot = label.find('.');
                    dot != std::string::npos && ImGui::CalcTextSize(label.c_str()).x > ImGui::GetContentRegionAvail().x)
                    label = label.substr(dot);
                if (ImGui::Selectable((label + "###" + o.decl.name).c_str(), selected, ImGuiSelectableFlags_AllowItemOverlap)) {
                    state.viewport.show(o.decl.name);
                    state.viewport.mode = DisplayMode::Deferred;
                }
                noteItem("inspector." + o.decl.name);
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("%s%s%s", o.decl.name.c_str(), o.decl.description.empty() ? "" : ": ", o.decl.description.c_str());
                ImGui::Unindent(8.0f);
                ImGui::TableNextColumn();
                if (ImGui::SmallButton("side")) {
                    state.side.show(o.decl.name);
                    state.panels.sideView = true;
                }
                ImGui::TableNextColumn();
                if (o.texture && resourceKind(o) == ResourceKind::Texture2D)
                    ImGui::TextDisabled("%s  %dx%d%s", toString(o.decl.kind), o.texture->width(o.level), o.texture->height(o.level),
                                        o.producedThisFrame ? "" : "  (not this frame)");
                else if (o.allocated())
                    ImGui::TextDisabled("%s  %s%s", toString(o.decl.kind), describe(o.desc, o.desc.width, o.desc.height).c_str(),
                                        o.producedThisFrame ? "" : "  (not this frame)");
                ImGui::PopID();
            }
            if (openNode) ImGui::TreePop();
        }
        ImGui::EndTable();
    }
    // What the frame graph allocated for this frame: an output whose pass did
    // not run, or that nothing asked for, has no memory.
    const auto resources = session.pipeline().resources();
    std::size_t bytes = 0;
    for (const auto& r : resources) bytes += r.bytes;
    char resHead[96];
    std::snprintf(resHead, sizeof(resHead), "allocated resources: %zu, %.1f MiB###resources", resources.size(),
                  static_cast<double>(bytes) / (1024.0 * 1024.0));
    if (ImGui::CollapsingHeader(resHead)) {
        for (const auto& r : resources)
            ImGui::TextDisabled("%-22s %8.1f KiB  %s", r.name.c_str(), static_cast<double>(r.bytes) / 1024.0,
                                describe(r.desc, r.desc.width, r.desc.height).c_str());
        wrappedColored(kDimColor, "pass-owned outputs (the light table, shadow arrays, bloom levels) are not counted here");
    }
    ImGui::Separator();
    const PublishedOutput* shown = outputs.find(state.viewport.output);
    if (shown && state.viewport.mode == DisplayMode::Deferred) {
        ImGui::Text("viewport: %s", shown->decl.name.c_str());
        ImGui::TextDisabled("%s", shown->decl.description.c_str());
        wrappedColored(kDimColor, "its display controls (channel, mapping, range, zoom, histogram) are above the image");
        if (ImGui::SmallButton("show final image")) state.viewport.show("final");
    }
    ImGui::End();
}

void SideViewPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    ImGui::SetNextItemWidth(200);
    if (ImGui::BeginCombo("output", state.side.output.c_str())) {
        for (const auto& o : session.pipeline().outputs().all())
            if (ImGui::Selectable(o.decl.name.c_str(), o.decl.name == state.side.output)) state.side.show(o.decl.name);
        ImGui::EndCombo();
    }
    const PublishedOutput* o = session.pipeline().outputs().find(state.side.output);
    imageViewControls(state.side, o, state.sideImage);
    imageViewLegend(state.side, o, state.sideImage);
    const ImVec2 avail(std::max(ImGui::GetContentRegionAvail().x, 16.0f), std::max(ImGui::GetContentRegionAvail().y, 16.0f));
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##side", avail);
    drawImageView(state.side, state.sideImage, origin, avail, state.nearestSampler, ImGui::IsItemHovered(), ImGui::IsItemActive());
    ImGui::End();
}

}  // namespace dw::ui
