#include "renderer/knobs/Preset.h"

#include <unistd.h>

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

json vec3(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

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
    if (camera) {
        j["camera"] = {{"pos", vec3(camera->position)}, {"look-at", vec3(camera->target)}, {"up", vec3(camera->up)},
                       {"fov", camera->fovYDegrees}, {"near", camera->nearPlane}, {"far", camera->farPlane}};
    }
    json k = json::object();
    for (const auto& [n, v] : knobs) {
        // Numbers and booleans as JSON values, enum choices as strings.
        if (v == "true" || v == "false") k[n] = v == "true";
        else {
            char* end = nullptr;
            const double d = std::strtod(v.c_str(), &end);
            if (end && *end == '\0' && !v.empty()) k[n] = d;
            else k[n] = v;
        }
    }
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

void Preset::save(const std::string& path) const {
    const fs::path target(path);
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (!fs::is_directory(dir)) throw FileError(path, "cannot save: folder " + dir.string() + " does not exist");
    if (fs::is_directory(target)) throw FileError(path, "cannot save: a folder has that name");
    const std::string text = toJson();
    const fs::path tmp = dir / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()));
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw FileError(path, "cannot save: cannot write in " + dir.string());
        out << text;
        out.flush();
        if (!out) {
            std::error_code ec;
            fs::remove(tmp, ec);
            throw FileError(path, "cannot save: writing failed (disk full?)");
        }
    }
    if (FILE* f = std::fopen(tmp.c_str(), "rb")) {
        ::fsync(fileno(f));
        std::fclose(f);
    }
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw FileError(path, "cannot save: " + ec.message());
    }
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
