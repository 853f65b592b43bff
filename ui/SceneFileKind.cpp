#include "ui/SceneFileKind.h"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "renderer/io/JsonGuard.h"

namespace dw::ui {

namespace fs = std::filesystem;

SceneFileKind classifySceneFile(const std::string& spec) {
    std::error_code ec;
    if (fs::path(spec).extension() != ".json" || !fs::is_regular_file(spec, ec)) return SceneFileKind::Scene;
    nlohmann::json j;
    try {
        JsonGuardOptions options;
        options.numbersAreFloats = false;  // classify only; the reader that opens it checks its numbers
        j = readJsonFile(spec, options);
    } catch (const std::exception&) {
        return SceneFileKind::Scene;
    }
    if (!j.is_object()) return SceneFileKind::Scene;
    if (const auto f = j.find("format"); f != j.end() && f->is_string()) {
        if (*f == "deferred-workbench record") return SceneFileKind::Record;
        if (*f == "deferred-workbench preset") return SceneFileKind::Preset;
    }
    // Presets written before "format" existed: knobs and no scene of their own.
    const auto knobs = j.find("knobs");
    if (knobs == j.end() || !knobs->is_object() || j.contains("format")) return SceneFileKind::Scene;
    for (const char* sceneKey : {"objects", "lighting", "lights", "materials", "sky"})
        if (j.contains(sceneKey)) return SceneFileKind::Scene;
    return SceneFileKind::Preset;
}

}  // namespace dw::ui
