#include "renderer/knobs/Preset.h"

#include <unistd.h>

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

json vec3(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

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
            // A number only when it reads back as one (not "1e400", not beyond a float).
            if (end && *end == '\0' && !v.empty() && floatProblem(d).empty()) k[n] = d;
            else k[n] = v;
        }
    }
    j["knobs"] = k;
    return j.dump(2) + "\n";
}

Preset Preset::fromJson(const std::string& text, const std::string& source) {
    // Depth and numbers beyond a float, by JSON path, before parsing.
    checkJsonText(text, source);
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        throw FileError(source, textPosition(text, e.byte) + ": not a valid preset (malformed JSON)");
    } catch (const json::exception& e) {
        throw FileError(source, "not a readable preset: " + jsonErrorText(e));
    }
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
