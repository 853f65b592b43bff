#pragma once
// What a JSON file the workbench reads is: a scene, an experiment record or
// a preset. The three share the .json extension and some keys ("name",
// "camera"), and the scene loader reads the other two as an empty scene with
// "unknown key" warnings; so every place that takes a scene (--scene of each
// subcommand, the Python module, the window's browser, recent list and drop)
// asks here first. The one definition of the test and of the message.
//
// A record: "format": "deferred-workbench record" (renderer/record/ExperimentRecord).
// A preset: "format": "deferred-workbench preset", or no "format" and a
// "knobs" object (renderer/knobs/Preset reads both). Anything else is a scene
// (or not JSON at all: the scene loader says what is wrong with it).
#include <string>

namespace dw {

enum class SceneFileKind { Scene, Record, Preset };

// The kind of the file at `path`: Scene for anything that is not a readable
// .json file or not valid JSON (the loaders report those), so it never throws.
// Reads the file (bounded: renderer/io/TextFile's limit).
SceneFileKind classifySceneFile(const std::string& path);
// Throws FileError(spec, ...) when `spec` names a record or a preset, saying
// what it is and what opens it: `deferred-workbench replay FILE` (and the
// record's scene) for a record, --preset FILE (preset= in Python) for a
// preset. Built-in names and other files pass.
void refuseNonSceneFile(const std::string& spec);

}  // namespace dw
