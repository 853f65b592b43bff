#include "renderer/knobs/Preset.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "renderer/Error.h"
#include "renderer/io/FloatCheck.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"
#include "renderer/scene/CameraCheck.h"

namespace dw {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

constexpr const char* kFormat = "deferred-workbench preset";

// A float as the double whose shortest text is the float's shortest text:
// -14 stays -14 in the file, not -13.999999046325684.
double exactFloat(float f) {
    std::array<char, 32> buf{};
    const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), f);
    return ec == std::errc() ? std::strtod(std::string(buf.data(), end).c_str(), nullptr) : f;
}

json vec3(const glm::vec3& v) { return json::array({exactFloat(v.x), exactFloat(v.y), exactFloat(v.z)}); }

// Knob text as a JSON value: booleans, integers as integers, other numbers
// as numbers, enum choices as strings.
json knobValue(const std::string& v) {
    if (v == "true" || v == "false") return v == "true";
    long long i = 0;
    if (auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), i); ec == std::errc() && p == v.data() + v.size())
        return i;
    double d = 0.0;
    // A number only when it reads back as one (not "1e400", not beyond a float).
    if (auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), d);
        ec == std::errc() && p == v.data() + v.size() && floatProblem(d).empty())
        return d;
    return v;
}

float readFloat(const json& j, const std::string& what, const std::string& source) {
    if (!j.is_number()) throw FileError(source, what + ": expected a number");
    const double v = j.get<double>();
    if (const std::string problem = floatProblem(v); !problem.empty()) throw FileError(source, what + ": " + problem);
    return static_cast<float>(v);
}

glm::vec3 readVec3(const json& j, const std::string& what, const std::string& source) {
    if (!j.is_array() || j.size() != 3) throw FileError(source, what + ": expected an array of 3 numbers");
    return {readFloat(j[0], what + "[0]", source), readFloat(j[1], what + "[1]", source),
            readFloat(j[2], what + "[2]", source)};
}

std::string valueText(const json& v) {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    return v.dump();
}

}  // namespace

Preset Preset::capture(const std::string& name, const KnobRegistry& knobs, const Camera& camera,
                       const std::string& scene) {
    Preset p;
    p.name = name;
    p.scene = scene;
    p.camera = camera;
    for (size_t i = 0; i < knobs.size(); ++i)
        p.knobs.emplace_back(knobs.spec(static_cast<int>(i)).name, knobs.format(static_cast<int>(i)));
    return p;
}

std::string Preset::toJson() const {
    json j;
    j["format"] = kFormat;
    j["version"] = 1;
    j["name"] = name;
    if (!description.empty()) j["description"] = description;
    if (!scene.empty()) j["scene"] = scene;
    if (!groups.empty()) j["groups"] = groups;
    if (camera) {
        j["camera"] = {{"pos", vec3(camera->position)}, {"look-at", vec3(camera->target)}, {"up", vec3(camera->up)},
                       {"fov", exactFloat(camera->fovYDegrees)}, {"near", exactFloat(camera->nearPlane)},
                       {"far", exactFloat(camera->farPlane)}};
    }
    json k = json::object();
    for (const auto& [n, v] : knobs) k[n] = knobValue(v);
    j["knobs"] = k;
    return j.dump(2) + "\n";
}

Preset Preset::fromJson(const std::string& text, const std::string& source) {
    // Depth and numbers beyond a float, by JSON path, before parsing.
    const json j = parseOrderedJson(text, source);
    if (!j.is_object() || !j.contains("knobs") || !j["knobs"].is_object())
        throw FileError(source, "not a preset: expected an object with a \"knobs\" object");
    if (j.contains("format") && j["format"] != kFormat)
        throw FileError(source, "not a preset: \"format\" is " + j["format"].dump());
    Preset p;
    p.name = fs::path(source).stem().string();
    for (const char* key : {"name", "description", "scene"}) {
        if (!j.contains(key)) continue;
        if (!j[key].is_string()) throw FileError(source, std::string(key) + ": expected a string");
        const std::string v = j[key].get<std::string>();
        if (std::string(key) == "name") p.name = v;
        else if (std::string(key) == "description") p.description = v;
        else p.scene = v;
    }
    if (j.contains("groups")) {
        const json& g = j["groups"];
        if (!g.is_array()) throw FileError(source, "\"groups\" must be an array of knob group names");
        for (const auto& e : g) {
            if (!e.is_string()) throw FileError(source, "\"groups\" must be an array of knob group names");
            p.groups.push_back(e.get<std::string>());
        }
    }
    if (j.contains("camera")) {
        const json& c = j["camera"];
        if (!c.is_object()) throw FileError(source, "camera: expected an object");
        for (const char* key : {"pos", "look-at"})
            if (!c.contains(key)) throw FileError(source, std::string("camera: needs \"") + key + "\"");
        Camera cam;
        cam.position = readVec3(c["pos"], "camera.pos", source);
        cam.target = readVec3(c["look-at"], "camera.look-at", source);
        cam.up = c.contains("up") ? readVec3(c["up"], "camera.up", source) : glm::vec3(0, 1, 0);
        cam.fovYDegrees = c.contains("fov") ? readFloat(c["fov"], "camera.fov", source) : 60.0f;
        cam.nearPlane = c.contains("near") ? readFloat(c["near"], "camera.near", source) : 0.1f;
        cam.farPlane = c.contains("far") ? readFloat(c["far"], "camera.far", source) : 200.0f;
        // The preset's scene is not loaded here: the camera's own coordinates set the scale.
        if (const auto problem = findCameraProblem(cam, 0.0f))
            throw FileError(source, "camera." + problem->field + ": " + problem->what);
        p.camera = cam;
    }
    for (auto it = j["knobs"].begin(); it != j["knobs"].end(); ++it) {
        const json& v = it.value();
        if (!v.is_string() && !v.is_boolean() && !v.is_number())
            throw FileError(source, "knobs." + it.key() + ": expected a number, string or boolean");
        p.knobs.emplace_back(it.key(), valueText(v));
    }
    return p;
}

Preset Preset::load(const std::string& path) {
    return fromJson(readWholeFile(path, "preset not found", "cannot read preset"), path);
}

void Preset::save(const std::string& path) const { writeFileAtomically(path, toJson()); }

std::string Preset::groupOf(const std::string& knobName) { return knobName.substr(0, knobName.find('.')); }

bool Preset::covers(const std::string& knobName) const {
    return groups.empty() || std::find(groups.begin(), groups.end(), groupOf(knobName)) != groups.end();
}

Preset::ApplyReport Preset::applyOver(KnobRegistry& registry,
                                      const std::vector<std::pair<std::string, std::string>>& sceneSettings) const {
    for (size_t i = 0; i < registry.size(); ++i)
        if (covers(registry.spec(static_cast<int>(i)).name)) registry.reset(static_cast<int>(i));
    for (const auto& [n, v] : sceneSettings) {
        if (!covers(n)) continue;
        try {
            registry.setFromString(n, v);
        } catch (const Error&) {
            // The scene's load already reported its bad settings.
        }
    }
    return applyKnobs(registry);
}

Preset::ApplyReport Preset::applyKnobs(KnobRegistry& registry) const {
    ApplyReport r;
    // An old name beside the new one sets one knob twice, and the file's
    // order would decide which wins: refused, both named.
    for (const auto& [n, v] : knobs) {
        const std::string target = registry.aliasTarget(n);
        if (target.empty()) continue;
        for (const auto& [other, ov] : knobs)
            if (other == target)
                r.ignored.push_back("knobs." + n + " and knobs." + target + " set the same knob ('" + n +
                                    "' is the old name of '" + target + "'); give only '" + target + "'");
    }
    if (!r.ignored.empty()) return r;
    for (const auto& [n, v] : knobs) {
        try {
            registry.setFromString(n, v);
            ++r.applied;
        } catch (const Error& e) {
            r.ignored.push_back(e.what());
        }
    }
    return r;
}

const Preset* findBuiltinPreset(const std::string& name) {
    for (const auto& p : builtinPresets())
        if (p.name == name) return &p;
    return nullptr;
}

}  // namespace dw
