// The presets that ship with the workbench, in knob values.
#include "renderer/Preset.h"

namespace dw {

const std::vector<Preset>& builtinPresets() {
    static const std::vector<Preset> presets = [] {
        std::vector<Preset> v;
        auto add = [&](std::string name, std::vector<std::pair<std::string, std::string>> knobs) {
            Preset p;
            p.name = std::move(name);
            p.knobs = std::move(knobs);
            v.push_back(std::move(p));
        };
        // Light-volume cost against accuracy: the threshold at which volumes end.
        add("lights: exact (threshold 1/1024)", {{"lighting.threshold", "0.0009765625"}});
        add("lights: 8-bit (threshold 1/255)", {{"lighting.threshold", "0.00392156862745098"}});
        add("lights: coarse (threshold 5/256, seed 003)", {{"lighting.threshold", "0.01953125"}});
        add("lights: brute force", {{"lighting.strategy", "fullscreen"}});
        return v;
    }();
    return presets;
}

}  // namespace dw
