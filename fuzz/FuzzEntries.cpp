#include "fuzz/FuzzEntries.h"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <string>

#include "renderer/Error.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/knobs/Preset.h"
#include "renderer/scene/CameraCheck.h"
#include "renderer/scene/SceneLoader.h"
#include "renderer/scene/SceneJsonLoader.h"

namespace dw::fuzz {

namespace {

namespace fs = std::filesystem;

// A folder of this process's own: the glTF input is written there, and a scene's
// relative file names resolve there (where nothing else lies).
const fs::path& workDir() {
    static const fs::path dir = [] {
        fs::path d = fs::temp_directory_path() / ("dw-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

// A finding the sanitizers cannot see: an accepted input that holds a value
// which is not finite. abort() so that libFuzzer keeps the input.
void require(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "fuzz: accepted input has a non-finite %s\n", what);
        std::abort();
    }
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        if (!finite(glm::vec3(m[c])) || !std::isfinite(m[c][3])) return false;
    return true;
}

// A plain loop, not std::string::find: libFuzzer learns the strings given to
// memcmp/strstr and would write them into inputs (a key named "unknown error").
bool contains(const std::string& text, const char* part) {
    const std::size_t n = std::strlen(part);
    for (std::size_t i = 0; i + n <= text.size(); ++i) {
        std::size_t k = 0;
        while (k < n && text[i + k] == part[k]) ++k;
        if (k == n) return true;
    }
    return false;
}

// What a refusal must look like: "<file>: <what>", in the format's words: not
// a JSON library's exception text, not tinygltf's "File not found : data:..."
// for a data: URI, never "unknown error", never a glTF refusal without a reason.
std::string checkMessage(const Error& e, const std::string& file) {
    const std::string m = e.what();
    const bool endsUnknown = m.size() >= 13 && m.compare(m.size() - 13, 13, "unknown error") == 0;
    for (const char* banned : {"[json.exception.", "File not found : data:", "without giving a reason"})
        if (contains(m, banned) || endsUnknown) {
            std::fprintf(stderr, "fuzz: unclear message: %s\n", m.c_str());
            std::abort();
        }
    if (m.rfind(file + ": ", 0) != 0) {
        std::fprintf(stderr, "fuzz: message does not start with the file name %s: %s\n", file.c_str(), m.c_str());
        std::abort();
    }
    return m;
}

void checkSceneFinite(const Scene& s) {
    require(finite(s.camera.view()), "view matrix");
    require(finite(s.camera.projection(16.0f / 9.0f)), "projection matrix");
    for (const auto& i : s.instances) require(finite(i.transform), "instance transform");
    for (const auto& m : s.meshes)
        for (const auto& v : m.vertices)
            require(finite(v.position) && finite(v.normal) && std::isfinite(v.uv.x) && std::isfinite(v.uv.y) &&
                        finite(glm::vec3(v.tangent)),
                    "vertex");
    for (const auto& l : s.lights)
        require(finite(l.position) && finite(l.direction) && finite(l.intensity) && std::isfinite(l.exponent) &&
                    std::isfinite(l.cutoffDegrees),
                "light");
    for (const auto& m : s.materials)
        require(finite(glm::vec3(m.baseColor)) && finite(m.emissive) && finite(m.specularColor), "material");
}

}  // namespace

std::string sceneJson(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const std::string file = (workDir() / "fuzz.json").string();
    try {
        checkSceneFinite(parseSceneJson(text, file));
    } catch (const FileError& e) {
        // A file the scene refers to (a glTF, a texture) may be the one named.
        return e.path() == file ? checkMessage(e, file) : std::string(e.what());
    }
    return {};
}

std::string preset(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    KnobRegistry knobs;
    knobs.addBool("a.flag", false, "a", "a bool");
    knobs.addInt("a.count", 4, 1, 64, "a", "an int");
    knobs.addFloat("a.scale", 1.0, 0.0, 1e6, "a", "a float", {}, false, true);
    knobs.addEnum("a.mode", {"one", "two"}, 0, "a", "an enum");
    try {
        const Preset p = Preset::fromJson(text, "fuzz-preset.json");
        p.applyKnobs(knobs);
        if (p.camera) {
            require(finite(p.camera->view()), "preset view matrix");
            require(finite(p.camera->projection(1.0f)), "preset projection matrix");
        }
        Preset::fromJson(p.toJson(), "fuzz-preset-resaved.json");  // what it saves, it reads back
    } catch (const FileError& e) {
        return checkMessage(e, "fuzz-preset.json");
    }
    return {};
}

std::string gltf(const std::uint8_t* data, std::size_t size) {
    const bool glb = size >= 4 && std::string(reinterpret_cast<const char*>(data), 4) == "glTF";
    const fs::path file = workDir() / (glb ? "fuzz.glb" : "fuzz.gltf");
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    try {
        // As `--scene file.gltf` loads it: framed camera and default lights included.
        checkSceneFinite(loadScene(file.string()));
    } catch (const FileError& e) {
        return e.path() == file.string() ? checkMessage(e, file.string()) : std::string(e.what());
    }
    return {};
}

}  // namespace dw::fuzz
