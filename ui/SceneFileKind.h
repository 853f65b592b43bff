#pragma once
// What a JSON file handed to the window as a scene really is: the Scene
// panel's path field, its file browser, the recent list and a file dropped
// on the window all take .json files, and an experiment record or a preset
// loaded as a scene rendered an empty scene with "unknown key" warnings. The
// window opens a record as a record and a preset as a preset instead.
//
// A local check of the window's own: the CLI side refuses such a file for
// --scene with a classifier of its own (branch wt-cli); the two are to
// become one.
#include <string>

namespace dw::ui {

enum class SceneFileKind {
    Scene,   // anything else: a scene JSON, glTF, a built-in scene's name, or a file the loader will refuse
    Record,  // "format": "deferred-workbench record" (renderer/record/ExperimentRecord)
    Preset,  // "format": "deferred-workbench preset", or an older preset: a "knobs" object and no scene keys
};

// Reads `spec` only when it names a .json file; one that cannot be read or
// parsed is a Scene (the scene loader then says what is wrong with it).
SceneFileKind classifySceneFile(const std::string& spec);

}  // namespace dw::ui
