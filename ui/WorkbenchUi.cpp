#include "ui/WorkbenchUi.h"

#include <imgui.h>

#include "ui/Widgets.h"

namespace dw::ui {

void MessagesPanel::draw(const char* title, bool* open, UiState& state) {
    if (!ImGui::Begin(title, open)) {
        ImGui::End();
        return;
    }
    if (ImGui::SmallButton("dismiss banner")) state.log.dismissBanner();
    ImGui::Separator();
    ImGui::BeginChild("##log");
    for (const auto& m : state.log.all()) {
        ImGui::TextDisabled("%7.1fs", m.time);
        ImGui::SameLine();
        if (m.error) wrappedColored(kErrorColor, m.text);
        else ImGui::TextWrapped("%s", m.text.c_str());
    }
    if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
    ImGui::EndChild();
    ImGui::End();
}

void WorkbenchUi::menuBar(UiState& state, RenderSession& session) {
    if (!ImGui::BeginMainMenuBar()) return;
    PanelFlags& p = state.panels;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open scene...")) p.scene = true;
        if (ImGui::MenuItem("Presets...")) p.presets = true;
        if (ImGui::MenuItem("Screenshot", "F12")) state.requestScreenshot = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) state.requestQuit = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        ImGui::MenuItem("Viewport", nullptr, &p.viewport);
        ImGui::MenuItem("Pass inspector", nullptr, &p.inspector);
        ImGui::MenuItem("Side view", nullptr, &p.sideView);
        ImGui::MenuItem("Pixel probe", nullptr, &p.probe);
        ImGui::MenuItem("Scene", nullptr, &p.scene);
        ImGui::MenuItem("Lights", nullptr, &p.lights);
        ImGui::MenuItem("GPU timings", nullptr, &p.timings);
        ImGui::MenuItem("Parameters", nullptr, &p.knobs);
        ImGui::MenuItem("Presets", nullptr, &p.presets);
        ImGui::MenuItem("Messages", nullptr, &p.messages);
        ImGui::Separator();
        if (ImGui::MenuItem("Reset layout")) state.resetLayout = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Render")) {
        ViewportView& v = state.viewport;
        if (ImGui::MenuItem("Deferred", "d", v.mode == DisplayMode::Deferred)) v.mode = DisplayMode::Deferred;
        if (ImGui::MenuItem("Textured (forward)", "t", v.mode == DisplayMode::Textured)) v.mode = DisplayMode::Textured;
        if (ImGui::MenuItem("Wireframe (forward)", "w", v.mode == DisplayMode::Wireframe)) v.mode = DisplayMode::Wireframe;
        ImGui::Separator();
        ImGui::MenuItem("Light volumes", "v", &v.overlay.lightVolumes);
        ImGui::MenuItem("Only the selected light", nullptr, &v.overlay.onlySelected);
        ImGui::MenuItem("World axes", "a", &v.overlay.axes);
        ImGui::Separator();
        if (ImGui::MenuItem("Orbit camera", "f", v.camera == CameraMode::Orbit)) v.camera = CameraMode::Orbit;
        if (ImGui::MenuItem("Fly camera", "f", v.camera == CameraMode::Fly)) v.camera = CameraMode::Fly;
        ImGui::Separator();
        if (ImGui::MenuItem("Reload changed shaders", "F5")) state.requestReloadShaders = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
        ImGui::MenuItem("Keys", nullptr, &p.keys);
        ImGui::EndMenu();
    }
    // Frame facts at the right of the bar.
    const PassTimer::Series* total = session.pipeline().timer().find(PassTimer::kFrameSeries);
    char info[160];
    std::snprintf(info, sizeof(info), "%s | GPU %.2f ms | %s", session.scene().name.c_str(),
                  total && !total->samples.empty() ? session.pipeline().timer().gpuStats(PassTimer::kFrameSeries, 60).median : 0.0f,
                  session.glInfo().renderer.c_str());
    ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(info).x - 16);
    ImGui::TextDisabled("%s", info);
    ImGui::EndMainMenuBar();
}

void WorkbenchUi::layout(UiState& state) {
    // The default arrangement, computed from the window size: scene and
    // lights on the left, the viewport in the middle with timings and the
    // probe under it, inspector and parameters on the right.
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    const float top = ImGui::GetFrameHeight();
    const float left = std::max(d.x * 0.18f, 240.0f), right = std::max(d.x * 0.24f, 300.0f);
    const float midW = d.x - left - right;
    const float viewH = (d.y - top) * 0.64f, bottomH = d.y - top - viewH;
    const ImGuiCond cond = state.resetLayout ? ImGuiCond_Always : ImGuiCond_FirstUseEver;
    layoutFor_ = {{"Viewport", {left, top, midW, viewH}},
                  {"GPU timings", {left, top + viewH, midW * 0.62f, bottomH}},
                  {"Pixel probe", {left + midW * 0.62f, top + viewH, midW * 0.38f, bottomH}},
                  {"Scene", {0, top, left, (d.y - top) * 0.42f}},
                  {"Lights", {0, top + (d.y - top) * 0.42f, left, (d.y - top) * 0.58f}},
                  {"Pass inspector", {d.x - right, top, right, (d.y - top) * 0.5f}},
                  {"Parameters", {d.x - right, top + (d.y - top) * 0.5f, right, (d.y - top) * 0.5f}},
                  {"Side view", {left + midW * 0.55f, top + 30, midW * 0.45f, viewH * 0.7f}},
                  {"Presets", {left + 40, top + 40, 340, 420}},
                  {"Messages", {left + 60, top + viewH - 220, midW * 0.8f, 200}},
                  {"Keys", {left + 80, top + 80, 640, 220}}};
    layoutCond_ = cond;
}

void WorkbenchUi::draw(UiState& state, RenderSession& session, float dt) {
    handleShortcuts(state, session, dt);
    menuBar(state, session);
    layout(state);
    PanelFlags& p = state.panels;
    auto next = [&](const char* name) {
        for (const auto& [n, r] : layoutFor_)
            if (n == name) {
                ImGui::SetNextWindowPos(ImVec2(r.x, r.y), layoutCond_);
                ImGui::SetNextWindowSize(ImVec2(r.z, r.w), layoutCond_);
            }
    };
    if (p.viewport) { next("Viewport"); viewport_.draw("Viewport", &p.viewport, state, session); }
    if (p.timings) { next("GPU timings"); timings_.draw("GPU timings", &p.timings, state, session); }
    if (p.probe) { next("Pixel probe"); probe_.draw("Pixel probe", &p.probe, state); }
    if (p.scene) { next("Scene"); scene_.draw("Scene", &p.scene, state, session); }
    if (p.lights) { next("Lights"); lights_.draw("Lights", &p.lights, state, session); }
    if (p.inspector) { next("Pass inspector"); inspector_.draw("Pass inspector", &p.inspector, state, session); }
    if (p.knobs) { next("Parameters"); knobs_.draw("Parameters", &p.knobs, session.knobs()); }
    if (p.sideView) { next("Side view"); side_.draw("Side view", &p.sideView, state, session); }
    if (p.presets) { next("Presets"); presets_.draw("Presets", &p.presets, state, session); }
    if (p.messages) { next("Messages"); messages_.draw("Messages", &p.messages, state); }
    if (p.keys) {
        next("Keys");
        if (ImGui::Begin("Keys", &p.keys)) ImGui::TextUnformatted(shortcutHelp());
        ImGui::End();
    }
    state.resetLayout = false;
}

}  // namespace dw::ui
