#pragma once
// One run configuration for every subcommand and the workbench (DESIGN.md:
// "one run configuration ... serves render, bench, tradeoff and the window
// alike"): the scene, the preset, the --set overrides, the size and the frame
// counts, and one rule for how they combine, so a scene never keeps the knobs
// of the one before it and a command line means the same everywhere:
//   presets --preset may be given several times (a GTAO or AOV preset with
//           Low, Medium or High): they apply in the order given, a later
//           one's knob over an earlier one's, knob by knob;
//   scene   --scene, else the last preset's scene that names one, else "default";
//   knobs   at every scene load: defaults, then the scene's own settings,
//           then each preset's knobs in order, then --set, each over the one before;
//   camera  the last preset's that has one and names the loaded scene (or
//           no scene at all), else the scene's.
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
    // --scene-time: the scene time (seconds) its glTF animation is posed at
    // (skins, morph targets, clips; Animation.h). RenderSession::setScene takes it.
    double sceneTime = 0.0;
    // --animation NAME|INDEX|none: which clip plays (ClipChoice.h); empty:
    // each file's first. RenderSession::setScene applies it before posing.
    std::string animation;

    // --preset: a built-in preset's name, else a preset file. Throws Error when
    // it is neither, FileError when the file is not a preset. setPreset
    // replaces the presets with this one ("" clears them); addPreset puts
    // one more after them (a repeated --preset).
    void setPreset(const std::string& spec);
    void addPreset(const std::string& spec);
    // A preset made in code (tests; the window's start-up preset re-applied).
    void setPreset(Preset preset);
    // The presets as one (null when there are none): name "A + B", the knobs
    // of each in order (applied in order, the later wins), the last scene
    // and camera given, the groups of all.
    const Preset* preset() const { return combined_ ? &*combined_ : nullptr; }
    // Each --preset as given, in order; presetSpec() joins them with " + ".
    const std::vector<std::string>& presetSpecs() const { return presetSpecs_; }
    std::string presetSpec() const;

    // The scene to open: --scene beats the presets' scene; "default" if neither names one.
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
    void combine();
    std::vector<std::string> presetSpecs_;
    std::vector<Preset> presets_;
    std::optional<Preset> combined_;
};

}  // namespace dw
