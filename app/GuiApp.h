#pragma once
// The workbench window: a GLFW window with an OpenGL 4.5 core context, Dear
// ImGui on top, and the frame loop that renders the pipeline, prepares the
// images the panels show, draws the UI and carries out its requests.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/scene/Scene.h"

namespace dw {

struct GuiOptions {
    std::string scene = "default";
    std::string preset;         // built-in preset name or file
    std::string presetsDir;     // where presets are listed and saved
    std::string scenesDir;      // example scenes offered in the Scene panel
    std::vector<std::string> sets;
    int width = 1600, height = 900;
    int frames = 0;             // 0: run until closed
    std::string screenshot;     // written after the last frame when frames > 0
};

// Throws dw::Error when there is no display or no GL 4.5 core window.
int runGui(const GuiOptions& options, Scene scene);

}  // namespace dw
