#include "renderer/RunConfig.h"

#include <algorithm>
#include <filesystem>

#include "renderer/Error.h"
#include "renderer/graph/Pipeline.h"

namespace dw {

namespace fs = std::filesystem;

void RunConfig::setPreset(const std::string& spec) {
    presetSpecs_.clear();
    presets_.clear();
    combined_.reset();
    if (!spec.empty()) addPreset(spec);
}

void RunConfig::addPreset(const std::string& spec) {
    if (const Preset* builtin = findBuiltinPreset(spec)) {
        presets_.push_back(*builtin);
    } else if (!fs::exists(spec)) {
        std::string names;
        for (const auto& b : builtinPresets()) names += (names.empty() ? "" : ", ") + b.name;
        throw Error("--preset '" + spec + "' is neither a built-in preset (" + names + ") nor an existing file");
    } else {
        presets_.push_back(Preset::load(spec));
    }
    presetSpecs_.push_back(spec);
    combine();
}

void RunConfig::setPreset(Preset preset) {
    presetSpecs_ = {preset.name};
    presets_ = {std::move(preset)};
    combine();
}

std::string RunConfig::presetSpec() const {
    std::string all;
    for (const auto& s : presetSpecs_) all += (all.empty() ? "" : " + ") + s;
    return all;
}

void RunConfig::combine() {
    if (presets_.empty()) {
        combined_.reset();
        return;
    }
    if (presets_.size() == 1) {
        combined_ = presets_.front();
        return;
    }
    Preset c;
    bool everyGroup = false;
    for (const Preset& p : presets_) {
        c.name += (c.name.empty() ? "" : " + ") + p.name;
        if (!p.description.empty()) c.description += (c.description.empty() ? "" : "\n") + p.name + ": " + p.description;
        if (!p.scene.empty()) c.scene = p.scene;
        if (p.camera) c.camera = p.camera;
        c.knobs.insert(c.knobs.end(), p.knobs.begin(), p.knobs.end());
        if (p.groups.empty()) everyGroup = true;
        for (const auto& g : p.groups)
            if (std::find(c.groups.begin(), c.groups.end(), g) == c.groups.end()) c.groups.push_back(g);
    }
    if (everyGroup) c.groups.clear();
    combined_ = std::move(c);
}

std::string RunConfig::sceneSpec() const {
    if (!scene.empty()) return scene;
    if (combined_ && !combined_->scene.empty()) return combined_->scene;
    return "default";
}

void RunConfig::validate() const { validate(declaredKnobs()); }

void RunConfig::validate(const KnobRegistry& declared) const {
    KnobRegistry knobs = declared;
    for (std::size_t p = 0; p < presets_.size(); ++p) {
        // Every key must be valid: a script should not silently run something else.
        const Preset::ApplyReport r = presets_[p].applyKnobs(knobs);
        if (!r.ignored.empty()) {
            std::string all;
            for (const auto& i : r.ignored) all += (all.empty() ? "" : " | ") + i;
            throw FileError(presetSpecs_[p], all);
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
    for (std::size_t p = 0; p < presets_.size(); ++p) {
        const Preset::ApplyReport r = presets_[p].applyKnobs(knobs);
        if (!r.ignored.empty()) throw FileError(presetSpecs_[p], r.ignored.front());
    }
    for (const auto& s : sets) knobs.applyAssignment(s);
}

Camera RunConfig::camera(const Scene& loaded) const {
    // A preset's camera was saved looking at its own scene; the last one that fits.
    for (auto p = presets_.rbegin(); p != presets_.rend(); ++p)
        if (p->camera && (p->scene.empty() || namesScene(p->scene, loaded))) return *p->camera;
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
