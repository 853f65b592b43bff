#include "renderer/scene/SceneJsonLoader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "renderer/Error.h"
#include "renderer/io/FloatCheck.h"
#include "renderer/io/ImageIO.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"
#include "renderer/scene/CameraCheck.h"
#include "renderer/scene/GltfLoader.h"
#include "renderer/scene/SceneCheck.h"
#include "renderer/scene/ShapeBuilder.h"

namespace dw {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;  // keeps the file's key order (settings apply in order)

namespace {

const char* typeName(const json& j) {
    switch (j.type()) {
        case json::value_t::null: return "null";
        case json::value_t::object: return "object";
        case json::value_t::array: return "array";
        case json::value_t::string: return "string";
        case json::value_t::boolean: return "boolean";
        case json::value_t::number_integer:
        case json::value_t::number_unsigned:
        case json::value_t::number_float: return "number";
        default: return "value";
    }
}

// Reads typed fields from a JSON object and reports problems by path.
class Reader {
public:
    Reader(const std::string& file, Scene& scene) : file_(file), scene_(scene) {}

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw FileError(file_, (where.empty() ? "" : where + ": ") + what);
    }

    void requireObject(const json& j, const std::string& where) const {
        if (!j.is_object()) fail(where, std::string("expected an object, got ") + typeName(j));
    }

    // Warns about keys the format does not define (typos would otherwise be silent).
    void checkKeys(const json& j, const std::string& where, std::initializer_list<const char*> known) {
        for (auto it = j.begin(); it != j.end(); ++it) {
            bool ok = false;
            for (const char* k : known) ok = ok || it.key() == k;
            if (!ok) scene_.warnings.push_back(file_ + ": " + where + (where.empty() ? "" : ".") + it.key() + ": unknown key ignored");
        }
    }

    float number(const json& j, const std::string& where) const {
        if (!j.is_number()) fail(where, std::string("expected a number, got ") + typeName(j));
        const double v = j.get<double>();
        if (const std::string problem = floatProblem(v); !problem.empty()) fail(where, problem);
        // A number that is not 0 but becomes 0 as a float would be read as 0
        // and refused (or used) as if the file said 0.
        if (v != 0.0 && static_cast<float>(v) == 0.0f)
            fail(where, shortNumber(v) + " is too small for a 32-bit float: it would be 0 (smallest about 1.4e-45)");
        return static_cast<float>(v);
    }
    float number(const json& obj, const char* key, const std::string& where, float fallback) const {
        return obj.contains(key) ? number(obj[key], join(where, key)) : fallback;
    }
    float positive(const json& obj, const char* key, const std::string& where, float fallback) const {
        const float v = number(obj, key, where, fallback);
        if (!(v > 0.0f)) fail(join(where, key), "must be greater than 0, got " + std::to_string(v));
        return v;
    }
    glm::vec3 vec3(const json& j, const std::string& where) const {
        if (j.is_number()) {
            const float v = number(j, where);
            return glm::vec3(v);
        }
        if (!j.is_array() || j.size() != 3) fail(where, std::string("expected an array of 3 numbers, got ") + describe(j));
        return {number(j[0], where + "[0]"), number(j[1], where + "[1]"), number(j[2], where + "[2]")};
    }
    glm::vec3 vec3(const json& obj, const char* key, const std::string& where, glm::vec3 fallback) const {
        return obj.contains(key) ? vec3(obj[key], join(where, key)) : fallback;
    }
    std::string string(const json& obj, const char* key, const std::string& where, const std::string& fallback) const {
        if (!obj.contains(key)) return fallback;
        if (!obj[key].is_string()) fail(join(where, key), std::string("expected a string, got ") + typeName(obj[key]));
        return obj[key].get<std::string>();
    }
    bool boolean(const json& obj, const char* key, const std::string& where, bool fallback) const {
        if (!obj.contains(key)) return fallback;
        if (!obj[key].is_boolean()) fail(join(where, key), std::string("expected true or false, got ") + typeName(obj[key]));
        return obj[key].get<bool>();
    }
    static std::string join(const std::string& where, const std::string& key) {
        return where.empty() ? key : where + "." + key;
    }
    static std::string describe(const json& j) {
        if (j.is_array()) return "an array of " + std::to_string(j.size());
        return std::string("a ") + typeName(j);
    }
    fs::path resolve(const std::string& rel) const {
        const fs::path p(rel);
        return p.is_absolute() ? p : fs::path(file_).parent_path() / p;
    }

    const std::string& file() const { return file_; }
    Scene& scene() { return scene_; }

private:
    std::string file_;
    Scene& scene_;
};

class SceneJsonParser {
public:
    SceneJsonParser(const std::string& path, Scene& scene) : r_(path, scene), scene_(scene) {}

    void parse(const json& root) {
        r_.requireObject(root, "");
        r_.checkKeys(root, "", {"name", "camera", "ambient", "background", "sky", "lighting", "lights", "materials", "objects", "description", "settings"});
        scene_.name = r_.string(root, "name", "", fs::path(r_.file()).stem().string());
        scene_.ambient = r_.vec3(root, "ambient", "", glm::vec3(0.05f));
        scene_.background = r_.vec3(root, "background", "", glm::vec3(0.0f));
        if (root.contains("lighting")) parseLighting(root["lighting"]);
        if (root.contains("lights")) parseLights(root["lights"], "lights");
        if (root.contains("materials")) parseMaterials(root["materials"]);
        if (root.contains("objects")) {
            const json& objs = root["objects"];
            if (!objs.is_array()) r_.fail("objects", std::string("expected an array, got ") + typeName(objs));
            for (size_t i = 0; i < objs.size(); ++i) parseObject(objs[i], "objects[" + std::to_string(i) + "]");
        }
        if (root.contains("settings")) parseSettings(root["settings"]);
        if (root.contains("sky")) parseSky(root["sky"]);
        if (root.contains("camera")) {
            parseCamera(root["camera"]);
        } else {
            scene_.camera = Camera::framing(scene_.bounds());
        }
    }

private:
    // The diagonal of what the scene holds so far (objects come before the camera).
    float sceneExtent() const {
        const Bounds b = scene_.bounds();
        return b.empty() ? 0.0f : 2.0f * b.radius();
    }

    static FloatImage greyToRgb(const FloatImage& grey) {
        FloatImage rgb;
        rgb.width = grey.width;
        rgb.height = grey.height;
        rgb.channels = 3;
        rgb.pixels.resize(static_cast<size_t>(grey.width) * grey.height * 3);
        for (size_t p = 0; p < static_cast<size_t>(grey.width) * grey.height; ++p)
            for (int c = 0; c < 3; ++c) rgb.pixels[p * 3 + c] = grey.pixels[p * grey.channels];
        return rgb;
    }

    void parseSky(const json& j) {
        r_.requireObject(j, "sky");
        r_.checkKeys(j, "sky", {"type", "zenith", "horizon", "ground", "sun-size", "file", "files", "intensity", "rotation"});
        Sky& sky = scene_.sky;
        const std::string type = r_.string(j, "type", "sky", "procedural");
        sky.intensity = r_.number(j, "intensity", "sky", 1.0f);
        if (sky.intensity < 0.0f) r_.fail("sky.intensity", "must not be negative");
        sky.rotationDegrees = r_.number(j, "rotation", "sky", 0.0f);
        auto image = [&](const std::string& rel, const std::string& where) {
            const std::string full = r_.resolve(rel).string();
            if (!fs::exists(full)) r_.fail(where, "environment image '" + rel + "' not found (looked for " + full + ")");
            FloatImage img;
            try {
                img = loadImageFloat(full);
            } catch (const FileError& e) {
                // e.what() names the image file; the scene file and field come first.
                r_.fail(where, std::string("cannot load environment image: ") + e.what());
            }
            if (img.channels < 3) img = greyToRgb(img);  // 1 channel (grey) or 2 (grey, alpha)
            // Sanitised at load (issue 10): the sky is a half-float texture,
            // so NaN, infinities and values past 65504 would reach every
            // buffer that samples it. NaN and negative values become 0,
            // larger ones 65504; the warning says how many.
            long long fixedValues = 0;
            for (float& v : img.pixels) {
                const float clean = std::isnan(v) || v < 0.0f ? 0.0f : std::min(v, 65504.0f);
                if (clean != v) ++fixedValues;
                v = clean;
            }
            if (fixedValues > 0)
                scene_.warnings.push_back(where + ": environment image '" + rel + "': " + std::to_string(fixedValues) +
                                          " values were NaN, negative or beyond half float's 65504; set to 0 or 65504");
            return img;
        };
        if (type == "color") {
            sky.kind = Sky::Kind::Color;
        } else if (type == "procedural") {
            sky.kind = Sky::Kind::Procedural;
            sky.zenith = r_.vec3(j, "zenith", "sky", sky.zenith);
            sky.horizon = r_.vec3(j, "horizon", "sky", sky.horizon);
            sky.ground = r_.vec3(j, "ground", "sky", sky.ground);
            sky.sunSizeDegrees = r_.number(j, "sun-size", "sky", sky.sunSizeDegrees);
        } else if (type == "environment") {
            sky.kind = Sky::Kind::Environment;
            const std::string rel = r_.string(j, "file", "sky", "");
            if (rel.empty()) r_.fail("sky", "an environment sky needs \"file\" (an equirectangular image)");
            sky.equirect = image(rel, "sky.file");
            sky.environmentSource = r_.resolve(rel).string();
        } else if (type == "cubemap") {
            sky.kind = Sky::Kind::Environment;
            if (!j.contains("files") || !j["files"].is_array() || j["files"].size() != 6)
                r_.fail("sky.files", "a cube map needs 6 image files (+X -X +Y -Y +Z -Z)");
            for (size_t i = 0; i < 6; ++i) {
                const std::string where = "sky.files[" + std::to_string(i) + "]";
                if (!j["files"][i].is_string()) r_.fail(where, "expected a file name");
                sky.cubeFaces.push_back(image(j["files"][i].get<std::string>(), where));
                const FloatImage& f = sky.cubeFaces.back();
                if (f.width != f.height || f.width != sky.cubeFaces[0].width)
                    r_.fail(where, "cube faces must be square and all the same size");
            }
            sky.environmentSource = r_.resolve(j["files"][0].get<std::string>()).string();
        } else {
            r_.fail("sky.type", "expected \"color\", \"procedural\", \"environment\" or \"cubemap\", got \"" + type + "\"");
        }
    }

    // Knob values are checked against the registry when the scene is applied.
    void parseSettings(const json& j) {
        r_.requireObject(j, "settings");
        for (auto it = j.begin(); it != j.end(); ++it) {
            const json& v = it.value();
            std::string text;
            if (v.is_string()) text = v.get<std::string>();
            else if (v.is_boolean()) text = v.get<bool>() ? "true" : "false";
            else if (v.is_number()) text = v.dump();
            else r_.fail("settings." + it.key(), std::string("expected a number, string or boolean, got ") + typeName(v));
            scene_.settings.emplace_back(it.key(), text);
        }
    }

    void parseCamera(const json& j) {
        r_.requireObject(j, "camera");
        r_.checkKeys(j, "camera", {"pos", "look-at", "up", "fov", "near", "far", "size", "path"});
        Camera c = Camera::framing(scene_.bounds());
        c.position = r_.vec3(j, "pos", "camera", c.position);
        c.target = r_.vec3(j, "look-at", "camera", c.target);
        c.up = r_.vec3(j, "up", "camera", glm::vec3(0, 1, 0));
        // Without an "up", a camera looking straight up or down gets -Z as its
        // up (docs/scene-format.md); an "up" the file gives is checked as given.
        if (!j.contains("up") && !upIsUsable(c)) c.up = glm::vec3(0, 0, -1);
        c.fovYDegrees = r_.positive(j, "fov", "camera", 60.0f);
        if (c.fovYDegrees >= 179.0f) r_.fail("camera.fov", "must be less than 179 degrees");
        c.fitClipPlanes(scene_.bounds());
        // A plane the file sets wins; the other one is fitted so that the
        // pair stays ordered. Only two planes the file sets can conflict.
        const bool hasNear = j.contains("near"), hasFar = j.contains("far");
        c.nearPlane = r_.positive(j, "near", "camera", c.nearPlane);
        c.farPlane = r_.positive(j, "far", "camera", c.farPlane);
        if (hasFar && !hasNear) c.nearPlane = std::min(c.nearPlane, c.farPlane * 1e-3f);
        if (hasNear && !hasFar) c.farPlane = std::max(c.farPlane, c.nearPlane * 10.0f);
        if (c.farPlane <= c.nearPlane) r_.fail("camera.far", "must be greater than camera.near");
        if (const auto problem = findCameraProblem(c, sceneExtent())) r_.fail("camera." + problem->field, problem->what);
        scene_.camera = c;
        if (j.contains("path")) parseCameraPath(j["path"]);
    }

    // Between two keyframes pos and look-at move linearly: the camera must not
    // reach its look-at point, nor look along camera.up, on the way (both
    // ends can be fine while the middle is not: pos going from one side of
    // a fixed look-at to the other passes through it).
    void checkPathSegment(const CameraKeyframe& a, const CameraKeyframe& b, const std::string& where) {
        const glm::dvec3 v0 = glm::dvec3(a.target) - glm::dvec3(a.position);
        const glm::dvec3 dv = glm::dvec3(b.target) - glm::dvec3(b.position) - v0;
        const glm::dvec3 up(scene_.camera.up);
        const double scale = std::max({static_cast<double>(sceneExtent()), glm::length(glm::dvec3(a.position)),
                                       glm::length(glm::dvec3(a.target)), glm::length(glm::dvec3(b.position)),
                                       glm::length(glm::dvec3(b.target))});
        // The view vector v(t) = v0 + t dv is nearest zero at tView; its cross
        // product with up, linear in t too, is nearest zero at tUp.
        auto nearestZero = [](const glm::dvec3& p, const glm::dvec3& d) {
            const double dd = glm::dot(d, d);
            return dd > 0.0 ? std::clamp(-glm::dot(p, d) / dd, 0.0, 1.0) : 0.0;
        };
        const double tView = nearestZero(v0, dv), tUp = nearestZero(glm::cross(v0, up), glm::cross(dv, up));
        auto timeAt = [&](double t) { return shortNumber(static_cast<float>(a.time + t * (b.time - a.time))); };
        if (!(glm::length(v0 + tView * dv) > static_cast<double>(kMinViewDistance) * scale))
            r_.fail(where, "on the way from the keyframe before it, the camera reaches its look-at point (at time " +
                               timeAt(tView) + "), where it has no view direction");
        for (const double t : {tView, tUp}) {
            Camera c;
            c.position = glm::vec3(glm::dvec3(a.position) + t * (glm::dvec3(b.position) - glm::dvec3(a.position)));
            c.target = glm::vec3(glm::dvec3(a.target) + t * (glm::dvec3(b.target) - glm::dvec3(a.target)));
            c.up = scene_.camera.up;
            if (!upIsUsable(c))
                r_.fail(where, "on the way from the keyframe before it, the camera looks along camera.up (at time " +
                                   timeAt(t) + "); the view needs another direction");
        }
    }

    // A walk-through for `bench --walkthrough`: [{"time", "pos", "look-at"}, ...].
    void parseCameraPath(const json& j) {
        if (!j.is_array()) r_.fail("camera.path", std::string("expected an array of keyframes, got ") + typeName(j));
        if (j.size() < 2) r_.fail("camera.path", "needs at least two keyframes, got " + std::to_string(j.size()));
        for (size_t i = 0; i < j.size(); ++i) {
            const std::string where = "camera.path[" + std::to_string(i) + "]";
            r_.requireObject(j[i], where);
            r_.checkKeys(j[i], where, {"time", "pos", "look-at"});
            for (const char* key : {"time", "pos", "look-at"})
                if (!j[i].contains(key)) r_.fail(where, std::string("a keyframe needs \"") + key + "\"");
            CameraKeyframe k;
            k.time = r_.number(j[i]["time"], where + ".time");
            k.position = r_.vec3(j[i]["pos"], where + ".pos");
            k.target = r_.vec3(j[i]["look-at"], where + ".look-at");
            if (!scene_.cameraPath.empty() && !(k.time > scene_.cameraPath.back().time))
                r_.fail(where + ".time", "must be greater than the keyframe before it (" +
                                             std::to_string(scene_.cameraPath.back().time) + ")");
            Camera at;
            at.position = k.position;
            at.target = k.target;
            if (const auto problem = findCameraProblem(at, sceneExtent()); problem && problem->field == "look-at")
                r_.fail(where + ".look-at", problem->what);
            at.up = scene_.camera.up;
            if (!upIsUsable(at)) r_.fail(where + ".look-at", "looks along camera.up; the view needs another direction");
            if (!scene_.cameraPath.empty()) checkPathSegment(scene_.cameraPath.back(), k, where);
            scene_.cameraPath.push_back(k);
        }
    }

    // The CMSC 23700 layout: {"ambient", "direction", "intensity", "lights": [...]}.
    void parseLighting(const json& j) {
        r_.requireObject(j, "lighting");
        r_.checkKeys(j, "lighting", {"ambient", "direction", "intensity", "shadow", "lights"});
        scene_.ambient = r_.vec3(j, "ambient", "lighting", scene_.ambient);
        if (j.contains("direction")) {
            Light sun;
            sun.name = "directional";
            sun.type = LightType::Directional;
            sun.direction = normalized(r_.vec3(j["direction"], "lighting.direction"), "lighting.direction");
            sun.intensity = r_.vec3(j, "intensity", "lighting", glm::vec3(1.0f));
            sun.castShadows = r_.boolean(j, "shadow", "lighting", false);
            scene_.lights.push_back(sun);
        }
        if (j.contains("lights")) parseLights(j["lights"], "lighting.lights");
    }

    glm::vec3 normalized(const glm::vec3& v, const std::string& where) const {
        const float len = glm::length(v);
        if (len < 1e-8f) r_.fail(where, "direction must not be zero");
        return v / len;
    }

    void parseLights(const json& arr, const std::string& where) {
        if (!arr.is_array()) r_.fail(where, std::string("expected an array, got ") + typeName(arr));
        for (size_t i = 0; i < arr.size(); ++i) {
            const std::string w = where + "[" + std::to_string(i) + "]";
            const json& j = arr[i];
            r_.requireObject(j, w);
            r_.checkKeys(j, w, {"name", "type", "pos", "direction", "cutoff", "exponent", "intensity", "attenuation", "shadow", "enabled"});
            Light l;
            l.name = r_.string(j, "name", w, "light" + std::to_string(scene_.lights.size()));
            const std::string type = r_.string(j, "type", w, j.contains("cutoff") ? "spot" : "point");
            if (type == "spot") l.type = LightType::Spot;
            else if (type == "point") l.type = LightType::Point;
            else if (type == "directional") l.type = LightType::Directional;
            else r_.fail(w + ".type", "expected \"point\", \"spot\" or \"directional\", got \"" + type + "\"");
            if (l.type != LightType::Directional) {
                if (!j.contains("pos")) r_.fail(w, "a " + type + " light needs \"pos\"");
                l.position = r_.vec3(j["pos"], w + ".pos");
            }
            if (l.type != LightType::Point) {
                if (!j.contains("direction")) r_.fail(w, "a " + type + " light needs \"direction\"");
                l.direction = normalized(r_.vec3(j["direction"], w + ".direction"), w + ".direction");
            }
            if (l.type == LightType::Spot) {
                l.cutoffDegrees = r_.number(j, "cutoff", w, 45.0f);
                if (!(l.cutoffDegrees > 0.0f && l.cutoffDegrees <= 90.0f))
                    r_.fail(w + ".cutoff", "must be in (0, 90] degrees, got " + std::to_string(l.cutoffDegrees));
                l.exponent = r_.number(j, "exponent", w, 0.0f);
                if (l.exponent < 0.0f) r_.fail(w + ".exponent", "must not be negative");
            }
            l.intensity = r_.vec3(j, "intensity", w, glm::vec3(1.0f));
            if (glm::any(glm::lessThan(l.intensity, glm::vec3(0.0f)))) r_.fail(w + ".intensity", "must not be negative");
            if (j.contains("attenuation")) {
                const json& a = j["attenuation"];
                const std::string aw = w + ".attenuation";
                r_.requireObject(a, aw);
                r_.checkKeys(a, aw, {"constant", "linear", "quadratic"});
                l.attenuation.constant = r_.number(a, "constant", aw, 1.0f);
                l.attenuation.linear = r_.number(a, "linear", aw, 0.0f);
                l.attenuation.quadratic = r_.number(a, "quadratic", aw, 0.0f);
                const Attenuation& at = l.attenuation;
                if (at.constant < 0 || at.linear < 0 || at.quadratic < 0)
                    r_.fail(aw, "constant, linear and quadratic must not be negative");
                if (at.constant == 0 && at.linear == 0 && at.quadratic == 0)
                    r_.fail(aw, "constant, linear and quadratic are all 0 (infinite intensity)");
            }
            l.castShadows = r_.boolean(j, "shadow", w, false);
            l.enabled = r_.boolean(j, "enabled", w, true);
            scene_.lights.push_back(l);
        }
    }

    void parseMaterials(const json& j) {
        r_.requireObject(j, "materials");
        for (auto it = j.begin(); it != j.end(); ++it) named_[it.key()] = parseMaterial(it.value(), "materials." + it.key(), it.key());
    }

    int texture(const json& m, const char* key, const std::string& where) {
        if (!m.contains(key)) return -1;
        const std::string rel = r_.string(m, key, where, "");
        const std::string full = r_.resolve(rel).string();
        auto cached = images_.find(full);
        if (cached != images_.end()) return cached->second;
        if (!fs::exists(full)) r_.fail(Reader::join(where, key), "missing texture '" + rel + "' (looked for " + full + ")");
        Image img;
        try {
            img = loadImage8(full);
        } catch (const FileError& e) {
            r_.fail(Reader::join(where, key), std::string("cannot load texture: ") + e.what());
        }
        const int idx = scene_.addImage(std::move(img));
        images_[full] = idx;
        return idx;
    }

    int parseMaterial(const json& j, const std::string& where, const std::string& name) {
        r_.requireObject(j, where);
        r_.checkKeys(j, where, {"diffuse", "specular", "shininess", "emissive", "opacity", "diffuse-map", "normal-map", "specular-map", "emissive-map", "double-sided"});
        Material m;
        m.name = name;
        m.model = MaterialModel::BlinnPhong;
        const float opacity = r_.number(j, "opacity", where, 1.0f);
        if (!(opacity >= 0.0f && opacity <= 1.0f))
            r_.fail(r_.join(where, "opacity"), "must be between 0 (invisible) and 1 (opaque), got " + std::to_string(opacity));
        m.baseColor = glm::vec4(r_.vec3(j, "diffuse", where, glm::vec3(0.8f)), opacity);
        m.specularColor = r_.vec3(j, "specular", where, glm::vec3(0.04f));
        m.specularExponent = r_.positive(j, "shininess", where, 32.0f);
        m.emissive = r_.vec3(j, "emissive", where, glm::vec3(0.0f));
        m.baseColorTexture = texture(j, "diffuse-map", where);
        m.normalTexture = texture(j, "normal-map", where);
        m.specularTexture = texture(j, "specular-map", where);
        m.emissiveTexture = texture(j, "emissive-map", where);
        m.doubleSided = r_.boolean(j, "double-sided", where, false);
        if (m.baseColor.a < 1.0f) m.alphaMode = AlphaMode::Blend;
        return scene_.addMaterial(std::move(m));
    }

    glm::mat4 transform(const json& j, const std::string& where) const {
        glm::mat4 t = glm::translate(glm::mat4(1.0f), r_.vec3(j, "pos", where, glm::vec3(0.0f)));
        const glm::vec3 rot = r_.vec3(j, "rotate", where, glm::vec3(0.0f));  // degrees, applied Y, X, Z
        t = glm::rotate(t, glm::radians(rot.y), glm::vec3(0, 1, 0));
        t = glm::rotate(t, glm::radians(rot.x), glm::vec3(1, 0, 0));
        t = glm::rotate(t, glm::radians(rot.z), glm::vec3(0, 0, 1));
        const glm::vec3 s = r_.vec3(j, "scale", where, glm::vec3(1.0f));
        if (glm::any(glm::equal(s, glm::vec3(0.0f)))) r_.fail(where + ".scale", "must not be 0");
        t = glm::scale(t, s);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(t[c][r]))
                    r_.fail(where, "pos, rotate and scale give a transform that does not fit 32-bit floats");
        return t;
    }

    void parseObject(const json& j, const std::string& where) {
        r_.requireObject(j, where);
        r_.checkKeys(j, where, {"name", "gltf", "shape", "material", "pos", "rotate", "scale", "size", "radius", "height", "uv-scale"});
        const glm::mat4 xf = transform(j, where);
        if (j.contains("gltf")) {
            const std::string rel = r_.string(j, "gltf", where, "");
            const std::string full = r_.resolve(rel).string();
            if (!fs::exists(full)) r_.fail(where + ".gltf", "glTF file '" + rel + "' not found (looked for " + full + ")");
            importGltf(full, scene_, xf, false);
            return;
        }
        if (!j.contains("shape")) r_.fail(where, "an object needs \"gltf\" or \"shape\"");
        const std::string shape = r_.string(j, "shape", where, "");
        const float uvScale = r_.number(j, "uv-scale", where, 1.0f);
        Mesh mesh;
        // A side of 0 has no face normal (the faces are built from cross products).
        auto sides = [&](glm::vec2 used, const glm::vec3& s) {
            if (!(used.x > 0.0f && used.y > 0.0f) || (shape == "box" && !(s.z > 0.0f)))
                r_.fail(where + ".size", "every side must be greater than 0, got [" + shortNumber(s.x) + ", " +
                                             shortNumber(s.y) + ", " + shortNumber(s.z) + "]");
        };
        if (shape == "box") {
            const glm::vec3 s = r_.vec3(j, "size", where, glm::vec3(1.0f));
            sides(glm::vec2(s.x, s.y), s);
            mesh = shapes::box(s, uvScale);
        } else if (shape == "plane") {
            const glm::vec3 s = r_.vec3(j, "size", where, glm::vec3(10.0f));
            sides(glm::vec2(s.x, s.z == 0 ? s.y : s.z), s);
            mesh = shapes::plane(s.x, s.z == 0 ? s.y : s.z, uvScale);
        } else if (shape == "sphere") mesh = shapes::sphere(r_.positive(j, "radius", where, 0.5f));
        else if (shape == "cylinder") mesh = shapes::cylinder(r_.positive(j, "radius", where, 0.5f), r_.positive(j, "height", where, 1.0f));
        else if (shape == "cone") mesh = shapes::cone(r_.positive(j, "radius", where, 0.5f), r_.positive(j, "height", where, 1.0f));
        else r_.fail(where + ".shape", "unknown shape \"" + shape + "\" (box, plane, sphere, cylinder, cone)");
        mesh.name = r_.string(j, "name", where, shape);
        mesh.material = material(j, where);
        const int idx = scene_.addMesh(std::move(mesh));
        scene_.instances.push_back({idx, xf});
    }

    int material(const json& j, const std::string& where) {
        if (!j.contains("material")) {
            if (defaultMaterial_ < 0) {
                Material m;
                m.name = "default";
                defaultMaterial_ = scene_.addMaterial(m);
            }
            return defaultMaterial_;
        }
        const json& m = j["material"];
        if (m.is_string()) {
            auto it = named_.find(m.get<std::string>());
            if (it == named_.end()) r_.fail(where + ".material", "no material named \"" + m.get<std::string>() + "\" in \"materials\"");
            return it->second;
        }
        return parseMaterial(m, where + ".material", where);
    }

    Reader r_;
    Scene& scene_;
    std::map<std::string, int> named_;
    std::map<std::string, int> images_;
    int defaultMaterial_ = -1;
};

}  // namespace

Scene parseSceneJson(const std::string& text, const std::string& path) {
    // Depth, and numbers beyond a double or a float, by JSON path before parsing.
    const json root = parseOrderedJson(text, path);
    Scene scene;
    scene.source = path;
    SceneJsonParser parser(path, scene);
    parser.parse(root);
    checkSceneValues(scene);  // what the fields combine into (extent, transforms, framed camera)
    warnClampedEmission(scene);
    return scene;
}

Scene loadSceneJson(const std::string& path) {
    return parseSceneJson(readWholeFile(path, "scene file not found", "cannot read scene file"), path);
}

}  // namespace dw
