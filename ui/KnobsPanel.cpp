#include "ui/KnobsPanel.h"

#include <imgui.h>

#include <algorithm>
#include <string>
#include <vector>

#include "ui/Widgets.h"

namespace dw::ui {

bool knobWidget(KnobRegistry& knobs, int id) {
    const KnobSpec& s = knobs.spec(id);
    ImGui::PushID(id);
    bool changed = false;
    // Called inside a 3-column table: name | widget | reset.
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::AlignTextToFramePadding();
    const std::string shortName = s.name.substr(s.name.find('.') + 1);
    // The whole name, on more lines where the column is narrow (it was cut:
    // "material_", "directional_in_gb"); the tooltip names the knob in full.
    const ImVec4 color = knobs.isDefault(id) ? ImGui::GetStyleColorVec4(ImGuiCol_Text) : ImVec4(1.0f, 0.85f, 0.45f, 1.0f);
    ImGui::BeginGroup();
    for (const std::string& line : breakName(shortName, ImGui::GetContentRegionAvail().x))
        ImGui::TextColored(color, "%s", line.c_str());
    ImGui::EndGroup();
    noteItem("knob_name." + s.name);
    const bool labelHovered = ImGui::IsItemHovered();
    ImGui::TableNextColumn();
    ImGui::SetNextItemWidth(-1.0f);
    const char* label = "##value";
    switch (s.type) {
        case KnobType::Bool: {
            bool v = knobs.value(id) != 0.0;
            if (ImGui::Checkbox(label, &v)) {
                knobs.set(id, v ? 1.0 : 0.0);
                changed = true;
            }
            break;
        }
        case KnobType::Int: {
            int v = static_cast<int>(knobs.value(id));
            if (ImGui::SliderInt(label, &v, static_cast<int>(s.minValue), static_cast<int>(s.maxValue))) {
                knobs.set(id, v);
                changed = true;
            }
            break;
        }
        case KnobType::Float: {
            float v = static_cast<float>(knobs.value(id));
            const ImGuiSliderFlags flags = s.logarithmic ? ImGuiSliderFlags_Logarithmic : 0;
            if (ImGui::SliderFloat(label, &v, static_cast<float>(s.minValue), static_cast<float>(s.maxValue),
                                   s.logarithmic ? "%.5g" : "%.4g", flags)) {
                knobs.set(id, v);
                changed = true;
            }
            break;
        }
        case KnobType::Enum: {
            int v = static_cast<int>(knobs.value(id));
            if (ImGui::BeginCombo(label, s.choices[static_cast<size_t>(v)].c_str())) {
                for (size_t c = 0; c < s.choices.size(); ++c)
                    if (ImGui::Selectable(s.choices[c].c_str(), static_cast<int>(c) == v)) {
                        knobs.set(id, static_cast<double>(c));
                        changed = true;
                    }
                ImGui::EndCombo();
            }
            break;
        }
    }
    noteItem("knob." + s.name);
    if (labelHovered || ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
        ImGui::Text("%s", s.name.c_str());
        ImGui::TextUnformatted(s.description.c_str());
        ImGui::TextDisabled("range %s%s%s, default %s", knobs.formatRange(id).c_str(), s.unit.empty() ? "" : " ",
                            s.unit.c_str(), knobs.formatValue(id, s.defaultValue).c_str());
        if (s.tradeoff) ImGui::TextDisabled("trades speed for quality");
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
    ImGui::TableNextColumn();
    ImGui::BeginDisabled(knobs.isDefault(id));
    if (ImGui::SmallButton("reset")) {
        knobs.reset(id);
        changed = true;
    }
    ImGui::EndDisabled();
    ImGui::PopID();
    return changed;
}

void KnobsPanel::draw(const char* title, bool* open, KnobRegistry& knobs) {
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    ImGui::SetNextItemWidth(-80.0f);
    ImGui::InputTextWithHint("##filter", "filter knobs", filter, sizeof(filter));
    ImGui::SameLine();
    if (ImGui::Button("reset all")) knobs.resetAll();
    const std::string f = filter;
    // Groups in declaration order (the pipeline's pass order).
    std::vector<std::string> passes;
    for (const auto& s : knobs.specs())
        if (std::find(passes.begin(), passes.end(), s.pass) == passes.end()) passes.push_back(s.pass);
    for (const auto& pass : passes) {
        std::vector<int> ids;
        for (size_t i = 0; i < knobs.size(); ++i) {
            const KnobSpec& s = knobs.spec(static_cast<int>(i));
            if (s.pass == pass && (f.empty() || s.name.find(f) != std::string::npos)) ids.push_back(static_cast<int>(i));
        }
        if (ids.empty()) continue;
        int changedCount = 0;
        for (int id : ids) changedCount += knobs.isDefault(id) ? 0 : 1;
        const std::string header = pass + (changedCount ? " (" + std::to_string(changedCount) + " changed)" : "") + "###" + pass;
        if (!ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) continue;
        ImGui::PushID(pass.c_str());
        if (ImGui::BeginTable("knobs", 3, ImGuiTableFlags_SizingStretchProp)) {
            ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch, 0.48f);
            ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch, 0.52f);
            ImGui::TableSetupColumn("reset", ImGuiTableColumnFlags_WidthFixed, 42.0f);
            for (int id : ids) knobWidget(knobs, id);
            ImGui::EndTable();
        }
        if (changedCount && ImGui::SmallButton("reset group"))
            for (int id : ids) knobs.reset(id);
        ImGui::PopID();
    }
    ImGui::End();
}

}  // namespace dw::ui
