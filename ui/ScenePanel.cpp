#include "ui/ScenePanel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "renderer/Error.h"
#include "renderer/scene/BuiltinScenes.h"
#include "ui/PresetsPanel.h"
#include "ui/RecordDialog.h"
#include "renderer/scene/SceneFileKind.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace fs = std::filesystem;

const std::vector<std::string> kSceneExtensions = {".json", ".gltf", ".glb"};

namespace {

void rememberRecent(UiState& state, const std::string& spec) {
    std::error_code ec;
    if (!fs::is_regular_file(spec, ec)) return;  // a built-in scene's name
    const std::string path = fs::absolute(spec, ec).lexically_normal().string();
    auto& r = state.recentScenes;
    r.erase(std::remove(r.begin(), r.end(), path), r.end());
    r.push_front(path);
    while (r.size() > UiState::kRecentScenes) r.pop_back();
}

}  // namespace

namespace {

// Opening a record's or a preset's own scene goes through openScene again;
// there a record or a preset is an error, not another redirect (a record
// naming itself as its scene would never end).
int& redirectDepth() {
    static int depth = 0;
    return depth;
}

// A record or a preset handed over as a scene opens as what it is; false when it is a scene.
bool openAsWhatItIs(UiState& state, RenderSession& session, const std::string& spec, bool& opened) {
    const SceneFileKind kind = classifySceneFile(spec);
    if (kind == SceneFileKind::Scene) return false;
    const char* what = kind == SceneFileKind::Record ? "an experiment record" : "a preset";
    if (redirectDepth() > 0) {
        state.log.error("cannot open scene " + spec + ": it is " + what + ", not a scene", state.time, "open scene");
        opened = false;
        return true;
    }
    ++redirectDepth();
    if (kind == SceneFileKind::Record) {
        state.log.info(spec + " is an experiment record, not a scene: opened as a record (its scene, camera and knobs, "
                              "as File > Open record...; `deferred-workbench replay " + spec + "` measures it again)",
                       state.time);
        opened = openRecord(state, session, spec);
    } else {
        state.log.info(spec + " is a preset, not a scene: loaded as in the Presets panel (--preset on the command line)",
                       state.time);
        opened = loadPresetFile(state, session, spec);
    }
    --redirectDepth();
    if (opened) state.log.succeeded("open scene");
    return true;
}

}  // namespace

bool openScene(UiState& state, RenderSession& session, const std::string& spec) {
    if (bool opened = false; openAsWhatItIs(state, session, spec, opened)) return opened;
    try {
        if (state.animator.running()) state.animator.stop(session.mutableScene());
        session.loadScene(spec, state.run);
        state.timeline.reset();
        state.selectedLight = -1;
        state.probe.pinned = false;
        state.log.info("opened scene " + session.scene().name + " (" + spec + ")", state.time);
        state.log.succeeded("open scene");
        rememberRecent(state, spec);
        for (const auto& w : session.scene().warnings) state.log.info("warning: " + w, state.time);
        return true;
    } catch (const std::exception& e) {
        state.log.error("cannot open scene " + spec + ": " + e.what(), state.time, "open scene");
        return false;
    }
}

namespace {

// The built-in scenes' buttons and the examples', wrapped to the panel's
// width (a row of them was cut: "fir").
void sceneButtons(UiState& state, RenderSession& session) {
    const float padding = 2.0f * ImGui::GetStyle().FramePadding.x;
    bool first = true;
    for (const auto& b : builtinScenes()) {
        if (!first) sameLineIfFits(ImGui::CalcTextSize(b.name.c_str()).x + padding);
        first = false;
        if (ImGui::Button(b.name.c_str())) openScene(state, session, b.name);
        noteItem("scene.builtin." + b.name);
        if (ImGui::IsItemHovered()) tooltip("%s", b.description.c_str());
    }
    std::error_code ec;
    if (state.scenesDir.empty() || !fs::is_directory(state.scenesDir, ec)) return;
    std::vector<fs::path> examples;
    for (const auto& e : fs::directory_iterator(state.scenesDir, ec))
        if (e.path().extension() == ".json") examples.push_back(e.path());
    std::sort(examples.begin(), examples.end());
    first = true;
    for (const fs::path& e : examples) {
        const std::string name = e.filename().string();
        if (!first) sameLineIfFits(ImGui::CalcTextSize(name.c_str()).x + padding);
        first = false;
        if (ImGui::SmallButton(name.c_str())) openScene(state, session, e.string());
        noteItem("scene.example." + name);
        if (ImGui::IsItemHovered()) tooltip("%s", e.string().c_str());
    }
}

}  // namespace

void ScenePanel::openSection(UiState& state, RenderSession& session, bool focusPath) {
    // The path field and its buttons first: the wrapped scene buttons below
    // them would push them out of a short panel (1024x640).
    // The field has the panel's whole width (paths are long), the buttons the next line.
    ImGui::SetNextItemWidth(-1.0f);
    if (focusPath) ImGui::SetKeyboardFocusHere();
    // Focused by Ctrl+O, the old path is selected, so typing replaces it.
    const bool enter = inputTextEnter("##path", ".json / .gltf / .glb path (Ctrl+O)", path, sizeof(path),
                                      ImGuiInputTextFlags_AutoSelectAll);
    noteItem("scene.path");
    if (ImGui::IsItemHovered())
        tooltip("a scene file's path (relative to %s); Enter opens it. Files dropped on the window open too.",
                fs::current_path().c_str());
    const bool openClicked = ImGui::Button("open##path");  // not "open": the header above has that ID
    noteItem("scene.open");
    if (openClicked || enter) {
        if (path[0]) openScene(state, session, path);
        else state.log.error("cannot open scene: type a file's path first (or use browse)", state.time, "open scene");
    }
    ImGui::SameLine();
    if (ImGui::Button("browse")) browser.open(path);
    if (auto picked = browser.draw("Open scene file", kSceneExtensions)) {
        std::snprintf(path, sizeof(path), "%s", picked->c_str());
        openScene(state, session, *picked);
    }
    if (!state.recentScenes.empty() && ImGui::TreeNodeEx("recent", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (const std::string& r : std::vector<std::string>(state.recentScenes.begin(), state.recentScenes.end())) {
            if (ImGui::Selectable(fs::path(r).filename().c_str())) {
                std::snprintf(path, sizeof(path), "%s", r.c_str());
                openScene(state, session, r);
            }
            if (ImGui::IsItemHovered()) tooltip("%s", r.c_str());
        }
        ImGui::TreePop();
    }
    sceneButtons(state, session);
}

void ScenePanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    Scene& scene = session.mutableScene();
    ImGui::Text("%s", scene.name.c_str());
    ImGui::TextDisabled("%s", scene.source.c_str());
    char facts[160];
    std::snprintf(facts, sizeof(facts), "%zu triangles, %zu draws, %zu lights, %zu materials, %zu textures",
                  scene.triangleCount(), scene.instances.size(), scene.lights.size(), scene.materials.size(), scene.images.size());
    wrappedColored(kDimColor, facts);
    const bool focusPath = state.requestOpenScene;
    if (focusPath) {
        ImGui::SetWindowFocus();
        ImGui::SetNextItemOpen(true, ImGuiCond_Always);
        state.requestOpenScene = false;
    }
    if (ImGui::CollapsingHeader("open", ImGuiTreeNodeFlags_DefaultOpen)) openSection(state, session, focusPath);
    if (ImGui::CollapsingHeader("global terms", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::ColorEdit3("ambient", &scene.ambient.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
        ImGui::ColorEdit3("background", &scene.background.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    }
    if (ImGui::CollapsingHeader("camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        Camera& c = session.camera();
        int mode = state.viewport.camera == CameraMode::Orbit ? 0 : 1;
        if (ImGui::RadioButton("orbit", &mode, 0)) state.viewport.camera = CameraMode::Orbit;
        ImGui::SameLine();
        if (ImGui::RadioButton("fly (hold right button)", &mode, 1)) state.viewport.camera = CameraMode::Fly;
        ImGui::DragFloat3("eye", &c.position.x, 0.05f);
        ImGui::DragFloat3("look-at", &c.target.x, 0.05f);
        ImGui::SliderFloat("fov (deg)", &c.fovYDegrees, 10.0f, 120.0f, "%.1f");
        ImGui::DragFloatRange2("near / far", &c.nearPlane, &c.farPlane, 0.05f, 0.001f, 1e5f, "%.3f", "%.1f",
                               ImGuiSliderFlags_Logarithmic);
        c.nearPlane = std::max(c.nearPlane, 1e-4f);
        c.farPlane = std::max(c.farPlane, c.nearPlane * 1.01f);
        if (ImGui::Button("reset to the scene's camera")) c = scene.camera;
        ImGui::SameLine();
        if (ImGui::Button("frame everything")) c = Camera::framing(scene.bounds());
    }
    state.timeline.draw(session);
    ImGui::End();
}

}  // namespace dw::ui
