#include "ui/WorkbenchUi.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "ui/ScenePanel.h"
#include "ui/Widgets.h"

namespace dw::ui {

void MessagesPanel::draw(const char* title, bool* open, UiState& state) {
    if (!beginPanel(title, open)) {
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
        if (ImGui::MenuItem("Open scene...", "Ctrl+O")) {
            p.scene = true;
            state.requestOpenScene = true;
        }
        if (ImGui::BeginMenu("Open recent", !state.recentScenes.empty())) {
            for (const std::string& r : std::vector<std::string>(state.recentScenes.begin(), state.recentScenes.end()))
                if (ImGui::MenuItem(r.c_str())) openScene(state, session, r);
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Presets...")) p.presets = true;
        if (ImGui::MenuItem("Save record...", "Ctrl+S")) record_.request(RecordDialog::Mode::Save);
        if (ImGui::MenuItem("Open record...", "Ctrl+R")) record_.request(RecordDialog::Mode::Open);
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
        ImGui::MenuItem("Pareto (tradeoff CSV)", nullptr, &p.pareto);
        ImGui::MenuItem("Parameters", nullptr, &p.knobs);
        ImGui::MenuItem("Presets", nullptr, &p.presets);
        ImGui::MenuItem("Messages", nullptr, &p.messages);
        ImGui::Separator();
        // The default layout and the default set of open panels (the Pareto
        // panel, closed by default, stayed open).
        if (ImGui::MenuItem("Reset layout")) {
            state.resetLayout = true;
            state.panels = PanelFlags{};
        }
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Render")) {
        ViewportView& v = state.viewport;
        if (ImGui::MenuItem("Deferred", "d", v.mode == DisplayMode::Deferred)) v.mode = DisplayMode::Deferred;
        if (ImGui::MenuItem("Textured (forward)", "t", v.mode == DisplayMode::Textured)) v.mode = DisplayMode::Textured;
        if (ImGui::MenuItem("Wireframe (forward)", "w", v.mode == DisplayMode::Wireframe)) v.mode = DisplayMode::Wireframe;
        ImGui::Separator();
        ImGui::MenuItem("Light volumes", "v", &v.overlay.lightVolumes);
        if (ImGui::MenuItem("Volumes at the probed pixel", nullptr, v.volumes == VolumeFilter::AtProbe)) v.volumes = VolumeFilter::AtProbe;
        if (ImGui::MenuItem("Every light's volume", nullptr, v.volumes == VolumeFilter::All)) v.volumes = VolumeFilter::All;
        if (ImGui::MenuItem("Only the selected light", nullptr, v.volumes == VolumeFilter::Selected)) v.volumes = VolumeFilter::Selected;
        ImGui::MenuItem("World axes", "a", &v.overlay.axes);
        ImGui::Separator();
        if (ImGui::MenuItem("Orbit camera", "f", v.camera == CameraMode::Orbit)) v.camera = CameraMode::Orbit;
        if (ImGui::MenuItem("Fly camera", "f", v.camera == CameraMode::Fly)) v.camera = CameraMode::Fly;
        ImGui::Separator();
        if (ImGui::MenuItem("Reload changed shaders", "F5")) state.requestReloadShaders = true;
        if (ImGui::IsItemHovered())
            tooltip("from %s (DW_SHADER_DIR=FOLDER picks another folder at start)", session.shaders().root().c_str());
        ImGui::MenuItem(("shader folder: " + session.shaders().root().string()).c_str(), nullptr, false, false);
        if (ImGui::MenuItem("Capture frame (RenderDoc)", "F11")) state.requestRenderDocCapture = true;
        ImGui::Separator();
        reference_.menuItems(state);
        if (ImGui::IsItemHovered())
            tooltip("%s", state.renderdocAvailable ? "the next frame to a RenderDoc capture in the export folder"
                                                             : state.renderdocWhy.c_str());
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
        ImGui::MenuItem("Keys", nullptr, &p.keys);
        ImGui::EndMenu();
    }
    reference_.progressBar();
    RecordDialog::progressBar(state, session);
    // Frame facts at the right of the bar: the GPU time of the latest
    // rendered frame (or which frame's it is while that one's is in flight).
    char info[256];
    std::snprintf(info, sizeof(info), "%s | %s | %s", session.scene().name.c_str(),
                  gpuFrameText(session.pipeline().timer(), state).c_str(), session.glInfo().renderer.c_str());
    ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(info).x - 16);
    ImGui::TextDisabled("%s", info);
    ImGui::EndMainMenuBar();
}

bool* WorkbenchUi::panelFlag(PanelFlags& p, const std::string& name) {
    const std::pair<const char*, bool*> flags[] = {
        {"Viewport", &p.viewport},    {"GPU timings", &p.timings}, {"Pixel probe", &p.probe},
        {"Scene", &p.scene},          {"Lights", &p.lights},       {"Pass inspector", &p.inspector},
        {"Parameters", &p.knobs},     {"Side view", &p.sideView},  {"Presets", &p.presets},
        {"Messages", &p.messages},    {"Keys", &p.keys},           {"Pareto", &p.pareto}};
    for (const auto& [n, f] : flags)
        if (name == n) return f;
    return nullptr;
}

void WorkbenchUi::splitters(const PanelLayout::Arrangement& a) {
    // The gaps between panels, in one window behind them that draws nothing
    // but the bar under the mouse: a drag moves room from one neighbour to the other.
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(d);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::Begin("##splitters", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                     ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
    for (const auto& s : a.splitters) {
        char id[48];
        std::snprintf(id, sizeof(id), "##split%d.%d.%d.%d", s.column, s.row, s.item, s.vertical ? 1 : 0);
        ImGui::SetCursorScreenPos(ImVec2(s.rect.x, s.rect.y));
        ImGui::InvisibleButton(id, ImVec2(std::max(s.rect.w, 1.0f), std::max(s.rect.h, 1.0f)));
        const bool hot = ImGui::IsItemHovered() || ImGui::IsItemActive();
        if (hot) {
            ImGui::SetMouseCursor(s.vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
            ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(s.rect.x, s.rect.y), ImVec2(s.rect.x + s.rect.w, s.rect.y + s.rect.h),
                                                      ImGui::GetColorU32(ImGuiCol_SeparatorHovered));
        }
        if (ImGui::IsItemActive()) {
            const float delta = s.vertical ? ImGui::GetIO().MouseDelta.x : ImGui::GetIO().MouseDelta.y;
            if (delta != 0.0f) layout_.drag(s, delta);
        }
    }
    ImGui::End();
}

void WorkbenchUi::toast(const UiState& state) {
    const Message* m = state.log.toast(state.time);
    if (!m) return;
    // Drawn over everything (not a window: it takes no room and no input).
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    const float wrap = std::min(d.x * 0.5f, 640.0f);
    const ImVec2 size = ImGui::CalcTextSize(m->text.c_str(), nullptr, false, wrap);
    const ImVec2 max(d.x - 12.0f, d.y - 12.0f), min(max.x - size.x - 16.0f, max.y - size.y - 12.0f);
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    dl->AddRectFilled(min, max, IM_COL32(40, 70, 45, 235), 4.0f);
    dl->AddText(nullptr, 0.0f, ImVec2(min.x + 8.0f, min.y + 6.0f), IM_COL32(230, 245, 230, 255), m->text.c_str(), nullptr, wrap);
}

void WorkbenchUi::draw(UiState& state, RenderSession& session, float dt) {
    handleShortcuts(state, session, dt);
    if (state.requestOpenScene) state.panels.scene = true;
    // A file dropped on the window opens as a scene (the last of several wins).
    for (const std::string& f : state.droppedFiles) openScene(state, session, f);
    state.droppedFiles.clear();
    reference_.update(state, session);
    menuBar(state, session);
    if (state.resetLayout) layout_.reset();
    state.resetLayout = false;
    PanelFlags& p = state.panels;
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    const PanelLayout::Arrangement a = layout_.arrange(d.x, d.y, ImGui::GetFrameHeight(), [&](const std::string& name) {
        const bool* f = panelFlag(p, name);
        return f && *f;
    });
    splitters(a);
    drawn_.clear();
    for (const auto& placed : a.panels) {
        const PanelRect& r = placed.rect;
        ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
        ImGui::SetNextWindowSize(ImVec2(r.w, r.h), ImGuiCond_Always);
        const std::string& n = placed.panel;
        bool* open = panelFlag(p, n);
        if (n == "Viewport") viewport_.draw("Viewport", open, state, session);
        else if (n == "GPU timings") timings_.draw("GPU timings", open, state, session);
        else if (n == "Pixel probe") probe_.draw("Pixel probe", open, state);
        else if (n == "Scene") scene_.draw("Scene", open, state, session);
        else if (n == "Lights") lights_.draw("Lights", open, state, session);
        else if (n == "Pass inspector") inspector_.draw("Pass inspector", open, state, session);
        else if (n == "Parameters") knobs_.draw("Parameters", open, session.knobs());
        else if (n == "Side view") side_.draw("Side view", open, state, session);
        else if (n == "Presets") presets_.draw("Presets", open, state, session);
        else if (n == "Messages") messages_.draw("Messages", open, state);
        else if (n == "Pareto") pareto_.draw("Pareto", open, state, session);
        else if (n == "Keys") {
            if (beginPanel("Keys", open)) {
                ImGui::PushTextWrapPos(0.0f);
                ImGui::TextUnformatted(shortcutHelp());
                ImGui::PopTextWrapPos();
            }
            ImGui::End();
        }
        drawn_.push_back({n, r});
    }
    record_.draw(state, session);
    toast(state);
}

}  // namespace dw::ui
