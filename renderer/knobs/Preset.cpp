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
#include "renderer/io/TextFile.h"

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
    if (auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), d); ec == std::errc() && p == v.data() + v.size())
        return d;
    return v;
}

glm::vec3 readVec3(const json& j, const std::string& what, const std::string& source) {
    if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
        throw FileError(source, what + ": expected an array of 3 numbers");
    return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
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
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        throw FileError(source, std::string("not a valid preset (malformed JSON: ") + e.what() + ")");
    }
    if (!j.is_object() || !j.contains("knobs") || !j["knobs"].is_object())
        throw FileError(source, "not a preset: expected an object with a \"knobs\" object");
    if (j.contains("format") && j["format"] != kFormat)
        throw FileError(source, "not a preset: \"format\" is " + j["format"].dump());
    Preset p;
    p.name = j.value("name", fs::path(source).stem().string());
    if (j.contains("description") && j["description"].is_string()) p.description = j["description"].get<std::string>();
    if (j.contains("scene")) {
        if (!j["scene"].is_string()) throw FileError(source, "\"scene\" must be a string");
        p.scene = j["scene"].get<std::string>();
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
        if (!c.is_object()) throw FileError(source, "\"camera\" must be an object");
        Camera cam;
        cam.position = readVec3(c.value("pos", json()), "camera.pos", source);
        cam.target = readVec3(c.value("look-at", json()), "camera.look-at", source);
        cam.up = c.contains("up") ? readVec3(c["up"], "camera.up", source) : glm::vec3(0, 1, 0);
        cam.fovYDegrees = c.value("fov", 60.0f);
        cam.nearPlane = c.value("near", 0.1f);
        cam.farPlane = c.value("far", 200.0f);
        if (!(cam.fovYDegrees > 0 && cam.fovYDegrees < 179 && cam.nearPlane > 0 && cam.farPlane > cam.nearPlane))
            throw FileError(source, "camera has an invalid fov or near/far range");
        p.camera = cam;
    }
    for (auto it = j["knobs"].begin(); it != j["knobs"].end(); ++it) p.knobs.emplace_back(it.key(), valueText(it.value()));
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
