#include "ui/InspectorPanel.h"

#include <imgui.h>

#include <algorithm>

#include "renderer/inspect/FiniteCheck.h"
#include "renderer/inspect/OutputReadback.h"
#include "ui/Widgets.h"

namespace dw::ui {

bool viewSettingsEditor(BufferViewSettings& s, OutputKind kind, const std::pair<glm::vec4, glm::vec4>* autoRange,
                        const PublishedOutput* output) {
    bool changed = false;
    using M = BufferViewSettings::Mapping;
    using C = BufferViewSettings::Channel;
    // Which layer (cube) of a layered output and which sample of a multisample one; -1 at the left end.
    if (const int layers = output ? selectableLayers(*output) : 0; layers > 0) {
        s.layer = std::min(s.layer, layers - 1);
        ImGui::SetNextItemWidth(160);
        const char* what = resourceKind(*output) == ResourceKind::TextureCubeArray ? "cube" : "layer";
        changed |= ImGui::SliderInt(what, &s.layer, -1, layers - 1, s.layer < 0 ? "all" : "%d");
    }
    if (const int samples = output ? sampleCount(*output) : 1; samples > 1) {
        s.sample = std::min(s.sample, samples - 1);
        ImGui::SetNextItemWidth(160);
        changed |= ImGui::SliderInt("sample", &s.sample, -1, samples - 1, s.sample < 0 ? "resolved" : "%d");
    }
    const char* channels[] = {"RGB", "R", "G", "B", "A"};
    for (int c = 0; c < 5; ++c) {
        if (c) ImGui::SameLine();
        if (ImGui::RadioButton(channels[c], static_cast<int>(s.channel) == c)) {
            s.channel = static_cast<C>(c);
            changed = true;
        }
    }
    const char* mappings[] = {"auto",     "direct (range)", "linear depth",
                              "normal colours", "heat map", "tone map", "non-finite (NaN / Inf)"};
    int m = static_cast<int>(s.mapping) + 1;
    ImGui::SetNextItemWidth(160);
    if (ImGui::Combo("mapping", &m, mappings, 7)) {
        s.mapping = static_cast<M>(m - 1);
        changed = true;
    }
    const M resolved = BufferView::resolveMapping(kind, s);
    if (s.mapping == M::Auto) {
        ImGui::SameLine();
        ImGui::TextDisabled("-> %s", mappings[static_cast<int>(resolved) + 1]);
    }
    if (resolved == M::NonFinite && output && output->allocated()) {
        // Counted on the CPU from a read-back of what is shown (only while this view is on).
        const NonFiniteCount c = FiniteCheck::count(readOutputRaw(*output, s.selection()), output->decl.name);
        if (c.nonFinite() == 0) {
            ImGui::TextDisabled("no NaN or infinity in %lld values", c.values);
        } else {
            ImGui::TextColored(ImVec4(1.0f, 0.3f, 1.0f, 1.0f), "NaN %lld (magenta), +Inf %lld (red), -Inf %lld (blue)", c.nan,
                               c.positiveInf, c.negativeInf);
            ImGui::TextDisabled("first at pixel (%d, %d), rows top-down", c.firstX, c.firstY);
        }
    }
    if (resolved == M::Tonemap) {
        ImGui::SetNextItemWidth(160);
        changed |= ImGui::SliderFloat("exposure (EV)", &s.exposure, -10.0f, 10.0f, "%.1f");
    }
    if (resolved == M::Direct || resolved == M::LinearDepth || resolved == M::Heatmap) {
        bool automatic = BufferView::resolveAutoRange(kind, s);
        if (ImGui::Checkbox("auto min/max", &automatic)) {
            s.autoRange = automatic ? 1 : 0;
            changed = true;
        }
        if (automatic && autoRange) {
            ImGui::SameLine();
            const int c = std::max(0, static_cast<int>(s.channel) - 1);
            ImGui::TextDisabled("%.4g .. %.4g", autoRange->first[c], autoRange->second[c]);
        }
        if (!automatic) {
            ImGui::SetNextItemWidth(220);
            float range[2] = {s.rangeMin, s.rangeMax};
            if (ImGui::InputFloat2("range", range, "%.5g")) {
                s.rangeMin = range[0];
                s.rangeMax = range[1];
                changed = true;
            }
            if (autoRange && ImGui::SmallButton("from auto")) {
                s.rangeMin = autoRange->first[0];
                s.rangeMax = autoRange->second[0];
                changed = true;
            }
        }
    }
    return changed;
}

void InspectorPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    if (!ImGui::Begin(title, open)) {
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
                if (ImGui::Selectable(o.decl.name.c_str(), selected, ImGuiSelectableFlags_AllowItemOverlap)) {
                    state.viewport.output = o.decl.name;
                    state.viewport.mode = DisplayMode::Deferred;
                }
                if (ImGui::IsItemHovered() && !o.decl.description.empty()) ImGui::SetTooltip("%s", o.decl.description.c_str());
                ImGui::Unindent(8.0f);
                ImGui::TableNextColumn();
                if (ImGui::SmallButton("side")) {
                    state.side.output = o.decl.name;
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
        if (!isDisplayReady(*shown)) {
            std::pair<glm::vec4, glm::vec4> range;
            const bool haveRange = BufferView::resolveAutoRange(shown->decl.kind, state.viewport.settings) && state.viewportImage.texture;
            if (haveRange) range = session.bufferView().lastAutoRange();
            viewSettingsEditor(state.viewport.settings, shown->decl.kind, haveRange ? &range : nullptr, shown);
        }
        if (ImGui::SmallButton("show final image")) state.viewport.output = "final";
    }
    ImGui::End();
}

void SideViewPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    if (!ImGui::Begin(title, open)) {
        ImGui::End();
        return;
    }
    ImGui::SetNextItemWidth(200);
    if (ImGui::BeginCombo("output", state.side.output.c_str())) {
        for (const auto& o : session.pipeline().outputs().all())
            if (ImGui::Selectable(o.decl.name.c_str(), o.decl.name == state.side.output)) state.side.output = o.decl.name;
        ImGui::EndCombo();
    }
    if (const PublishedOutput* o = session.pipeline().outputs().find(state.side.output))
        viewSettingsEditor(state.side.settings, o->decl.kind, nullptr, o);
    const ShownImage& img = state.sideImage;
    if (img.texture) {
        const ImVec2 avail = ImGui::GetContentRegionAvail();
        const float scale = std::min(avail.x / img.width, std::max(avail.y, 64.0f) / img.height);
        image(img.texture, ImVec2(img.width * scale, img.height * scale));
    } else {
        wrappedColored(kErrorColor, img.unavailable.empty() ? "no image" : img.unavailable);
    }
    ImGui::End();
}

}  // namespace dw::ui
