#pragma once
// Scene: what is loaded, opening another (built-in, example or any path; a
// failure keeps the current scene and says why), ambient and background, and
// the camera.
#include "renderer/RenderSession.h"
#include "ui/FileBrowser.h"
#include "ui/UiState.h"

namespace dw::ui {

struct ScenePanel {
    char path[1024] = {};
    FileBrowser browser;
    void draw(const char* title, bool* open, UiState& state, RenderSession& session);

private:
    // The path field, open and browse, the recent files, then the built-in and example scenes.
    void openSection(UiState& state, RenderSession& session, bool focusPath);
};

// Loads a scene into the session with knobs and camera as at start-up
// (state.run: defaults, the scene's settings, the start-up preset, --set);
// on failure logs the error and keeps the old scene and knobs. A file
// opened goes to the front of state.recentScenes. An experiment record or a
// preset given as the scene (the path field, browser, recent list, a drop)
// opens as a record (openRecord) or a preset (loadPresetFile), said in Messages.
bool openScene(UiState& state, RenderSession& session, const std::string& spec);
// The scene files the Scene panel and the file browser offer.
extern const std::vector<std::string> kSceneExtensions;

}  // namespace dw::ui
