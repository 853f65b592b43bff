#include "renderer/RunConfig.h"

#include <filesystem>

#include "renderer/Error.h"
#include "renderer/graph/Pipeline.h"

namespace dw {

namespace fs = std::filesystem;

void RunConfig::setPreset(const std::string& spec) {
    if (spec.empty()) {
        presetSpec_.clear();
        preset_.reset();
        return;
    }
    if (const Preset* builtin = findBuiltinPreset(spec)) {
        preset_ = *builtin;
    } else if (!fs::exists(spec)) {
        std::string names;
        for (const auto& b : builtinPresets()) names += (names.empty() ? "" : ", ") + b.name;
        throw Error("--preset '" + spec + "' is neither a built-in preset (" + names + ") nor an existing file");
    } else {
        preset_ = Preset::load(spec);
    }
    presetSpec_ = spec;
}

void RunConfig::setPreset(Preset preset) {
    presetSpec_ = preset.name;
    preset_ = std::move(preset);
}

std::string RunConfig::sceneSpec() const {
    if (!scene.empty()) return scene;
    if (preset_ && !preset_->scene.empty()) return preset_->scene;
    return "default";
}

void RunConfig::validate() const { validate(declaredKnobs()); }

void RunConfig::validate(const KnobRegistry& declared) const {
    KnobRegistry knobs = declared;
    if (preset_) {
        // Every key must be valid: a script should not silently run something else.
        const Preset::ApplyReport r = preset_->applyKnobs(knobs);
        if (!r.ignored.empty()) {
            std::string all;
            for (const auto& i : r.ignored) all += (all.empty() ? "" : " | ") + i;
            throw FileError(presetSpec_, all);
        }
    }
    for (const auto& s : sets) knobs.applyAssignment(s);
}

void RunConfig::applyKnobs(KnobRegistry& knobs, const Scene& loaded) const {
    knobs.resetAll();
    for (const auto& [name, value] : loaded.settings) {
        try {
            knobs.setFromString(name, value);
        } catch (const Error& e) {
            throw FileError(loaded.source, std::string("settings: ") + e.what());
        }
    }
    if (preset_) {
        const Preset::ApplyReport r = preset_->applyKnobs(knobs);
        if (!r.ignored.empty()) throw FileError(presetSpec_, r.ignored.front());
    }
    for (const auto& s : sets) knobs.applyAssignment(s);
}

Camera RunConfig::camera(const Scene& loaded) const {
    // The preset's camera was saved looking at its own scene.
    if (preset_ && preset_->camera && (preset_->scene.empty() || namesScene(preset_->scene, loaded)))
        return *preset_->camera;
    return loaded.camera;
}

bool RunConfig::namesScene(const std::string& spec, const Scene& loaded) {
    if (spec.empty()) return false;
    if (spec == loaded.source || "builtin:" + spec == loaded.source) return true;
    std::error_code ec;
    return fs::is_regular_file(spec, ec) && fs::is_regular_file(loaded.source, ec) && fs::equivalent(spec, loaded.source, ec);
}

KnobRegistry RunConfig::declaredKnobs() {
    KnobRegistry knobs;
    Pipeline declarations(knobs);  // the passes declare their knobs; no GL needed
    return knobs;
}

}  // namespace dw
