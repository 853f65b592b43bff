#pragma once
// The workbench window: a GLFW window with an OpenGL 4.5 core context, Dear
// ImGui on top, the session, the UI state and the panels set up from the
// options, then handed to the frame loop (GuiLoop), which renders the
// pipeline, prepares the images the panels show, draws the UI and carries
// out its requests; at exit the layout, --save-record and --dump-knobs.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/RunConfig.h"
#include "renderer/scene/Scene.h"

namespace dw {

struct GuiOptions {
    // Scene, preset, --set, window size, frames (0: run until closed). Every
    // scene opened in the window starts from it, as at start-up.
    RunConfig run;
    std::string presetsDir;     // where presets are listed and saved
    std::string scenesDir;      // example scenes offered in the Scene panel
    std::string screenshot;     // written after the last frame when frames > 0
    std::string dumpKnobs;      // knob values written here at exit (RenderSession::writeKnobValues)
    std::string events;         // scripted input replayed frame by frame (ScriptedInput), with frames > 0
    std::string layoutIn;       // a layout.json to start from instead of the saved one (also scripted; never written)
    std::string layoutOut;      // with frames > 0: the panels' rectangles and the probe as JSON after the last frame
    std::string exportDir;      // screenshots and timing CSVs; empty: <data dir>/deferred-workbench/exports
    std::string view;           // the output the viewport shows at start ("final" when empty)
    std::string resolution;     // full, 1/2, 1/4 or auto ("" : full)
    std::string ab;             // the A/B split at start: "", pinned, reference, preset=NAME
    std::string abDisplay;      // and what B's side shows: "" (split), split, difference, flip
    bool record = false;        // start with timing capture on (every frame rendered and timed)
    std::string openRecord;     // an experiment record restored at start (scene, camera, knobs)
    std::string saveRecord;     // the experiment record of the last frame, written at exit
    bool renderdoc = false;     // the process runs under RenderDoc (gui --renderdoc relaunched it so)
};

// `scene` is run.sceneSpec() loaded (so a bad one fails before a window opens).
// Throws dw::Error when there is no display or no GL 4.5 core window.
int runGui(const GuiOptions& options, Scene scene);

}  // namespace dw
