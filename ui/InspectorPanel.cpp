#include "ui/InspectorPanel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "renderer/inspect/MemoryTable.h"
#include "renderer/inspect/OutputReadback.h"
#include "ui/ImageViewer.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace {

double mib(std::size_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

// A pass's row: its tree node, GPU ms, and what it did (under the name when narrow). True when open.
bool passRow(const PassRecord& rec, PassTimer& timer, bool narrow) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const bool openNode = ImGui::TreeNodeEx(rec.name.c_str(), ImGuiTreeNodeFlags_DefaultOpen | ImGuiTreeNodeFlags_SpanFullWidth,
                                            "%s %s", rec.ran ? "+" : "-", rec.name.c_str());
    if (ImGui::IsItemHovered()) tooltip("%s: %s", rec.name.c_str(), rec.ran ? "ran" : ("skipped: " + rec.reason).c_str());
    if (narrow) {
        ImGui::Indent(ImGui::GetFontSize());
        wrappedColored(kDimColor, rec.ran ? (rec.stats.empty() ? "ran" : rec.stats) : "skipped: " + rec.reason);
        ImGui::Unindent(ImGui::GetFontSize());
    }
    ImGui::TableNextColumn();
    if (rec.ran) ImGui::Text("%.3f", timer.gpuStats(rec.name, 60).median);
    else ImGui::TextDisabled("-");
    if (!narrow) {
        ImGui::TableNextColumn();
        if (rec.ran) ImGui::TextWrapped("%s", rec.stats.empty() ? "ran" : rec.stats.c_str());
        else wrappedColored(kDimColor, "skipped: " + rec.reason);
    }
    return openNode;
}

// "color  584x279", "(not this frame)" when it was not produced this frame; "" for an unallocated output.
std::string outputFacts(const PublishedOutput& o) {
    char t[160] = "";
    if (o.texture && resourceKind(o) == ResourceKind::Texture2D)
        std::snprintf(t, sizeof(t), "%s  %dx%d%s", toString(o.decl.kind), o.texture->width(o.level), o.texture->height(o.level),
                      o.producedThisFrame ? "" : "  (not this frame)");
    else if (o.allocated())
        std::snprintf(t, sizeof(t), "%s  %s%s", toString(o.decl.kind), describe(o.desc, o.desc.width, o.desc.height).c_str(),
                      o.producedThisFrame ? "" : "  (not this frame)");
    return t;
}

// An output's row: its name (a click shows it in the viewport), 'side', and its kind and size.
void outputRow(const PublishedOutput& o, UiState& state, bool narrow) {
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
    {
        // Where the label's text lies (the selectable spans the row): the tests check it ends before 'side'.
        const ImVec2 at(ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y);
        const ImVec2 text = ImGui::CalcTextSize(label.c_str());
        noteRect("inspector_label." + o.decl.name, at, ImVec2(at.x + text.x, at.y + text.y));
    }
    const std::string facts = outputFacts(o);
    if (ImGui::IsItemHovered())
        tooltip("%s%s%s%s%s", o.decl.name.c_str(), o.decl.description.empty() ? "" : ": ", o.decl.description.c_str(),
                facts.empty() ? "" : "\n", facts.c_str());
    ImGui::Unindent(8.0f);
    ImGui::TableNextColumn();
    if (ImGui::SmallButton("side")) {
        state.side.show(o.decl.name);
        state.panels.sideView = true;
    }
    noteItem("inspector_side." + o.decl.name);
    if (!narrow) {
        ImGui::TableNextColumn();
        if (!facts.empty()) ImGui::TextDisabled("%s", facts.c_str());
    }
    ImGui::PopID();
}

// Every byte the renderer holds (inspect/MemoryTable.h): the frame graph's
// resources (an output whose pass did not run, or that nothing asked for, has
// none) and what passes, services and the scene own, with their total.
void memorySection(RenderSession& session) {
    const MemoryTable t = MemoryTable::build(session.pipeline().resources());
    char head[160];
    std::snprintf(head, sizeof(head), "GPU memory: %.1f MiB (frame graph %.1f MiB, %zu rows), peak %.1f MiB###memory",
                  mib(t.total), mib(t.frameGraphBytes()), t.rows.size(), mib(t.ledgerPeak));
    if (!ImGui::CollapsingHeader(head)) return;
    if (ImGui::BeginTable("memory", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_Resizable)) {
        ImGui::TableSetupColumn("owner", ImGuiTableColumnFlags_WidthStretch, 0.6f);
        ImGui::TableSetupColumn("MiB", ImGuiTableColumnFlags_WidthFixed, 64.0f);
        ImGui::TableSetupColumn("objects", ImGuiTableColumnFlags_WidthFixed, 48.0f);
        ImGui::TableHeadersRow();
        for (const MemoryRow& r : t.rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r.owner.c_str());
            if (ImGui::IsItemHovered())
                tooltip("%s: %zu bytes%s%s", r.owner.c_str(), r.bytes, r.detail.empty() ? "" : ", ", r.detail.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", mib(r.bytes));
            ImGui::TableNextColumn();
            ImGui::Text("%d", r.objects);
        }
        ImGui::EndTable();
    }
    ImGui::Text("total %.2f MiB (%zu bytes); the GL wrapper counts %zu bytes", mib(t.total), t.total, t.ledgerLive);
    wrappedColored(kDimColor, "logical sizes (format x size x levels x layers x samples), not the driver's padded ones; "
                              "ImGui's own font texture and vertex buffers are not counted");
}

}  // namespace

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
    // Narrow (the right column at 1024x640): two columns, what a pass did
    // under its name and an output's kind in its tooltip, so the names keep
    // their room (they were cut: ".specul", ".emissi").
    const bool narrow = ImGui::GetContentRegionAvail().x < 360.0f;
    if (ImGui::BeginTable("passes", narrow ? 2 : 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_Resizable)) {
        ImGui::TableSetupColumn("pass / output", ImGuiTableColumnFlags_WidthStretch, 0.5f);
        ImGui::TableSetupColumn("GPU ms", ImGuiTableColumnFlags_WidthFixed, 56.0f);
        if (!narrow) ImGui::TableSetupColumn("what happened", ImGuiTableColumnFlags_WidthStretch, 0.5f);
        ImGui::TableHeadersRow();
        for (const auto& rec : state.report.passes) {
            const bool openNode = passRow(rec, timer, narrow);
            for (const auto& o : outputs.all()) {
                if (o.pass != rec.name) continue;
                listed.push_back(o.decl.name);
                if (openNode) outputRow(o, state, narrow);
            }
            if (openNode) ImGui::TreePop();
        }
        ImGui::EndTable();
    }
    memorySection(session);
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
