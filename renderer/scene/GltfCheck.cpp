#include "renderer/scene/GltfCheck.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "renderer/Error.h"
#include "renderer/io/FloatCheck.h"
#include "renderer/scene/GltfSchema.h"

namespace dw {

namespace {

using json = nlohmann::json;

std::uint32_t readU32(const std::string& bytes, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;  // GLB is little-endian, as is every platform the workbench builds on
}

constexpr double kPi = 3.14159265358979323846;
// Exporters write pi/2 rounded to a 32-bit float (1.5707963705...).
constexpr double kRightAngleTolerance = 1e-6;

// One object's first problem: the checks of that object stop there, the
// other objects are still checked (every bad camera is named, not the last).
struct ObjectProblem {
    std::string text;
};

class ValueChecker {
public:
    ValueChecker(const json& root, std::vector<std::string>& problems) : root_(root), problems_(problems) {}

    void run() {
        checkUris("buffers");
        checkUris("images");
        if (root_.contains("cameras") && root_["cameras"].is_array())
            for (std::size_t i = 0; i < root_["cameras"].size(); ++i) {
                const std::string where = "cameras[" + std::to_string(i) + "]";
                attempt(where, [&] { checkCamera(root_["cameras"][i], where); });
            }
        const json* lights = find(root_, {"extensions", "KHR_lights_punctual", "lights"});
        if (lights && lights->is_array())
            for (std::size_t i = 0; i < lights->size(); ++i) {
                const std::string where = "extensions.KHR_lights_punctual.lights[" + std::to_string(i) + "]";
                attempt(where, [&] { checkLight((*lights)[i], where); });
            }
    }

private:
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw ObjectProblem{where + ": " + what};
    }

    // Runs one object's checks unless the schema check already named it.
    template <typename F>
    void attempt(const std::string& where, F check) {
        for (const std::string& p : problems_)
            if (p.rfind(where + ":", 0) == 0 || p.rfind(where + ".", 0) == 0) return;
        try {
            check();
        } catch (const ObjectProblem& p) {
            problems_.push_back(p.text);
        }
    }

    static const json* find(const json& j, std::initializer_list<const char*> keys) {
        const json* at = &j;
        for (const char* k : keys) {
            if (!at->is_object() || !at->contains(k)) return nullptr;
            at = &(*at)[k];
        }
        return at;
    }

    // The number at obj[key] (fallback when absent), as a float-representable double.
    double number(const json& obj, const char* key, const std::string& where, double fallback) const {
        if (!obj.contains(key)) return fallback;
        const json& v = obj[key];
        const std::string field = where + "." + key;
        if (!v.is_number()) fail(field, "expected a number");
        const double d = v.get<double>();
        if (const std::string problem = floatProblem(d); !problem.empty()) fail(field, problem);
        return d;
    }

    void checkUris(const char* array) {
        if (!root_.contains(array) || !root_[array].is_array()) return;
        const json& a = root_[array];
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (!a[i].is_object() || !a[i].contains("uri") || !a[i]["uri"].is_string()) continue;
            const std::string uri = a[i]["uri"].get<std::string>();
            if (uri.rfind("data:", 0) != 0) continue;
            std::string problem;
            if (!isDecodableDataUri(uri, problem))
                problems_.push_back(std::string(array) + "[" + std::to_string(i) + "].uri: malformed data: URI: " + problem);
        }
    }

    void checkCamera(const json& c, const std::string& where) const {
        if (!c.is_object() || !c.contains("perspective") || !c["perspective"].is_object()) return;
        const json& p = c["perspective"];
        const std::string w = where + ".perspective";
        if (!p.contains("yfov")) fail(w, "needs \"yfov\"");
        const double yfov = number(p, "yfov", w, 0.0);
        if (!(yfov > 0.0 && yfov < 179.0 * kPi / 180.0))
            fail(w + ".yfov", "must be in (0, 179) degrees, got " + shortNumber(yfov) + " rad (" +
                                  shortNumber(yfov * 180.0 / kPi) + " degrees)");
        if (!p.contains("znear")) fail(w, "needs \"znear\"");
        const double znear = number(p, "znear", w, 0.0);
        if (!(znear > 0.0)) fail(w + ".znear", "must be greater than 0, got " + shortNumber(znear));
        if (static_cast<float>(znear) < FLT_MIN)
            fail(w + ".znear", shortNumber(znear) + " is below the smallest normal 32-bit float (1.2e-38)");
        if (p.contains("zfar")) {
            const double zfar = number(p, "zfar", w, 0.0);
            if (!(static_cast<float>(zfar) > static_cast<float>(znear)))
                fail(w + ".zfar", "must be greater than znear (" + shortNumber(znear) + "), got " + shortNumber(zfar));
        }
        if (p.contains("aspectRatio")) {
            const double aspect = number(p, "aspectRatio", w, 1.0);
            if (!(aspect > 0.0)) fail(w + ".aspectRatio", "must be greater than 0, got " + shortNumber(aspect));
        }
    }

    void checkLight(const json& l, const std::string& where) const {
        if (!l.is_object()) fail(where, "expected an object");
        if (!l.contains("type") || !l["type"].is_string()) fail(where, "needs a \"type\" (directional, point or spot)");
        const std::string type = l["type"].get<std::string>();
        if (type != "directional" && type != "point" && type != "spot")
            fail(where + ".type", "expected \"directional\", \"point\" or \"spot\", got \"" + type + "\"");
        const double intensity = number(l, "intensity", where, 1.0);
        if (intensity < 0.0) fail(where + ".intensity", "must not be negative, got " + shortNumber(intensity));
        if (l.contains("color")) {
            const json& c = l["color"];
            if (!c.is_array() || c.size() != 3) fail(where + ".color", "expected an array of 3 numbers");
            for (std::size_t k = 0; k < 3; ++k) {
                const std::string field = where + ".color[" + std::to_string(k) + "]";
                if (!c[k].is_number()) fail(field, "expected a number");
                const double v = c[k].get<double>();
                if (const std::string problem = floatProblem(v); !problem.empty()) fail(field, problem);
                if (v < 0.0) fail(field, "must not be negative, got " + shortNumber(v));
            }
            // Colour times intensity is the light's radiance: it must stay a float too.
            for (std::size_t k = 0; k < 3; ++k)
                if (const std::string problem = floatProblem(c[k].get<double>() * intensity); !problem.empty())
                    fail(where + ".intensity", "color times intensity " + problem);
        }
        if (l.contains("range")) {
            const double range = number(l, "range", where, 1.0);
            if (!(range > 0.0)) fail(where + ".range", "must be greater than 0, got " + shortNumber(range));
        }
        if (type != "spot") return;
        const json empty = json::object();
        const json& s = l.contains("spot") ? l["spot"] : empty;
        if (!s.is_object()) fail(where + ".spot", "expected an object");
        const std::string w = where + ".spot";
        const double inner = number(s, "innerConeAngle", w, 0.0);
        const double outer = number(s, "outerConeAngle", w, kPi / 4.0);
        if (!(outer > 0.0 && outer <= kPi / 2.0 + kRightAngleTolerance))
            fail(w + ".outerConeAngle", "must be in (0, pi/2] radians, got " + shortNumber(outer) + " (" +
                                             shortNumber(outer * 180.0 / kPi) + " degrees)");
        if (!(inner >= 0.0 && inner < outer))
            fail(w + ".innerConeAngle", "must be at least 0 and less than outerConeAngle (" + shortNumber(outer) +
                                            "), got " + shortNumber(inner));
    }

    const json& root_;
    std::vector<std::string>& problems_;
};

}  // namespace

namespace {

// A chunk type as the spec writes it: 0x4E4F534A ("JSON").
std::string chunkTypeName(std::uint32_t type) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%08X", type);
    std::string text;
    for (int i = 0; i < 4; ++i) {
        const unsigned char c = static_cast<unsigned char>((type >> (8 * i)) & 0xFF);
        if (c == 0) text += "\\0";
        else if (c >= 0x20 && c < 0x7F) text += static_cast<char>(c);
        else return hex;
    }
    return std::string(hex) + " (\"" + text + "\")";
}

constexpr std::uint32_t kJsonChunk = 0x4E4F534Au, kBinChunk = 0x004E4942u;

}  // namespace

std::string_view glbJsonChunk(const std::string& bytes, const std::string& path, std::vector<std::string>* invalid) {
    auto fail = [&](const std::string& what) { throw FileError(path, "malformed GLB: " + what); };
    auto note = [&](const std::string& what) {
        if (invalid) invalid->push_back("GLB: " + what);
    };
    const std::size_t size = bytes.size();
    if (size < 12) fail("the file is " + std::to_string(size) + " bytes, shorter than the 12-byte GLB header");
    if (bytes.compare(0, 4, "glTF") != 0) fail("the file does not start with the GLB magic \"glTF\"");
    const std::uint32_t version = readU32(bytes, 4), length = readU32(bytes, 8);
    if (version != 2) fail("GLB version " + std::to_string(version) + " (only version 2 is read)");
    // Spec: "length is the total length of the Binary glTF, including Header
    // and all Chunks, in bytes". Either way round the file is not what its
    // header says: cut short, or the length field (or the file) is wrong.
    if (length != size)
        fail("the header declares a total length of " + std::to_string(length) + " bytes but the file has " +
             std::to_string(size) + (length > size ? " (cut short?)" : ""));
    if (size == 12) fail("no JSON chunk: the file ends after the 12-byte header");
    if (size < 20)
        fail("the JSON chunk's header is incomplete: " + std::to_string(size - 12) +
             " byte(s) after the 12-byte file header, a chunk header takes 8");
    const std::uint32_t jsonLength = readU32(bytes, 12), jsonType = readU32(bytes, 16);
    if (jsonType != kJsonChunk)
        fail("the first chunk is of type " + chunkTypeName(jsonType) + ", not JSON (0x4E4F534A): the JSON chunk must come first");
    if (jsonLength == 0) fail("the JSON chunk is empty (chunkLength 0)");
    if (jsonLength > size - 20)
        fail("the JSON chunk declares " + std::to_string(jsonLength) + " bytes but only " + std::to_string(size - 20) +
             " follow its header (the file has " + std::to_string(size) + ")");
    if (jsonLength % 4 != 0)
        note("the JSON chunk's length (" + std::to_string(jsonLength) +
             " bytes) is not a multiple of 4 (spec: chunks end on a 4-byte boundary)");
    // The chunks after the JSON chunk: an optional BIN chunk first, then any
    // of unknown types (which readers must skip); each must fit the file.
    std::size_t at = 20ull + jsonLength;
    for (int index = 1; at < size; ++index) {
        const std::string where = "chunk " + std::to_string(index) + " (at byte " + std::to_string(at) + ")";
        if (size - at < 8)
            fail(where + ": " + std::to_string(size - at) + " byte(s) left, too few for a chunk header (8 bytes)");
        const std::uint32_t chunkLength = readU32(bytes, at), type = readU32(bytes, at + 4);
        const std::string name = type == kBinChunk ? "the binary chunk" : "chunk " + std::to_string(index);
        if (chunkLength > size - at - 8)
            fail(name + " (at byte " + std::to_string(at) + ") declares " + std::to_string(chunkLength) +
                 " bytes but only " + std::to_string(size - at - 8) + " follow its header (the file has " +
                 std::to_string(size) + ")");
        if (index == 1 && type != kBinChunk)
            fail(where + " is of type " + chunkTypeName(type) +
                 ", not BIN (0x004E4942): the reader needs the binary chunk right after the JSON chunk");
        if (type == kJsonChunk) fail(where + " is a second JSON chunk (a GLB has exactly one)");
        if (type == kBinChunk && index > 1) fail(where + " is a second binary chunk (a GLB has at most one)");
        if (type == kBinChunk && chunkLength == 0)
            fail("the binary chunk is empty (chunkLength 0; spec: an empty binary chunk is left out)");
        if (chunkLength % 4 != 0) {
            const std::string what = name + "'s length (" + std::to_string(chunkLength) +
                                     " bytes) is not a multiple of 4 (spec: chunks end on a 4-byte boundary)";
            if (type == kBinChunk) fail(what);  // the reader refuses it
            note(what);
        }
        at += 8ull + chunkLength;
    }
    return std::string_view(bytes).substr(20, jsonLength);
}

bool isDecodableDataUri(const std::string& uri, std::string& problem) {
    // The types tinygltf 2.7 decodes (IsDataURI), and image/webp, which the
    // importer decodes itself (EXT_texture_webp); anything else tinygltf
    // would look for as a file named "data:...".
    static const char* kTypes[] = {"application/octet-stream", "application/gltf-buffer", "image/jpeg", "image/png",
                                   "image/bmp", "image/gif", "image/webp", "text/plain"};
    const std::size_t comma = uri.find(',');
    if (comma == std::string::npos) {
        problem = "no ',' before the data";
        return false;
    }
    const std::string header = uri.substr(5, comma - 5);
    const std::string suffix = ";base64";
    if (header.size() < suffix.size() || header.compare(header.size() - suffix.size(), suffix.size(), suffix) != 0) {
        problem = "the data is not marked ;base64";
        return false;
    }
    const std::string type = header.substr(0, header.size() - suffix.size());
    bool known = false;
    for (const char* t : kTypes) known = known || type == t;
    if (!known) {
        problem = "media type '" + type + "' is not one the reader decodes (application/octet-stream, "
                  "application/gltf-buffer, image/png, image/jpeg, ...)";
        return false;
    }
    const std::size_t begin = comma + 1;
    std::size_t end = uri.size();
    while (end > begin && uri[end - 1] == '=' && uri.size() - end < 2) --end;
    for (std::size_t i = begin; i < end; ++i) {
        const unsigned char c = static_cast<unsigned char>(uri[i]);
        if (!(std::isalnum(c) || c == '+' || c == '/')) {
            problem = "invalid base64 character at position " + std::to_string(i);
            return false;
        }
    }
    if ((uri.size() - begin) % 4 == 1) {
        problem = "the base64 data has a length that no byte count encodes to";
        return false;
    }
    return true;
}

std::optional<std::uint32_t> glbBinLength(const std::string& bytes) {
    const std::size_t at = 20ull + readU32(bytes, 12);
    if (at + 8 > bytes.size() || readU32(bytes, at + 4) != kBinChunk) return std::nullopt;
    return readU32(bytes, at);
}

namespace {

// A buffer without a uri: only a GLB's buffer 0, for its binary chunk, which
// must exist and hold byteLength bytes (tinygltf says neither which buffer nor why).
void checkBufferSources(const json& gltf, const GltfContainer& container, std::vector<std::string>& problems) {
    if (!gltf.contains("buffers") || !gltf["buffers"].is_array()) return;
    const json& buffers = gltf["buffers"];
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        const json& b = buffers[i];
        if (!b.is_object() || b.contains("uri")) continue;
        const std::string where = "buffers[" + std::to_string(i) + "]";
        if (!container.glb)
            problems.push_back(where + ": required property 'uri' is missing (only a GLB's buffer 0 may leave it out)");
        else if (i != 0)
            problems.push_back(where + ": has no uri (only buffer 0 of a GLB takes the binary chunk)");
        else if (!container.binLength)
            problems.push_back(where + ": has no uri and the GLB has no binary chunk");
        else if (b.contains("byteLength") && b["byteLength"].is_number_unsigned() &&
                 b["byteLength"].get<std::uint64_t>() > *container.binLength)
            problems.push_back(where + ".byteLength: " + b["byteLength"].dump() + " is more than the binary chunk's " +
                               std::to_string(*container.binLength) + " bytes");
    }
}

}  // namespace

void checkGltfValues(const nlohmann::json& gltf, const std::string& path, std::vector<std::string>* invalid,
                     const GltfContainer& container) {
    std::vector<std::string> problems, readPast;
    checkGltfSchema(gltf, problems, readPast);
    checkBufferSources(gltf, container, problems);
    ValueChecker(gltf, problems).run();
    if (!problems.empty()) throw FileError(path, joinProblems(problems));
    if (invalid) invalid->insert(invalid->end(), readPast.begin(), readPast.end());
}

std::string joinProblems(std::vector<std::string> problems) {
    // In the order of the objects' JSON paths, indices by number (cameras[2]
    // before cameras[10]); one object's problems in the order found.
    auto less = [](const std::string& a, const std::string& b) {
        const std::string pa = a.substr(0, a.find(": ")), pb = b.substr(0, b.find(": "));
        std::size_t i = 0, k = 0;
        while (i < pa.size() && k < pb.size()) {
            if (std::isdigit(static_cast<unsigned char>(pa[i])) && std::isdigit(static_cast<unsigned char>(pb[k]))) {
                std::size_t ei = i, ek = k;
                while (ei < pa.size() && std::isdigit(static_cast<unsigned char>(pa[ei]))) ++ei;
                while (ek < pb.size() && std::isdigit(static_cast<unsigned char>(pb[ek]))) ++ek;
                const std::string na = pa.substr(i, ei - i), nb = pb.substr(k, ek - k);
                if (na.size() != nb.size()) return na.size() < nb.size();
                if (na != nb) return na < nb;
                i = ei;
                k = ek;
            } else {
                if (pa[i] != pb[k]) return pa[i] < pb[k];
                ++i;
                ++k;
            }
        }
        return pa.size() - i < pb.size() - k;
    };
    std::stable_sort(problems.begin(), problems.end(), less);
    constexpr std::size_t kShown = 12;
    std::string out;
    for (std::size_t i = 0; i < problems.size() && i < kShown; ++i) out += (i ? "; " : "") + problems[i];
    if (problems.size() > kShown) out += "; and " + std::to_string(problems.size() - kShown) + " more";
    return out;
}

}  // namespace dw
