#pragma once
// Presets: every knob, the camera and the scene reference as JSON. Saving
// writes a temporary file and renames it over the old one, so a failed save
// never destroys the previous preset. Loading applies what it can and reports
// the keys it ignored (unknown knobs, bad values); a file that is not a valid
// preset changes nothing.
#include <optional>
#include <string>
#include <vector>

#include "renderer/knobs/KnobRegistry.h"
#include "renderer/scene/Camera.h"

namespace dw {

struct Preset {
    std::string name;
    std::string description;
    std::string scene;  // scene spec (built-in name or path); empty: any scene
    std::optional<Camera> camera;
    std::vector<std::pair<std::string, std::string>> knobs;  // name -> value text, in order

    // Snapshot of the current state.
    static Preset capture(const std::string& name, const KnobRegistry& knobs, const Camera& camera,
                          const std::string& scene);
    std::string toJson() const;
    // Throws FileError(source, ...) when the text is not a preset at all.
    static Preset fromJson(const std::string& text, const std::string& source);
    static Preset load(const std::string& path);
    // Atomic: temp file in the same folder, flushed, then renamed. Throws FileError.
    void save(const std::string& path) const;

    struct ApplyReport {
        int applied = 0;
        std::vector<std::string> ignored;  // "tonemap.kee: unknown knob ..." etc.
    };
    // Sets every valid knob; invalid or unknown ones are listed, not applied.
    ApplyReport applyKnobs(KnobRegistry& registry) const;
};

// Presets that ship with the workbench (the seed's quality levels and test settings).
const std::vector<Preset>& builtinPresets();
const Preset* findBuiltinPreset(const std::string& name);

}  // namespace dw
