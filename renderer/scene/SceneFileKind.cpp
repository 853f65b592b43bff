#include "renderer/scene/SceneFileKind.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "renderer/Error.h"
#include "renderer/io/JsonGuard.h"

namespace dw {

namespace {

constexpr const char* kRecordFormat = "deferred-workbench record";
constexpr const char* kPresetFormat = "deferred-workbench preset";

bool isJsonName(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".json";
}

// `j[key][inner]` as text, when it is a string.
std::string nestedText(const nlohmann::json& j, const char* key, const char* inner) {
    const auto outer = j.find(key);
    if (outer == j.end() || !outer->is_object()) return "";
    const auto v = outer->find(inner);
    return v != outer->end() && v->is_string() ? v->get<std::string>() : "";
}

// The kind of a parsed JSON document.
SceneFileKind classifySceneJson(const nlohmann::json& j) {
    if (!j.is_object()) return SceneFileKind::Scene;
    const auto format = j.find("format");
    if (format != j.end() && format->is_string()) {
        if (*format == kRecordFormat) return SceneFileKind::Record;
        if (*format == kPresetFormat) return SceneFileKind::Preset;
        return SceneFileKind::Scene;
    }
    // A preset written before "format" existed: knobs and nothing of a scene's
    // own (a scene JSON with a stray "knobs" key stays a scene; its loader warns).
    const auto knobs = j.find("knobs");
    if (knobs == j.end() || !knobs->is_object()) return SceneFileKind::Scene;
    for (const char* sceneKey : {"objects", "lights", "lighting", "materials", "sky", "ambient", "background", "settings"})
        if (j.contains(sceneKey)) return SceneFileKind::Scene;
    return SceneFileKind::Preset;
}

// The parsed file, or null when it is not a readable JSON file.
nlohmann::json readIfJson(const std::string& path) {
    std::error_code ec;
    if (!isJsonName(path) || !std::filesystem::is_regular_file(path, ec)) return nullptr;
    try {
        JsonGuardOptions options;
        options.numbersAreFloats = false;  // records hold 64-bit counts and hashes
        return readJsonFile(path, options);
    } catch (const Error&) {
        return nullptr;
    }
}

}  // namespace

SceneFileKind classifySceneFile(const std::string& path) { return classifySceneJson(readIfJson(path)); }

void refuseNonSceneFile(const std::string& spec) {
    const nlohmann::json j = readIfJson(spec);
    switch (classifySceneJson(j)) {
    case SceneFileKind::Scene:
        return;
    case SceneFileKind::Record: {
        const std::string scene = nestedText(j, "scene", "spec");
        throw FileError(spec, std::string("this is an experiment record (\"format\": \"") + kRecordFormat +
                                  "\"), not a scene: `deferred-workbench replay " + spec +
                                  "` renders it again and compares; its scene is the record's scene.spec (" +
                                  (scene.empty() ? std::string("missing here") : "here '" + scene + "'") + ")");
    }
    case SceneFileKind::Preset: {
        const auto s = j.find("scene");
        const std::string scene = s != j.end() && s->is_string() ? s->get<std::string>() : "";
        throw FileError(spec, "this is a preset (knobs" + std::string(j.contains("camera") ? " and a camera" : "") +
                                  "), not a scene: give it as --preset " + spec + " (preset= in Python)" +
                                  (scene.empty() ? std::string(", with the scene it is for as --scene")
                                                 : "; it names its scene, '" + scene + "', used without --scene"));
    }
    }
}

}  // namespace dw
