#include "ui/PresetsPanel.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>

#include "ui/ScenePanel.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace fs = std::filesystem;

void rememberPreset(UiState& state, const RenderSession& session, const std::string& name) {
    state.activePreset = name;
    state.activePresetKnobs.clear();
    for (size_t i = 0; i < session.knobs().size(); ++i) state.activePresetKnobs.push_back(session.knobs().value(static_cast<int>(i)));
}

bool applyPreset(UiState& state, RenderSession& session, const Preset& preset) {
    // Another scene opens as any scene does (start-up knobs first); this
    // preset, chosen by hand, then goes over them.
    if (!preset.scene.empty() && !RunConfig::namesScene(preset.scene, session.scene())) {
        if (!openScene(state, session, preset.scene)) return false;
    }
    if (preset.camera) session.camera() = *preset.camera;
    const Preset::ApplyReport r = preset.applyOver(session.knobs(), session.scene().settings);
    state.log.info("preset '" + preset.name + "': " + std::to_string(r.applied) + " knobs set", state.time);
    if (!r.ignored.empty()) {
        std::string all = "preset '" + preset.name + "' ignored " + std::to_string(r.ignored.size()) + " key(s):";
        for (const auto& i : r.ignored) all += "\n  " + i;
        state.log.error(all, state.time, "load preset");
    } else {
        state.log.succeeded("load preset");
    }
    rememberPreset(state, session, preset.name);
    return true;
}

bool savePreset(UiState& state, RenderSession& session, const std::string& path, const std::string& name) {
    std::error_code ec;
    const std::string shown = fs::absolute(path, ec).string();
    try {
        Preset::capture(name, session.knobs(), session.camera(), session.scene().source).save(path);
        state.log.done("saved preset " + shown, state.time, "save preset");
        rememberPreset(state, session, name);
        return true;
    } catch (const std::exception& e) {
        state.log.error(std::string("cannot save preset: ") + e.what(), state.time, "save preset");
        return false;
    }
}

bool presetModified(const UiState& state, const RenderSession& session) {
    const KnobRegistry& k = session.knobs();
    if (state.activePresetKnobs.size() != k.size()) return false;
    for (size_t i = 0; i < k.size(); ++i)
        if (k.value(static_cast<int>(i)) != state.activePresetKnobs[i]) return true;
    return false;
}

bool loadPresetFile(UiState& state, RenderSession& session, const std::string& path) {
    try {
        return applyPreset(state, session, Preset::load(path));
    } catch (const std::exception& e) {
        state.log.error(std::string("cannot load preset: ") + e.what(), state.time, "load preset");
        return false;
    }
}

void PresetsPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    if (!beginPanel(title, open)) {
        ImGui::End();
        return;
    }
    if (state.activePreset.empty()) {
        ImGui::TextDisabled("no preset loaded");
    } else {
        ImGui::Text("active: %s", state.activePreset.c_str());
        if (presetModified(state, session)) {
            ImGui::SameLine();
            ImGui::TextColored(kErrorColor, "(modified since)");
        }
    }
    // Saving first: the lists below can be long, the name field stays in reach.
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("save as").x - 2 * ImGui::GetStyle().FramePadding.x - ImGui::GetStyle().ItemSpacing.x);
    const bool enter = inputTextEnter("##name", "preset name", saveName, sizeof(saveName));
    noteItem("presets.name");
    if (ImGui::IsItemHovered()) tooltip("name of the preset file; Enter saves");
    ImGui::SameLine();
    std::error_code ec;
    if ((ImGui::Button("save as") || enter) && saveName[0]) {
        fs::create_directories(state.presetsDir, ec);
        savePreset(state, session, (fs::path(state.presetsDir) / (std::string(saveName) + ".json")).string(), saveName);
    }
    ImGui::Separator();
    wrappedColored(kDimColor, "built in (a click loads)");
    for (const auto& p : builtinPresets()) {
        if (ImGui::Selectable(p.name.c_str())) applyPreset(state, session, p);
        noteItem("presets.builtin." + p.name);
        if (ImGui::IsItemHovered()) {
            std::string tip = p.description.empty() ? "" : p.description + "\n\n";
            for (const auto& [k, v] : p.knobs) tip += k + " = " + v + "\n";
            tooltip("%s", tip.c_str());
        }
    }
    ImGui::Separator();
    ImGui::TextDisabled("folder %s", state.presetsDir.c_str());
    std::vector<fs::path> files;
    if (fs::is_directory(state.presetsDir, ec))
        for (const auto& e : fs::directory_iterator(state.presetsDir, ec))
            if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) ImGui::TextDisabled("(no presets saved yet)");
    for (const auto& f : files) {
        ImGui::PushID(f.c_str());
        if (ImGui::Selectable(f.stem().c_str(), false, ImGuiSelectableFlags_AllowItemOverlap)) loadPresetFile(state, session, f.string());
        ImGui::SameLine(ImGui::GetContentRegionAvail().x - 60);
        if (ImGui::SmallButton("overwrite")) savePreset(state, session, f.string(), f.stem().string());
        ImGui::PopID();
    }
    ImGui::End();
}

}  // namespace dw::ui
