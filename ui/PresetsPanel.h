#pragma once
// Presets: the built-in ones and the JSON files in the presets folder; load
// (scene, camera and knobs; unknown or invalid keys are listed, the rest
// applied) and save (atomically; a failed save keeps the old file).
#include "renderer/knobs/Preset.h"
#include "renderer/RenderSession.h"
#include "ui/UiState.h"

namespace dw::ui {

struct PresetsPanel {
    char saveName[128] = "my-preset";
    void draw(const char* title, bool* open, UiState& state, RenderSession& session);
};

// Saves the session's knobs, camera and scene as `path` (atomically); the
// result goes to the log and a toast with the absolute path.
bool savePreset(UiState& state, RenderSession& session, const std::string& path, const std::string& name);
// Whether any knob differs from its value right after the active preset was loaded or saved.
bool presetModified(const UiState& state, const RenderSession& session);

// Applies a preset to the session; errors and ignored keys go to the log. A
// preset naming another scene opens it first (openScene: knobs reset to the
// start-up values for that scene), then sets its camera, and its knobs over
// the defaults and scene settings of the groups it covers (Preset::applyOver),
// so the result does not depend on what was loaded before.
// Returns false (and changes nothing) when the preset's scene cannot be opened.
bool applyPreset(UiState& state, RenderSession& session, const Preset& preset);
// Names `name` the active preset, with the session's knob values now as the
// ones "(modified since)" compares with: after a load or save, and at start-up
// for the --preset ones ("AOV1 + Low" when several).
void rememberPreset(UiState& state, const RenderSession& session, const std::string& name);
bool loadPresetFile(UiState& state, RenderSession& session, const std::string& path);

}  // namespace dw::ui
