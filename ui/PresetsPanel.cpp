#include "ui/PresetsPanel.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>

#include "ui/ScenePanel.h"
#include "ui/Widgets.h"

namespace dw::ui {

namespace fs = std::filesystem;

bool applyPreset(UiState& state, RenderSession& session, const Preset& preset) {
    // Another scene opens as any scene does (start-up knobs first); this
    // preset, chosen by hand, then goes over them.
    if (!preset.scene.empty() && !RunConfig::namesScene(preset.scene, session.scene())) {
        if (!openScene(state, session, preset.scene)) return false;
    }
    if (preset.camera) session.camera() = *preset.camera;
    const Preset::ApplyReport r = preset.applyKnobs(session.knobs());
    state.log.info("preset '" + preset.name + "': " + std::to_string(r.applied) + " knobs set", state.time);
    if (!r.ignored.empty()) {
        std::string all = "preset '" + preset.name + "' ignored " + std::to_string(r.ignored.size()) + " key(s):";
        for (const auto& i : r.ignored) all += "\n  " + i;
        state.log.error(all, state.time);
    }
    return true;
}

bool loadPresetFile(UiState& state, RenderSession& session, const std::string& path) {
    try {
        return applyPreset(state, session, Preset::load(path));
    } catch (const std::exception& e) {
        state.log.error(std::string("cannot load preset: ") + e.what(), state.time);
        return false;
    }
}

void PresetsPanel::draw(const char* title, bool* open, UiState& state, RenderSession& session) {
    if (!ImGui::Begin(title, open)) {
        ImGui::End();
        return;
    }
    ImGui::TextDisabled("built in");
    for (const auto& p : builtinPresets()) {
        if (ImGui::Selectable(p.name.c_str())) applyPreset(state, session, p);
        if (ImGui::IsItemHovered()) {
            std::string tip = p.description.empty() ? "" : p.description + "\n\n";
            for (const auto& [k, v] : p.knobs) tip += k + " = " + v + "\n";
            ImGui::SetTooltip("%s", tip.c_str());
        }
    }
    ImGui::Separator();
    ImGui::TextDisabled("folder %s", state.presetsDir.c_str());
    std::error_code ec;
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
        if (ImGui::SmallButton("overwrite")) {
            try {
                Preset::capture(f.stem().string(), session.knobs(), session.camera(), session.scene().source).save(f.string());
                state.log.info("saved " + f.string(), state.time);
            } catch (const std::exception& e) {
                state.log.error(std::string("cannot save preset: ") + e.what(), state.time);
            }
        }
        ImGui::PopID();
    }
    ImGui::Separator();
    ImGui::SetNextItemWidth(-70);
    ImGui::InputText("##name", saveName, sizeof(saveName));
    ImGui::SameLine();
    if (ImGui::Button("save as") && saveName[0]) {
        const fs::path path = fs::path(state.presetsDir) / (std::string(saveName) + ".json");
        try {
            fs::create_directories(state.presetsDir);
            Preset::capture(saveName, session.knobs(), session.camera(), session.scene().source).save(path.string());
            state.log.info("saved " + path.string(), state.time);
        } catch (const std::exception& e) {
            state.log.error(std::string("cannot save preset: ") + e.what(), state.time);
        }
    }
    ImGui::End();
}

}  // namespace dw::ui
