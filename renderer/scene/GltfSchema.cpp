#include "renderer/scene/GltfSchema.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <initializer_list>

namespace dw {

namespace {

using json = nlohmann::json;

constexpr long long kMaxIndex = INT_MAX;               // tinygltf stores indices as int
constexpr long long kMaxSize = (1ll << 53) - 1;        // the largest integer every JSON reader keeps exactly

// One integer property: its range, or its allowed values (an enum).
struct IntRule {
    long long min = 0, max = kMaxIndex;
    const char* kind = "an index";               // "an index from 0 to ..."
    std::vector<long long> values;               // an enum: only these
    const char* valueNames = nullptr;            // the enum's values in words
    bool readAnyway = false;                     // a value outside the enum is read past (the default is used)
};

const IntRule kIndex{};
const IntRule kTexCoord{0, kMaxIndex, "a texture coordinate set"};
const IntRule kOffset{0, kMaxSize, "a byte offset"};
const IntRule kLength{1, kMaxSize, "a byte length"};
const IntRule kCount{1, kMaxSize, "a count"};
const IntRule kSparseCount{1, kMaxIndex, "a count"};
const IntRule kSparseOffset{0, kMaxIndex, "a byte offset"};
const IntRule kStride{4, 252, "a byte stride (a multiple of 4)"};
const IntRule kComponentType{0, 0, "", {5120, 5121, 5122, 5123, 5125, 5126},
                             "5120 (BYTE), 5121 (UNSIGNED_BYTE), 5122 (SHORT), 5123 (UNSIGNED_SHORT), 5125 (UNSIGNED_INT), 5126 (FLOAT)"};
const IntRule kSparseIndexType{0, 0, "", {5121, 5123, 5125}, "5121 (UNSIGNED_BYTE), 5123 (UNSIGNED_SHORT), 5125 (UNSIGNED_INT)"};
const IntRule kMode{0, 6, "a primitive mode (0 POINTS to 6 TRIANGLE_FAN)"};
const IntRule kTarget{0, 0, "", {34962, 34963}, "34962 (ARRAY_BUFFER), 34963 (ELEMENT_ARRAY_BUFFER)", true};
const IntRule kMagFilter{0, 0, "", {9728, 9729}, "9728 (NEAREST), 9729 (LINEAR)", true};
const IntRule kMinFilter{0, 0, "", {9728, 9729, 9984, 9985, 9986, 9987}, "9728, 9729 or 9984 to 9987", true};
const IntRule kWrap{0, 0, "", {33071, 33648, 10497}, "33071 (CLAMP_TO_EDGE), 33648 (MIRRORED_REPEAT), 10497 (REPEAT)", true};

// "accessors[3].sparse.count" -> "accessors[].sparse.count".
std::string normalized(const std::string& path) {
    std::string out;
    out.reserve(path.size());
    for (std::size_t i = 0; i < path.size(); ++i) {
        out += path[i];
        if (path[i] != '[') continue;
        std::size_t j = i + 1;
        while (j < path.size() && path[j] >= '0' && path[j] <= '9') ++j;
        i = j - 1;
    }
    return out;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The rest of `path` after `prefix` when it is one plain key (no '.' or '[').
bool oneKeyAfter(const std::string& path, const std::string& prefix) {
    return startsWith(path, prefix) && path.size() > prefix.size() &&
           path.find_first_of(".[", prefix.size()) == std::string::npos;
}

const IntRule* ruleFor(const std::string& rawPath) {
    const std::string p = normalized(rawPath);
    if (p.find("extras") != std::string::npos) return nullptr;
    struct Entry {
        const char* path;
        const IntRule* rule;
    };
    static const Entry kRules[] = {
        {"scene", &kIndex},
        {"scenes[].nodes[]", &kIndex},
        {"accessors[].bufferView", &kIndex},
        {"accessors[].byteOffset", &kOffset},
        {"accessors[].componentType", &kComponentType},
        {"accessors[].count", &kCount},
        {"accessors[].sparse.count", &kSparseCount},
        {"accessors[].sparse.indices.bufferView", &kIndex},
        {"accessors[].sparse.indices.byteOffset", &kSparseOffset},
        {"accessors[].sparse.indices.componentType", &kSparseIndexType},
        {"accessors[].sparse.values.bufferView", &kIndex},
        {"accessors[].sparse.values.byteOffset", &kSparseOffset},
        {"animations[].channels[].sampler", &kIndex},
        {"animations[].channels[].target.node", &kIndex},
        {"animations[].samplers[].input", &kIndex},
        {"animations[].samplers[].output", &kIndex},
        {"buffers[].byteLength", &kLength},
        {"bufferViews[].buffer", &kIndex},
        {"bufferViews[].byteOffset", &kOffset},
        {"bufferViews[].byteLength", &kLength},
        {"bufferViews[].byteStride", &kStride},
        {"bufferViews[].target", &kTarget},
        {"images[].bufferView", &kIndex},
        {"meshes[].primitives[].indices", &kIndex},
        {"meshes[].primitives[].material", &kIndex},
        {"meshes[].primitives[].mode", &kMode},
        {"nodes[].camera", &kIndex},
        {"nodes[].children[]", &kIndex},
        {"nodes[].skin", &kIndex},
        {"nodes[].mesh", &kIndex},
        {"nodes[].extensions.KHR_lights_punctual.light", &kIndex},
        {"samplers[].magFilter", &kMagFilter},
        {"samplers[].minFilter", &kMinFilter},
        {"samplers[].wrapS", &kWrap},
        {"samplers[].wrapT", &kWrap},
        {"skins[].inverseBindMatrices", &kIndex},
        {"skins[].skeleton", &kIndex},
        {"skins[].joints[]", &kIndex},
        {"textures[].sampler", &kIndex},
        {"textures[].source", &kIndex},
        {"textures[].extensions.EXT_texture_webp.source", &kIndex},
    };
    for (const Entry& e : kRules)
        if (p == e.path) return e.rule;
    if (oneKeyAfter(p, "meshes[].primitives[].attributes.") || oneKeyAfter(p, "meshes[].primitives[].targets[].")) return &kIndex;
    // Texture references of materials (and of the material extensions the importer reads).
    static const char* kTextureInfos[] = {
        "materials[].pbrMetallicRoughness.baseColorTexture.", "materials[].pbrMetallicRoughness.metallicRoughnessTexture.",
        "materials[].normalTexture.", "materials[].occlusionTexture.", "materials[].emissiveTexture.",
        "materials[].extensions.KHR_materials_pbrSpecularGlossiness.diffuseTexture.",
        "materials[].extensions.KHR_materials_pbrSpecularGlossiness.specularGlossinessTexture."};
    for (const char* t : kTextureInfos) {
        if (!startsWith(p, t)) continue;
        const std::string rest = p.substr(std::string(t).size());
        if (rest == "index") return &kIndex;
        if (rest == "texCoord" || rest == "extensions.KHR_texture_transform.texCoord") return &kTexCoord;
    }
    return nullptr;
}

std::string integerText(long long v) { return std::to_string(v); }

// What is wrong with an integer property's value, empty when nothing; sets
// `readPast` when the importer reads past it.
std::string problemOf(const IntRule& rule, double value, const std::string& text, bool integral, bool& readPast) {
    readPast = false;
    if (!integral) return "expected an integer, got " + text;
    if (!rule.values.empty()) {
        const bool known = std::fabs(value) < 1e18 &&
                           std::find(rule.values.begin(), rule.values.end(), static_cast<long long>(value)) != rule.values.end();
        if (known) return {};
        readPast = rule.readAnyway;
        return text + " is not one of " + rule.valueNames;
    }
    if (value < static_cast<double>(rule.min) || value > static_cast<double>(rule.max)) {
        std::string range = std::string(rule.kind) + " from " + integerText(rule.min) + " to " + integerText(rule.max);
        return text + " is out of range (" + range + ")";
    }
    if (&rule == &kStride && static_cast<long long>(value) % 4 != 0) return text + " is not a multiple of 4";
    return {};
}

class SchemaChecker {
public:
    SchemaChecker(const json& root, std::vector<std::string>& problems, std::vector<std::string>& invalid)
        : root_(root), problems_(problems), invalid_(invalid) {}

    void run() {
        if (!root_.contains("asset") || !root_["asset"].is_object()) problem("top level", "required property 'asset' is missing");
        else if (!root_["asset"].contains("version") || !root_["asset"]["version"].is_string())
            problem("asset", "required property 'version' (a string) is missing");
        integers(root_, "");
        forEach("accessors", [&](const json& o, const std::string& w) { accessor(o, w); });
        forEach("animations", [&](const json& o, const std::string& w) { animation(o, w); });
        forEach("buffers", [&](const json& o, const std::string& w) { require(o, w, {"byteLength"}); });
        forEach("bufferViews", [&](const json& o, const std::string& w) { require(o, w, {"buffer", "byteLength"}); });
        forEach("cameras", [&](const json& o, const std::string& w) { camera(o, w); });
        forEach("images", [&](const json& o, const std::string& w) { image(o, w); });
        forEach("materials", [&](const json& o, const std::string& w) { material(o, w); });
        forEach("meshes", [&](const json& o, const std::string& w) { mesh(o, w); });
        forEach("nodes", [&](const json& o, const std::string& w) {
            indexArray(o, w, "children", false);
            if (o.contains("matrix") && (o.contains("translation") || o.contains("rotation") || o.contains("scale")))
                invalid_.push_back(w + ": has both 'matrix' and translation/rotation/scale (spec: one or the other); the matrix is used");
        });
        forEach("samplers", [](const json&, const std::string&) {});
        forEach("scenes", [&](const json& o, const std::string& w) { indexArray(o, w, "nodes", false); });
        forEach("skins", [&](const json& o, const std::string& w) {
            require(o, w, {"joints"});
            indexArray(o, w, "joints", true);
        });
        forEach("textures", [](const json&, const std::string&) {});
    }

private:
    void problem(const std::string& where, const std::string& what) { problems_.push_back(where + ": " + what); }

    // Every element of the top-level array `name` is an object; `check` sees each.
    template <typename F>
    void forEach(const char* name, F check) {
        if (!root_.contains(name)) return;
        const json& a = root_[name];
        if (!a.is_array()) return problem(name, "expected an array");
        for (std::size_t i = 0; i < a.size(); ++i) {
            const std::string where = std::string(name) + "[" + std::to_string(i) + "]";
            if (!a[i].is_object()) problem(where, "expected an object");
            else check(a[i], where);
        }
    }

    // Whether every key in `keys` is present; names each missing one.
    bool require(const json& o, const std::string& where, std::initializer_list<const char*> keys) {
        bool all = true;
        for (const char* k : keys)
            if (!o.contains(k)) {
                problem(where, std::string("required property '") + k + "' is missing");
                all = false;
            }
        return all;
    }

    // o[key] (when present, or when `required`) is an array of indices, not empty when required.
    void indexArray(const json& o, const std::string& where, const char* key, bool required) {
        if (!o.contains(key)) return;
        const json& a = o[key];
        if (!a.is_array()) return problem(where + "." + key, "expected an array of indices");
        if (required && a.empty()) problem(where + "." + key, "must not be empty (at least 1 index)");
    }

    // o[key], when present, is an object; returns it or nullptr.
    const json* object(const json& o, const std::string& where, const char* key) {
        if (!o.contains(key)) return nullptr;
        if (!o[key].is_object()) {
            problem(where + "." + key, "expected an object");
            return nullptr;
        }
        return &o[key];
    }

    void accessor(const json& o, const std::string& w) {
        require(o, w, {"componentType", "count", "type"});
        if (o.contains("type")) {
            static const char* kTypes[] = {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};
            const json& t = o["type"];
            if (!t.is_string() || std::none_of(std::begin(kTypes), std::end(kTypes), [&](const char* k) { return t == k; }))
                problem(w + ".type", "expected one of SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3, MAT4, got " + t.dump());
        }
        if (const json* s = object(o, w, "sparse")) {
            const std::string sw = w + ".sparse";
            require(*s, sw, {"count", "indices", "values"});
            if (const json* i = object(*s, sw, "indices")) require(*i, sw + ".indices", {"bufferView", "componentType"});
            if (const json* v = object(*s, sw, "values")) require(*v, sw + ".values", {"bufferView"});
        }
    }

    void animation(const json& o, const std::string& w) {
        require(o, w, {"channels", "samplers"});
        for (const char* key : {"channels", "samplers"}) {
            if (!o.contains(key)) continue;
            const json& a = o[key];
            const std::string aw = w + "." + key;
            if (!a.is_array()) {
                problem(aw, "expected an array");
                continue;
            }
            if (a.empty()) problem(aw, "must not be empty");
            for (std::size_t i = 0; i < a.size(); ++i) {
                const std::string ew = aw + "[" + std::to_string(i) + "]";
                if (!a[i].is_object()) {
                    problem(ew, "expected an object");
                } else if (std::string(key) == "samplers") {
                    require(a[i], ew, {"input", "output"});
                } else if (require(a[i], ew, {"sampler", "target"})) {
                    if (const json* t = object(a[i], ew, "target")) require(*t, ew + ".target", {"path"});
                }
            }
        }
    }

    void camera(const json& o, const std::string& w) {
        if (!require(o, w, {"type"})) return;
        const json& type = o["type"];
        if (type != "perspective" && type != "orthographic")
            return problem(w + ".type", "expected \"perspective\" or \"orthographic\", got " + type.dump());
        const std::string kind = type.get<std::string>();
        if (!o.contains(kind)) return problem(w, "required property '" + kind + "' is missing (type is " + kind + ")");
        const json* p = object(o, w, kind.c_str());
        if (!p) return;
        const std::string pw = w + "." + kind;
        if (kind == "perspective") require(*p, pw, {"yfov", "znear"});
        else require(*p, pw, {"xmag", "ymag", "zfar", "znear"});
    }

    void image(const json& o, const std::string& w) {
        const bool uri = o.contains("uri"), view = o.contains("bufferView");
        if (uri && view) problem(w, "has both 'uri' and 'bufferView' (exactly one is allowed)");
        if (!uri && !view) problem(w, "required property 'uri' or 'bufferView' is missing");
        if (view && !uri && !o.contains("mimeType"))
            invalid_.push_back(w + ": 'mimeType' is missing (required with 'bufferView'); the image's bytes tell its type");
    }

    void textureInfo(const json& o, const std::string& w, const char* key) {
        if (const json* t = object(o, w, key)) require(*t, w + "." + key, {"index"});
    }

    void factor(const json& o, const std::string& w, const char* key, std::size_t n) {
        if (!o.contains(key)) return;
        const json& f = o[key];
        if (!f.is_array() || f.size() != n || std::any_of(f.begin(), f.end(), [](const json& v) { return !v.is_number(); }))
            problem(w + "." + key, "expected an array of " + std::to_string(n) + " numbers");
    }

    void material(const json& o, const std::string& w) {
        if (const json* pbr = object(o, w, "pbrMetallicRoughness")) {
            const std::string pw = w + ".pbrMetallicRoughness";
            textureInfo(*pbr, pw, "baseColorTexture");
            textureInfo(*pbr, pw, "metallicRoughnessTexture");
            factor(*pbr, pw, "baseColorFactor", 4);
        }
        for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"}) textureInfo(o, w, key);
        factor(o, w, "emissiveFactor", 3);
    }

    void mesh(const json& o, const std::string& w) {
        if (!require(o, w, {"primitives"})) return;
        const json& prims = o["primitives"];
        const std::string pw = w + ".primitives";
        if (!prims.is_array()) return problem(pw, "expected an array");
        if (prims.empty()) problem(pw, "must not be empty (at least 1 primitive)");
        for (std::size_t i = 0; i < prims.size(); ++i) {
            const std::string ew = pw + "[" + std::to_string(i) + "]";
            if (!prims[i].is_object()) {
                problem(ew, "expected an object");
                continue;
            }
            if (!require(prims[i], ew, {"attributes"})) continue;
            const json& attributes = prims[i]["attributes"];
            if (!attributes.is_object()) problem(ew + ".attributes", "expected an object");
            else if (attributes.empty()) problem(ew + ".attributes", "must not be empty");
        }
    }

    // Every integer property anywhere in the file (extras left out).
    void integers(const json& j, const std::string& path) {
        if (j.is_object()) {
            for (auto it = j.begin(); it != j.end(); ++it) {
                if (it.key() == "extras") continue;
                integers(it.value(), path.empty() ? it.key() : path + "." + it.key());
            }
            return;
        }
        if (j.is_array()) {
            for (std::size_t i = 0; i < j.size(); ++i) integers(j[i], path + "[" + std::to_string(i) + "]");
            return;
        }
        const IntRule* rule = ruleFor(path);
        if (!rule) return;
        if (!j.is_number()) return problem(path, "expected an integer, got " + j.dump());
        const double value = j.get<double>();
        bool readPast = false;
        // A whole number beyond 64 bits (18446744073709551616) or written as
        // 1e20 is an integer the parser kept as a double: its problem is its size.
        const bool integral = j.is_number_integer() || (std::isfinite(value) && value == std::floor(value));
        const std::string what = problemOf(*rule, value, j.dump(), integral, readPast);
        if (what.empty()) return;
        if (readPast) invalid_.push_back(path + ": " + what + "; the default is used");
        else problem(path, what);
    }

    const json& root_;
    std::vector<std::string>& problems_;
    std::vector<std::string>& invalid_;
};

}  // namespace

void checkGltfSchema(const nlohmann::json& gltf, std::vector<std::string>& problems, std::vector<std::string>& invalid) {
    SchemaChecker(gltf, problems, invalid).run();
}

std::string gltfIntegerProblem(const std::string& path, double value, const std::string& number) {
    const IntRule* rule = ruleFor(path);
    if (!rule) return {};
    bool readPast = false;
    // Beyond a float every double is a whole number: the range decides.
    return problemOf(*rule, value, number, true, readPast);
}

}  // namespace dw
