#include "ui/LightsPanel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "renderer/lighting/LightVolume.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace {

Light newLight(LightType type, const Scene& scene, const Camera& cam, size_t index) {
    Light l;
    l.type = type;
    l.name = std::string(toString(type)) + " " + std::to_string(index);
    const glm::vec3 forward = glm::normalize(cam.target - cam.position);
    l.position = cam.target + glm::vec3(0.0f, std::max(scene.bounds().radius() * 0.1f, 0.5f), 0.0f);
    l.direction = type == LightType::Directional ? glm::normalize(forward + glm::vec3(0, -1, 0)) : glm::vec3(0, -1, 0);
    l.intensity = glm::vec3(1.0f, 0.95f, 0.85f);
    l.attenuation = {1.0f, 0.3f, 0.5f};
    l.cutoffDegrees = 30.0f;
    l.exponent = 4.0f;
    return l;
}

// The animation's switch, radius and speed.
void animationControls(UiState& state, Scene& scene) {
    bool animate = state.animator.running();
    if (ImGui::Checkbox("animate", &animate)) {
        if (animate) state.animator.start(scene);
        else state.animator.stop(scene);
    }
    sameLineIfFits(130.0f);
    ImGui::SetNextItemWidth(60);
    ImGui::DragFloat("radius", &state.animator.radius, 0.01f, 0.0f, 100.0f, "%.2f");
    sameLineIfFits(120.0f);
    ImGui::SetNextItemWidth(60);
    ImGui::DragFloat("speed", &state.animator.speed, 0.01f, 0.0f, 20.0f, "%.2f");
}

// *add* point, spot, directional (a light in front of the camera); all on,
// all off. Returns the index of the light added (-1: none).
int addButtons(Scene& scene, const Camera& camera) {
    int added = -1;
    auto add = [&](LightType type) {
        scene.lights.push_back(newLight(type, scene, camera, scene.lights.size()));
        added = static_cast<int>(scene.lights.size()) - 1;
    };
    ImGui::TextDisabled("add");
    ImGui::SameLine();
    if (ImGui::Button("point")) add(LightType::Point);
    sameLineIfFits(ImGui::CalcTextSize("spot").x + 16.0f);
    if (ImGui::Button("spot")) add(LightType::Spot);
    sameLineIfFits(ImGui::CalcTextSize("directional").x + 16.0f);
    if (ImGui::Button("directional")) add(LightType::Directional);
    sameLineIfFits(ImGui::CalcTextSize("all on").x + 16.0f);
    if (ImGui::Button("all on"))
        for (auto& l : scene.lights) l.enabled = true;
    sameLineIfFits(ImGui::CalcTextSize("all off").x + 16.0f);
    if (ImGui::Button("all off"))
        for (auto& l : scene.lights) l.enabled = false;
    return added;
}

// The lights' table: switch, colour and name (a click selects), type,
// volume radius at `threshold`; scrolled to the selected light when asked.
void lightTable(UiState& state, Scene& scene, double threshold, bool& scrollToSelected) {
    // The list fills the panel until a light is selected, then shares it with the editor.
    const float avail = ImGui::GetContentRegionAvail().y;
    const float listHeight =
        state.selectedLight >= 0 ? std::max(avail * 0.4f, 80.0f)
                                 : std::max(avail - ImGui::GetTextLineHeightWithSpacing() - 4.0f, 5.0f * ImGui::GetFrameHeightWithSpacing());
    // Columns as wide as their contents, the name taking what is left; a
    // panel too narrow for the longest name (up to 160 px) scrolls the table
    // sideways, the switch and name frozen at the left, rather than
    // squeezing the names away.
    float nameWidth = ImGui::CalcTextSize("name").x;
    for (const Light& l : scene.lights) nameWidth = std::max(nameWidth, ImGui::CalcTextSize(l.name.c_str()).x);
    nameWidth = std::min(nameWidth, 160.0f) + 18.0f;  // and the colour swatch
    const float onWidth = ImGui::GetFrameHeight(), typeWidth = ImGui::CalcTextSize("directional").x + 4.0f,
                radiusWidth = ImGui::CalcTextSize("999.99").x + 4.0f;
    const float cells = 4.0f * 2.0f * ImGui::GetStyle().CellPadding.x;
    // At least 9 characters of name before the table scrolls.
    const float nameMin = std::min(nameWidth, ImGui::CalcTextSize("lantern00").x + 18.0f);
    const float innerWidth = std::max(ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ScrollbarSize,
                                      onWidth + nameMin + typeWidth + radiusWidth + cells);
    if (ImGui::BeginTable("lights", 4,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_ScrollX | ImGuiTableFlags_SizingFixedFit,
                          ImVec2(0, listHeight), innerWidth)) {
        ImGui::TableSetupScrollFreeze(2, 1);
        ImGui::TableSetupColumn("on", ImGuiTableColumnFlags_WidthFixed, onWidth);
        ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("type", ImGuiTableColumnFlags_WidthFixed, typeWidth);
        ImGui::TableSetupColumn("radius", ImGuiTableColumnFlags_WidthFixed, radiusWidth);
        ImGui::TableHeadersRow();
        for (size_t i = 0; i < scene.lights.size(); ++i) {
            Light& l = scene.lights[i];
            ImGui::PushID(static_cast<int>(i));
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Checkbox("##on", &l.enabled);
            ImGui::TableNextColumn();
            if (i == 0) {
                // The room the names have (--layout-out: the GUI tests check it at small sizes).
                const ImVec2 at = ImGui::GetCursorScreenPos();
                noteRect("lights.name_cell", at, ImVec2(at.x + ImGui::GetContentRegionAvail().x, at.y + ImGui::GetTextLineHeight()));
            }
            const glm::vec4 c = ViewportOverlay::lightColor(l.intensity, false);
            ImGui::ColorButton("##c", ImVec4(c.r, c.g, c.b, 1.0f), ImGuiColorEditFlags_NoTooltip, ImVec2(10, 10));
            ImGui::SameLine();
            if (ImGui::Selectable(l.name.c_str(), state.selectedLight == static_cast<int>(i), ImGuiSelectableFlags_SpanAllColumns))
                state.selectedLight = state.selectedLight == static_cast<int>(i) ? -1 : static_cast<int>(i);
            if (ImGui::IsItemHovered()) tooltip("%s (%s): click to edit", l.name.c_str(), toString(l.type));
            if (scrollToSelected && state.selectedLight == static_cast<int>(i)) {
                ImGui::SetScrollHereY(0.5f);
                scrollToSelected = false;
            }
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(toString(l.type));
            ImGui::TableNextColumn();
            const LightVolume v = computeLightVolume(l, threshold);
            if (v.shape == VolumeShape::Culled) ImGui::TextDisabled(l.enabled ? "none" : "off");
            else if (!std::isfinite(v.radius)) ImGui::TextDisabled("all");
            else numberCell(v.radius, v.radius >= 1000.0f ? 0 : 2);
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
}

// The selected light's editor.
void lightEditor(UiState& state, Scene& scene, double threshold) {
    Light& l = scene.lights[static_cast<size_t>(state.selectedLight)];
    ImGui::Separator();
    char name[128];
    std::snprintf(name, sizeof(name), "%s", l.name.c_str());
    if (ImGui::InputText("name", name, sizeof(name))) l.name = name;
    int type = static_cast<int>(l.type);
    if (ImGui::Combo("type", &type, "directional\0point\0spot\0")) l.type = static_cast<LightType>(type);
    ImGui::Checkbox("enabled", &l.enabled);
    ImGui::SameLine();
    ImGui::Checkbox("casts shadows", &l.castShadows);
    if (l.type != LightType::Directional) {
        ImGui::BeginDisabled(state.animator.running());
        ImGui::DragFloat3("position", &l.position.x, 0.05f);
        ImGui::EndDisabled();
        if (state.animator.running()) helpMarker("Stop the animation to move lights by hand.");
    }
    if (l.type != LightType::Point) {
        if (ImGui::DragFloat3("direction", &l.direction.x, 0.01f, -1.0f, 1.0f)) {
            if (glm::length(l.direction) < 1e-4f) l.direction = glm::vec3(0, -1, 0);
            l.direction = glm::normalize(l.direction);
        }
    }
    // Colour and strength separately: an HDR intensity is colour x scalar.
    float strength = std::max({l.intensity.r, l.intensity.g, l.intensity.b});
    glm::vec3 color = strength > 0.0f ? l.intensity / strength : glm::vec3(1.0f);
    bool changed = ImGui::ColorEdit3("colour", &color.x, ImGuiColorEditFlags_Float);
    changed |= ImGui::DragFloat("intensity", &strength, 0.02f, 0.0f, 1e4f, "%.3f", ImGuiSliderFlags_Logarithmic);
    if (changed) l.intensity = color * strength;
    if (l.type != LightType::Directional) {
        ImGui::TextDisabled("attenuation 1 / (c + l d + q d^2)");
        ImGui::DragFloat("constant", &l.attenuation.constant, 0.01f, 0.0f, 100.0f, "%.4f");
        ImGui::DragFloat("linear", &l.attenuation.linear, 0.005f, 0.0f, 100.0f, "%.4f");
        ImGui::DragFloat("quadratic", &l.attenuation.quadratic, 0.005f, 0.0f, 100.0f, "%.4f");
        if (l.attenuation.constant + l.attenuation.linear + l.attenuation.quadratic <= 0.0f) l.attenuation.constant = 1.0f;
    }
    if (l.type == LightType::Spot) {
        // The seeds' cutoff and exponent, or KHR_lights_punctual's cone
        // (what a glTF spot light comes with); the cutoff is the outer cone.
        int falloff = l.falloff == SpotFalloff::InnerOuterCone ? 1 : 0;
        if (ImGui::Combo("falloff", &falloff, "cutoff + exponent\0inner + outer cone (glTF)\0"))
            l.falloff = falloff == 1 ? SpotFalloff::InnerOuterCone : SpotFalloff::CutoffExponent;
        if (l.falloff == SpotFalloff::InnerOuterCone) {
            ImGui::SliderFloat("outer cone (deg)", &l.cutoffDegrees, 1.0f, 90.0f, "%.1f");
            ImGui::SliderFloat("inner cone (deg)", &l.innerConeDegrees, 0.0f, l.cutoffDegrees, "%.1f");
            l.innerConeDegrees = std::clamp(l.innerConeDegrees, 0.0f, l.cutoffDegrees);
        } else {
            ImGui::SliderFloat("cutoff (deg)", &l.cutoffDegrees, 1.0f, 90.0f, "%.1f");
            ImGui::SliderFloat("exponent", &l.exponent, 0.0f, 128.0f, "%.2f");
        }
    }
    const LightVolume v = computeLightVolume(l, threshold);
    const char* shape = v.shape == VolumeShape::Cone ? "cone" : v.shape == VolumeShape::Sphere ? "sphere"
                        : v.shape == VolumeShape::FullScreen ? "full-screen" : "none (below threshold)";
    ImGui::TextDisabled("volume: %s, radius %.3f at threshold %.5g", shape, v.radius, threshold);
    if (ImGui::Button("remove light")) {
        scene.lights.erase(scene.lights.begin() + state.selectedLight);
        state.selectedLight = -1;
    }
}

}  // namespace

void LightsPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    Scene& scene = session.mutableScene();
    KnobRegistry& knobs = session.knobs();
    const double threshold = knobs.value(*knobs.find("lighting.threshold"));
    if (state.selectedLight >= static_cast<int>(scene.lights.size())) state.selectedLight = -1;
    animationControls(state, scene);
    // A new light is selected (its editor opens) and scrolled to.
    const int added = addButtons(scene, session.camera());
    if (added >= 0) {
        state.selectedLight = added;
        scrollToSelected = true;
    }

    lightTable(state, scene, threshold, scrollToSelected);
    state.viewport.overlay.selectedLight = state.selectedLight;

    if (state.selectedLight < 0) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        clippedText(std::to_string(scene.lights.size()) + " lights; select one to edit it", ImGui::GetContentRegionAvail().x);
        ImGui::PopStyleColor();
    }
    if (state.selectedLight >= 0) lightEditor(state, scene, threshold);
    ImGui::End();
}

}  // namespace dw::ui
