#pragma once
// One run configuration for every subcommand and the workbench (DESIGN.md:
// "one run configuration ... serves render, bench, tradeoff and the window
// alike"): the scene, the preset, the --set overrides, the size and the frame
// counts, and one rule for how they combine, so a scene never keeps the knobs
// of the one before it and a command line means the same everywhere:
//   scene   --scene, else the preset's scene, else "default";
//   knobs   at every scene load: defaults, then the scene's own settings,
//           then the preset's knobs, then --set, each over the one before;
//   camera  the preset's when it has one and names the loaded scene (or no
//           scene at all), else the scene's.
// Needs no GL. validate() checks the preset and --set up front, so a typo in
// a script fails before anything renders.
#include <optional>
#include <string>
#include <vector>

#include "renderer/knobs/KnobRegistry.h"
#include "renderer/knobs/Preset.h"
#include "renderer/scene/Camera.h"
#include "renderer/scene/Scene.h"

namespace dw {

class RunConfig {
public:
    std::string scene;              // --scene: built-in name, .json, .gltf/.glb; empty: sceneSpec()
    std::vector<std::string> sets;  // --set name=value, applied in this order
    int width = 1280, height = 720;
    int frames = 1;   // frames counted (the window: 0 runs until it is closed)
    int warmup = 0;   // frames rendered before counting starts, left out of timings

    // --preset: a built-in preset's name, else a preset file. Throws Error when
    // it is neither, FileError when the file is not a preset. "" clears it.
    void setPreset(const std::string& spec);
    // A preset made in code (tests; the window's start-up preset re-applied).
    void setPreset(Preset preset);
    const Preset* preset() const { return preset_ ? &*preset_ : nullptr; }
    const std::string& presetSpec() const { return presetSpec_; }

    // The scene to open: --scene beats the preset's scene; "default" if neither names one.
    std::string sceneSpec() const;

    // Every preset key and every --set against the knob declarations: throws
    // FileError(preset, every bad key) or the Error of the first bad --set.
    // Without `declared`, those of the pipeline's passes.
    void validate() const;
    void validate(const KnobRegistry& declared) const;

    // The knob values the `loaded` scene starts with: every knob to its
    // default, then the scene's settings, then the preset, then --set. Throws
    // FileError(loaded.source, "settings: ...") for a bad scene setting (and
    // Error for anything validate() would have caught); `knobs` is then half
    // updated, so callers that must keep their values apply to a copy.
    void applyKnobs(KnobRegistry& knobs, const Scene& loaded) const;
    // The camera the `loaded` scene starts with.
    Camera camera(const Scene& loaded) const;

    // Whether `spec`, as --scene or a preset's "scene" take it, names the
    // `loaded` scene: "street" and "builtin:street" alike, a file by any path.
    static bool namesScene(const std::string& spec, const Scene& loaded);
    // Every knob the pipeline's passes declare, at its default (no GL).
    static KnobRegistry declaredKnobs();

private:
    std::string presetSpec_;
    std::optional<Preset> preset_;
};

}  // namespace dw
