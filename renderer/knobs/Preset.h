#pragma once
// Presets: every knob, the camera and the scene reference as JSON. Saving
// writes a temporary file and renames it over the old one, so a failed save
// never destroys the previous preset. Loading applies what it can and reports
// the keys it ignored (unknown knobs, bad values); a file that is not a valid
// preset changes nothing.
//
// Exact: integer and enum knobs are written as integers and strings, floats
// and the camera in the shortest text that reads back as the same float, so
// save -> load -> save is byte-identical.
//
// Groups: a knob's group is its name before the first '.' ("ssao" for
// ssao.samples). A preset covers the groups in its "groups" list, or every
// group when it has none (a saved preset always covers all). applyOver()
// first puts every knob of a covered group back to its default and the
// scene's setting, so loading a preset gives the same knobs whatever was
// loaded before it; a partial preset (e.g. only "lighting") leaves the other
// groups as they are.
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
    std::vector<std::string> groups;  // covered knob groups; empty: every group

    // "ssao.samples" -> "ssao".
    static std::string groupOf(const std::string& knobName);
    bool covers(const std::string& knobName) const;

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
    // Loading as the workbench does: every knob of a covered group to its
    // default, then to `sceneSettings` (the scene's own knob settings, as
    // Scene::settings), then applyKnobs(). Scene settings that do not apply
    // are skipped here (loading the scene already reported them).
    ApplyReport applyOver(KnobRegistry& registry,
                          const std::vector<std::pair<std::string, std::string>>& sceneSettings) const;
};

// Presets that ship with the workbench (the seed's quality levels and test settings).
const std::vector<Preset>& builtinPresets();
const Preset* findBuiltinPreset(const std::string& name);

}  // namespace dw
