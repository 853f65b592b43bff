#include "renderer/scene/GltfLoader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <new>
#include <optional>
#include <nlohmann/json.hpp>
#include <string_view>

#include "renderer/Error.h"
#include "renderer/io/ImageIO.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"
#include "renderer/scene/CameraCheck.h"
#include "renderer/scene/GltfCheck.h"
#include "renderer/scene/GltfSchema.h"
#include "renderer/scene/NormalGenerator.h"
#include "renderer/scene/TangentGenerator.h"

// tinygltf's base64 decoder: exported by Debian's libtinygltf, but declared
// only in tiny_gltf.h's implementation section.
namespace tinygltf {
std::string base64_decode(std::string const& encoded);
}  // namespace tinygltf

namespace dw {

namespace fs = std::filesystem;

namespace {

// Anything larger is treated as a corrupt count rather than allocated.
constexpr size_t kMaxElements = size_t(1) << 27;

// glTF sampler wrap modes (the GL enums).
constexpr int kRepeat = 10497, kClampToEdge = 33071, kMirroredRepeat = 33648;

class Importer {
public:
    Importer(std::string path, Scene& scene) : path_(std::move(path)), scene_(scene) {}

    [[noreturn]] void fail(const std::string& what) const { throw FileError(path_, what); }

    // Reads the glTF JSON (the first chunk of a .glb) with nlohmann to report
    // malformed JSON by line and column, and unsupported required extensions
    // before tinygltf misreads them (e.g. Draco-compressed accessors).
    // `bytes` is the whole file; returns what tinygltf parses afterwards
    // (the same bytes, unless hideZeroIndexAccessors rewrote the JSON).
    std::string precheck(const std::string& bytes) {
        const bool glb = isBinary(bytes);
        const std::string_view text = glb ? glbJsonChunk(bytes, path_, &invalid_) : std::string_view(bytes);
        // Nesting depth, numbers beyond a float, by JSON path; integer
        // properties beyond a float are named as integers (GltfSchema.h).
        JsonGuardOptions guard;
        guard.integerProblem = gltfIntegerProblem;
        checkJsonText(text, path_, guard);
        nlohmann::json j;
        try {
            j = nlohmann::json::parse(text);
        } catch (const nlohmann::json::parse_error& e) {
            fail("malformed JSON at " + textPosition(text, e.byte));
        } catch (const nlohmann::json::exception& e) {
            fail("unreadable JSON: " + jsonErrorText(e));
        }
        if (!j.is_object()) fail("not a glTF file: the top level is not a JSON object");
        GltfContainer container;
        container.glb = glb;
        if (glb) container.binLength = glbBinLength(bytes);
        checkGltfValues(j, path_, &invalid_, container);  // schema, buffers, cameras, lights, data: URIs (GltfCheck.h)
        if (j.contains("extensionsRequired") && j["extensionsRequired"].is_array()) {
            for (const auto& e : j["extensionsRequired"])
                if (e.is_string() && !isSupportedExtension(e.get<std::string>()))
                    fail("requires glTF extension " + e.get<std::string>() + ", which the workbench does not support");
        }
        if (j.contains("asset") && j["asset"].is_object() && j["asset"].contains("version") &&
            j["asset"]["version"].is_string() && j["asset"]["version"].get<std::string>().rfind("2.", 0) != 0)
            fail("glTF version " + j["asset"]["version"].get<std::string>() + " is not supported (2.x only)");
        if (!hideZeroIndexAccessors(j)) return bytes;
        const std::string json = j.dump();
        if (!glb) return json;
        // The GLB again, with the rewritten JSON chunk (space-padded to 4 bytes)
        // and the chunks after it unchanged.
        std::uint32_t oldLength = 0;
        std::memcpy(&oldLength, bytes.data() + 12, 4);
        std::string chunk = json;
        chunk.resize((chunk.size() + 3) & ~std::size_t(3), ' ');
        const auto chunkLength = static_cast<std::uint32_t>(chunk.size());
        std::string out = bytes.substr(0, 12);
        out.append(reinterpret_cast<const char*>(&chunkLength), 4);
        out.append(bytes, 16, 4);
        out += chunk;
        out.append(bytes, 20 + static_cast<std::size_t>(oldLength), std::string::npos);
        const auto total = static_cast<std::uint32_t>(out.size());
        std::memcpy(out.data() + 8, &total, 4);
        return out;
    }

    // glTF 2.0 (3.6.2.3): an accessor without bufferView holds zeros (plus its
    // sparse values). tinygltf 2.7 parses such accessors but refuses a
    // primitive whose *indices* use one ("invalid bufferView", in its pass that
    // assigns bufferView targets). So those primitives' "indices" are removed
    // from the JSON tinygltf sees, remembered, and put back after parsing
    // (restoreZeroIndexAccessors); readAccessor supplies the zeros.
    // Returns whether the JSON changed.
    bool hideZeroIndexAccessors(nlohmann::json& j) {
        if (!j.contains("meshes") || !j["meshes"].is_array() || !j.contains("accessors") || !j["accessors"].is_array())
            return false;
        const auto& accessors = j["accessors"];
        for (std::size_t m = 0; m < j["meshes"].size(); ++m) {
            auto& mesh = j["meshes"][m];
            if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
            for (std::size_t p = 0; p < mesh["primitives"].size(); ++p) {
                auto& prim = mesh["primitives"][p];
                if (!prim.is_object() || !prim.contains("indices") || !prim["indices"].is_number_unsigned()) continue;
                const auto a = prim["indices"].get<std::size_t>();
                if (a >= accessors.size() || !accessors[a].is_object() || accessors[a].contains("bufferView")) continue;
                hiddenIndices_.push_back({m, p, static_cast<int>(a)});
                prim.erase("indices");
            }
        }
        return !hiddenIndices_.empty();
    }

    void restoreZeroIndexAccessors() {
        for (const auto& h : hiddenIndices_)
            if (h.mesh < model_.meshes.size() && h.primitive < model_.meshes[h.mesh].primitives.size())
                model_.meshes[h.mesh].primitives[h.primitive].indices = h.accessor;
    }

    static bool isSupportedExtension(const std::string& ext) {
        // KHR_mesh_quantization: readAccessor reads every component type, normalised or not.
        static const char* supported[] = {"KHR_lights_punctual", "KHR_materials_pbrSpecularGlossiness",
                                          "KHR_materials_specular", "KHR_materials_emissive_strength",
                                          "KHR_texture_transform", "KHR_mesh_quantization", "EXT_texture_webp"};
        return std::find(std::begin(supported), std::end(supported), ext) != std::end(supported);
    }

    void load() {
        const std::string bytes = precheck(readWholeFile(path_, "file not found", "cannot open file"));
        tinygltf::TinyGLTF loader;
        loader.SetImageLoader(&Importer::decodeImageCallback, this);
        std::string err, warn;
        bool ok = false;
        // What tinygltf's *FromFile functions do after reading the file: parse
        // from memory with the file's folder as the base for relative URIs.
        const std::size_t slash = path_.find_last_of("/\\");
        const std::string baseDir = slash == std::string::npos ? std::string() : path_.substr(0, slash);
        const auto length = static_cast<unsigned int>(bytes.size());
        try {
            ok = isBinary(bytes)
                     ? loader.LoadBinaryFromMemory(&model_, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                   length, baseDir)
                     : loader.LoadASCIIFromString(&model_, &err, &warn, bytes.data(), length, baseDir);
        } catch (const std::bad_alloc&) {
            fail("malformed glTF: the parser ran out of memory (a corrupt length or count)");
        } catch (const FileError&) {
            throw;
        } catch (const std::exception& e) {
            fail(std::string("malformed glTF: ") + e.what());
        }
        if (!imageError_.empty()) fail(imageError_);
        if (!ok) fail("not a valid glTF 2.0 file: " + firstLines(err.empty() ? warn : err));
        restoreZeroIndexAccessors();
    }

    GltfImport import(const glm::mat4& root, bool lightsAndCamera) {
        load();
        validate();
        noteInvalid();
        importImages();
        importMaterials();
        importMeshes();
        GltfImport result;
        walkScene(root, lightsAndCamera, result);
        warnInvalid();
        warnIgnored();
        return result;
    }

private:
    static bool isGlb(const std::string& bytes) { return bytes.compare(0, 4, "glTF") == 0; }

    // By extension; by the GLB magic when the extension says neither.
    bool isBinary(const std::string& bytes) const {
        std::string ext = fs::path(path_).extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
        // The GLB magic wins over the name; a .glb without it is reported as a bad GLB header.
        if (isGlb(bytes) || ext == ".glb") return true;
        return false;
    }

    static std::string firstLines(const std::string& s) {
        std::string out = s;
        while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
        std::replace(out.begin(), out.end(), '\n', ';');
        if (out.size() > 400) out = out.substr(0, 400) + "...";
        return out.empty() ? "the glTF reader refused it without giving a reason" : out;
    }

    static bool decodeImageCallback(tinygltf::Image* image, const int index, std::string* err,
                                    std::string* /*warn*/, int, int, const unsigned char* bytes,
                                    int size, void* user) {
        auto* self = static_cast<Importer*>(user);
        const std::string name = image->uri.empty() ? "image[" + std::to_string(index) + "]"
                                                    : "image[" + std::to_string(index) + "] '" + image->uri + "'";
        // tinygltf passes a bufferView's bytes without checking them against
        // the buffer: check the range before anything reads it.
        if (image->bufferView >= 0) {
            const std::string range = self->imageRangeProblem(*image);
            if (!range.empty()) {
                self->imageError_ = name + ": " + range;
                if (err) *err += self->imageError_;
                return false;
            }
        }
        try {
            Image decoded = decodeImage8(bytes, static_cast<size_t>(std::max(size, 0)), name, image->mimeType);
            image->width = decoded.width;
            image->height = decoded.height;
            image->component = 4;
            image->bits = 8;
            image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
            image->image = std::move(decoded.rgba);
            return true;
        } catch (const std::exception& e) {
            // FileError's text already starts with the image name.
            self->imageError_ = std::string("cannot decode ") + e.what();
            if (err) *err += self->imageError_;
            return false;
        }
    }

    // Empty when image.bufferView's bytes lie inside its buffer (tinygltf has
    // parsed buffers and bufferViews into model_ before images).
    std::string imageRangeProblem(const tinygltf::Image& image) const {
        const size_t view = static_cast<size_t>(image.bufferView);
        if (view >= model_.bufferViews.size()) return "bufferView " + std::to_string(view) + " does not exist";
        const auto& bv = model_.bufferViews[view];
        if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= model_.buffers.size())
            return "bufferView[" + std::to_string(view) + "] refers to a buffer that does not exist";
        const size_t size = model_.buffers[bv.buffer].data.size();
        if (bv.byteOffset > size || bv.byteLength > size - bv.byteOffset)
            return "bufferView[" + std::to_string(view) + "] (bytes " + std::to_string(bv.byteOffset) + " to " +
                   std::to_string(bv.byteOffset + bv.byteLength) + ") runs past the end of buffer[" +
                   std::to_string(bv.buffer) + "] (" + std::to_string(size) + " bytes)";
        if (bv.byteLength > static_cast<size_t>(std::numeric_limits<int>::max()))
            return "bufferView[" + std::to_string(view) + "] is larger than 2 GiB";
        return {};
    }

    // ---- structural validation: everything later code indexes is checked here.
    template <typename T>
    void checkIndex(int index, const std::vector<T>& v, const std::string& what, bool optional = true) const {
        if (index < 0 && optional) return;
        if (index < 0 || static_cast<size_t>(index) >= v.size())
            fail(what + " refers to index " + std::to_string(index) + " but there are only " +
                 std::to_string(v.size()));
    }

    // Runs one object's checks; its first problem goes into `problems` (without
    // the file name) and the other objects are still checked.
    template <typename F>
    void collect(std::vector<std::string>& problems, F check) const {
        try {
            check();
        } catch (const FileError& e) {
            const std::string text = e.what();
            problems.push_back(text.rfind(path_ + ": ", 0) == 0 ? text.substr(path_.size() + 2) : text);
        }
    }

    void validate() const {
        for (const auto& ext : model_.extensionsRequired)
            if (!isSupportedExtension(ext)) fail("requires glTF extension " + ext + ", which the workbench does not support");
        std::vector<std::string> problems;
        for (size_t i = 0; i < model_.buffers.size(); ++i) {
            if (model_.buffers[i].data.empty())
                problems.push_back("buffer[" + std::to_string(i) + "] has no data (missing .bin file?)");
        }
        for (size_t i = 0; i < model_.bufferViews.size(); ++i) collect(problems, [&] {
            const auto& bv = model_.bufferViews[i];
            const std::string what = "bufferView[" + std::to_string(i) + "]";
            checkIndex(bv.buffer, model_.buffers, what + ".buffer", false);
            const size_t size = model_.buffers[bv.buffer].data.size();
            if (bv.byteOffset > size || bv.byteLength > size - bv.byteOffset)
                fail(what + " (offset " + std::to_string(bv.byteOffset) + ", length " +
                     std::to_string(bv.byteLength) + ") runs past the end of buffer[" +
                     std::to_string(bv.buffer) + "] (" + std::to_string(size) + " bytes)");
        });
        for (size_t i = 0; i < model_.accessors.size(); ++i)
            collect(problems, [&] { validateAccessor(static_cast<int>(i)); });
        for (size_t m = 0; m < model_.meshes.size(); ++m) {
            for (size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) collect(problems, [&] {
                const auto& prim = model_.meshes[m].primitives[p];
                const std::string what = "mesh[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
                for (const auto& [name, acc] : prim.attributes)
                    checkIndex(acc, model_.accessors, what + ".attributes." + name, false);
                checkIndex(prim.indices, model_.accessors, what + ".indices");
                checkIndex(prim.material, model_.materials, what + ".material");
            });
        }
        for (size_t i = 0; i < model_.textures.size(); ++i) collect(problems, [&] {
            checkIndex(model_.textures[i].source, model_.images, "texture[" + std::to_string(i) + "].source");
            checkIndex(model_.textures[i].sampler, model_.samplers, "texture[" + std::to_string(i) + "].sampler");
            checkIndex(webpSource(model_.textures[i]), model_.images,
                       "texture[" + std::to_string(i) + "].extensions.EXT_texture_webp.source");
        });
        for (size_t i = 0; i < model_.materials.size(); ++i) collect(problems, [&] {
            const auto& m = model_.materials[i];
            const std::string what = "material[" + std::to_string(i) + "]";
            checkIndex(m.pbrMetallicRoughness.baseColorTexture.index, model_.textures, what + ".baseColorTexture");
            checkIndex(m.pbrMetallicRoughness.metallicRoughnessTexture.index, model_.textures,
                       what + ".metallicRoughnessTexture");
            checkIndex(m.normalTexture.index, model_.textures, what + ".normalTexture");
            checkIndex(m.emissiveTexture.index, model_.textures, what + ".emissiveTexture");
            checkIndex(m.occlusionTexture.index, model_.textures, what + ".occlusionTexture");
        });
        for (size_t i = 0; i < model_.nodes.size(); ++i) collect(problems, [&] {
            const auto& n = model_.nodes[i];
            const std::string what = "node[" + std::to_string(i) + "]";
            checkIndex(n.mesh, model_.meshes, what + ".mesh");
            checkIndex(n.camera, model_.cameras, what + ".camera");
            for (int c : n.children) checkIndex(c, model_.nodes, what + ".children", false);
            auto finite = [&](const std::vector<double>& v, size_t want, const char* field) {
                if (!v.empty() && v.size() != want)
                    fail(what + "." + field + " has " + std::to_string(v.size()) + " values, expected " +
                         std::to_string(want));
                for (double d : v)
                    if (!std::isfinite(d)) fail(what + "." + field + " has a non-finite value");
            };
            finite(n.matrix, 16, "matrix");
            finite(n.translation, 3, "translation");
            finite(n.rotation, 4, "rotation");
            finite(n.scale, 3, "scale");
        });
        for (size_t s = 0; s < model_.scenes.size(); ++s) collect(problems, [&] {
            for (int n : model_.scenes[s].nodes)
                checkIndex(n, model_.nodes, "scene[" + std::to_string(s) + "].nodes", false);
        });
        if (!problems.empty()) fail(joinProblems(problems));
        checkNodeGraph();  // needs every child index in range
    }

    // Rules of the spec ("Skins", "Morph Targets") whose breaking does not
    // stop the file from drawing, since the workbench draws neither skins nor
    // morph targets: named for the "invalid glTF (drawn anyway)" warning.
    void noteInvalid() {
        auto targetCount = [&](size_t mesh) { return model_.meshes[mesh].primitives.empty() ? size_t(0)
                                                                                               : model_.meshes[mesh].primitives[0].targets.size(); };
        for (size_t m = 0; m < model_.meshes.size(); ++m) {
            const auto& mesh = model_.meshes[m];
            const std::string what = "meshes[" + std::to_string(m) + "]";
            for (size_t p = 1; p < mesh.primitives.size(); ++p)
                if (mesh.primitives[p].targets.size() != targetCount(m)) {
                    invalid_.push_back(what + ": primitive 0 has " + std::to_string(targetCount(m)) + " morph target(s), primitive " +
                                       std::to_string(p) + " " + std::to_string(mesh.primitives[p].targets.size()) +
                                       " (spec: every primitive of a mesh has the same number)");
                    break;
                }
            if (!mesh.weights.empty() && mesh.weights.size() != targetCount(m))
                invalid_.push_back(what + ".weights: " + std::to_string(mesh.weights.size()) + " weight(s) for " +
                                   std::to_string(targetCount(m)) + " morph target(s) (spec: one weight per morph target)");
        }
        for (size_t i = 0; i < model_.skins.size(); ++i)
            for (int joint : model_.skins[i].joints)
                if (joint < 0 || static_cast<size_t>(joint) >= model_.nodes.size()) {
                    invalid_.push_back("skins[" + std::to_string(i) + "].joints: refers to node " + std::to_string(joint) +
                                       " but there are only " + std::to_string(model_.nodes.size()));
                    break;
                }
        for (size_t i = 0; i < model_.nodes.size(); ++i) {
            const auto& n = model_.nodes[i];
            const std::string what = "nodes[" + std::to_string(i) + "]";
            if (n.skin >= 0) {
                if (static_cast<size_t>(n.skin) >= model_.skins.size())
                    invalid_.push_back(what + ".skin: refers to skin " + std::to_string(n.skin) + " but there are only " +
                                       std::to_string(model_.skins.size()));
                else if (n.mesh < 0)
                    invalid_.push_back(what + ": has skin " + std::to_string(n.skin) +
                                       " but no mesh (spec: a node with a skin has a mesh)");
                else
                    for (size_t p = 0; p < model_.meshes[n.mesh].primitives.size(); ++p) {
                        const auto& attrs = model_.meshes[n.mesh].primitives[p].attributes;
                        if (attrs.count("JOINTS_0") && attrs.count("WEIGHTS_0")) continue;
                        invalid_.push_back(what + ": has skin " + std::to_string(n.skin) + " but mesh " + std::to_string(n.mesh) +
                                           " primitive " + std::to_string(p) +
                                           " has no JOINTS_0 and WEIGHTS_0 (spec: the primitives of a skinned node's mesh have both)");
                        break;
                    }
            }
            if (!n.weights.empty()) {
                if (n.mesh < 0)
                    invalid_.push_back(what + ".weights: set on a node without a mesh (spec: weights need a mesh)");
                else if (n.weights.size() != targetCount(static_cast<size_t>(n.mesh)))
                    invalid_.push_back(what + ".weights: " + std::to_string(n.weights.size()) + " weight(s) for the " +
                                       std::to_string(targetCount(static_cast<size_t>(n.mesh))) + " morph target(s) of mesh " +
                                       std::to_string(n.mesh) + " (spec: one weight per morph target)");
            }
        }
    }

    void validateAccessor(int index) const {
        const auto& a = model_.accessors[index];
        const std::string what = "accessor[" + std::to_string(index) + "]";
        const int compSize = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
        const int comps = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
        if (compSize <= 0) fail(what + " has an invalid componentType " + std::to_string(a.componentType));
        if (comps <= 0) fail(what + " has an invalid type " + std::to_string(a.type));
        if (a.count > kMaxElements) fail(what + ".count " + std::to_string(a.count) + " is implausibly large");
        const size_t elem = static_cast<size_t>(compSize) * comps;
        if (a.bufferView >= 0) {
            checkIndex(a.bufferView, model_.bufferViews, what + ".bufferView", false);
            const auto& bv = model_.bufferViews[a.bufferView];
            const int stride = a.ByteStride(bv);
            if (stride <= 0) fail(what + " has an invalid byteStride in bufferView[" + std::to_string(a.bufferView) + "]");
            if (a.count > 0) {
                const size_t need = a.byteOffset + static_cast<size_t>(stride) * (a.count - 1) + elem;
                if (need > bv.byteLength)
                    fail(what + " reads " + std::to_string(need) + " bytes but bufferView[" +
                         std::to_string(a.bufferView) + "] has only " + std::to_string(bv.byteLength));
            }
        }
        if (a.sparse.isSparse) {
            const std::string sw = what + ".sparse";
            if (a.sparse.count < 0 || static_cast<size_t>(a.sparse.count) > a.count)
                fail(sw + ".count is out of range");
            checkIndex(a.sparse.indices.bufferView, model_.bufferViews, sw + ".indices.bufferView", false);
            checkIndex(a.sparse.values.bufferView, model_.bufferViews, sw + ".values.bufferView", false);
            const int isz = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.sparse.indices.componentType));
            if (isz <= 0) fail(sw + ".indices has an invalid componentType");
            const auto& ibv = model_.bufferViews[a.sparse.indices.bufferView];
            const auto& vbv = model_.bufferViews[a.sparse.values.bufferView];
            if (a.sparse.indices.byteOffset < 0 ||
                static_cast<size_t>(a.sparse.indices.byteOffset) + static_cast<size_t>(isz) * a.sparse.count > ibv.byteLength)
                fail(sw + ".indices run past their bufferView");
            if (a.sparse.values.byteOffset < 0 ||
                static_cast<size_t>(a.sparse.values.byteOffset) + elem * a.sparse.count > vbv.byteLength)
                fail(sw + ".values run past their bufferView");
        }
    }

    void checkNodeGraph() const {
        // Every node has at most one parent and the graph has no cycle.
        std::vector<int> parent(model_.nodes.size(), -1);
        for (size_t i = 0; i < model_.nodes.size(); ++i)
            for (int c : model_.nodes[i].children) {
                if (c == static_cast<int>(i)) fail("node[" + std::to_string(i) + "] lists itself as a child");
                if (parent[c] >= 0)
                    fail("node[" + std::to_string(c) + "] has two parents (node[" + std::to_string(parent[c]) +
                         "] and node[" + std::to_string(i) + "])");
                parent[c] = static_cast<int>(i);
            }
        for (size_t i = 0; i < model_.nodes.size(); ++i) {
            size_t steps = 0;
            for (int p = parent[i]; p >= 0; p = parent[p])
                if (++steps > model_.nodes.size()) fail("node hierarchy has a cycle through node[" + std::to_string(i) + "]");
        }
    }

    // ---- accessor reading, with normalisation and sparse substitution
    // Non-finite values are an error unless `allowNonFinite` (normals and
    // tangents, which the caller repairs).
    std::vector<double> readAccessor(int index, int wantComponents, const std::string& what,
                                     bool allowNonFinite = false) const {
        const auto& a = model_.accessors[index];
        const int comps = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
        if (comps != wantComponents)
            fail(what + " (accessor[" + std::to_string(index) + "]) has " + std::to_string(comps) +
                 " components, expected " + std::to_string(wantComponents));
        std::vector<double> out(a.count * comps, 0.0);
        auto readElement = [&](const unsigned char* p, double* dst) {
            for (int c = 0; c < comps; ++c) dst[c] = readComponent(p, c, a.componentType, a.normalized);
        };
        if (a.bufferView >= 0) {
            const auto& bv = model_.bufferViews[a.bufferView];
            const unsigned char* base = model_.buffers[bv.buffer].data.data() + bv.byteOffset + a.byteOffset;
            const int stride = a.ByteStride(bv);
            for (size_t i = 0; i < a.count; ++i) readElement(base + i * stride, &out[i * comps]);
        }
        if (a.sparse.isSparse) {
            const auto& ibv = model_.bufferViews[a.sparse.indices.bufferView];
            const auto& vbv = model_.bufferViews[a.sparse.values.bufferView];
            const unsigned char* ip = model_.buffers[ibv.buffer].data.data() + ibv.byteOffset + a.sparse.indices.byteOffset;
            const unsigned char* vp = model_.buffers[vbv.buffer].data.data() + vbv.byteOffset + a.sparse.values.byteOffset;
            const int isz = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.sparse.indices.componentType));
            const int esz = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType)) * comps;
            for (int s = 0; s < a.sparse.count; ++s) {
                const auto target = static_cast<size_t>(readComponent(ip + s * isz, 0, a.sparse.indices.componentType, false));
                if (target >= a.count) fail(what + ": sparse index " + std::to_string(target) + " out of range");
                readElement(vp + static_cast<size_t>(s) * esz, &out[target * comps]);
            }
        }
        if (!allowNonFinite)
            for (double d : out)
                if (!std::isfinite(d))
                    fail(what + " (accessor[" + std::to_string(index) + "]) contains non-finite values");
        return out;
    }

    static double readComponent(const unsigned char* p, int c, int type, bool normalized) {
        switch (type) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: { float v; std::memcpy(&v, p + 4 * c, 4); return v; }
            case TINYGLTF_COMPONENT_TYPE_DOUBLE: { double v; std::memcpy(&v, p + 8 * c, 8); return v; }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: { const double v = p[c]; return normalized ? v / 255.0 : v; }
            case TINYGLTF_COMPONENT_TYPE_BYTE: {
                const double v = static_cast<int8_t>(p[c]);
                return normalized ? std::max(v / 127.0, -1.0) : v;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                uint16_t v; std::memcpy(&v, p + 2 * c, 2);
                return normalized ? v / 65535.0 : v;
            }
            case TINYGLTF_COMPONENT_TYPE_SHORT: {
                int16_t v; std::memcpy(&v, p + 2 * c, 2);
                return normalized ? std::max(v / 32767.0, -1.0) : v;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p + 4 * c, 4); return v; }
            case TINYGLTF_COMPONENT_TYPE_INT: { int32_t v; std::memcpy(&v, p + 4 * c, 4); return v; }
            default: return 0.0;
        }
    }

    // ---- images, materials, meshes
    void importImages() {
        imageBase_ = static_cast<int>(scene_.images.size());
        for (size_t i = 0; i < model_.images.size(); ++i) {
            auto& img = model_.images[i];
            // tinygltf 2.7 decodes only the data: URIs of the media types it
            // lists (PNG, JPEG, BMP, GIF); any other (image/webp for
            // EXT_texture_webp) is decoded here, through the same decoder.
            if (img.image.empty() && img.uri.rfind("data:", 0) == 0) decodeDataUri(static_cast<int>(i), img);
            if (img.image.empty() || img.width <= 0 || img.height <= 0) {
                if (!img.uri.empty() && img.uri.rfind("data:", 0) != 0) {
                    const fs::path full = fs::path(path_).parent_path() / img.uri;
                    fail("missing texture: image[" + std::to_string(i) + "] '" + img.uri + "' (looked for " +
                         full.string() + ")");
                }
                fail("image[" + std::to_string(i) + "] has no decodable data");
            }
            if (img.image.size() < static_cast<size_t>(img.width) * img.height * 4)
                fail("image[" + std::to_string(i) + "] has fewer pixels than its size says");
            Image out;
            out.width = img.width;
            out.height = img.height;
            out.rgba = std::move(img.image);
            out.source = path_ + "#" + (img.uri.empty() ? "image" + std::to_string(i) : img.uri);
            scene_.addImage(std::move(out));
        }
    }

    void decodeDataUri(int index, tinygltf::Image& img) {
        const std::string& uri = img.uri;
        const size_t comma = uri.find(',');
        const std::string header = uri.substr(0, comma);
        if (comma == std::string::npos || header.size() < 12 || header.compare(header.size() - 7, 7, ";base64") != 0)
            fail("image[" + std::to_string(index) + "]: a data: URI must be 'data:<media type>;base64,<data>'");
        const std::string bytes = tinygltf::base64_decode(uri.substr(comma + 1));
        if (img.mimeType.empty()) img.mimeType = header.substr(5, header.size() - 12);
        decodeImageCallback(&img, index, nullptr, nullptr, 0, 0, reinterpret_cast<const unsigned char*>(bytes.data()),
                            static_cast<int>(bytes.size()), this);
        if (!imageError_.empty()) fail(imageError_);
    }

    // EXT_texture_webp's source, or -1.
    static int webpSource(const tinygltf::Texture& t) {
        auto it = t.extensions.find("EXT_texture_webp");
        if (it == t.extensions.end() || !it->second.Has("source") || !it->second.Get("source").IsNumber()) return -1;
        return it->second.Get("source").GetNumberAsInt();
    }

    // The image a texture shows: EXT_texture_webp's when there is one (the
    // extension's rule: prefer it when supported), else `source`.
    int imageOfTexture(int textureIndex) const {
        if (textureIndex < 0) return -1;
        const int webp = webpSource(model_.textures[textureIndex]);
        const int src = webp >= 0 ? webp : model_.textures[textureIndex].source;
        return src < 0 ? -1 : imageBase_ + src;
    }

    // A textureInfo's UV set, its texture's sampler and KHR_texture_transform.
    TextureMapping mappingOf(int textureIndex, int texCoord, const tinygltf::ExtensionMap& extensions) const {
        TextureMapping out;
        out.texCoord = texCoord;
        if (textureIndex >= 0 && model_.textures[textureIndex].sampler >= 0) {
            const auto& smp = model_.samplers[model_.textures[textureIndex].sampler];
            // Values outside the glTF enums fall back to the defaults.
            auto wrap = [](int w, unsigned fallback) {
                return w == kRepeat || w == kClampToEdge || w == kMirroredRepeat ? static_cast<unsigned>(w) : fallback;
            };
            out.wrapS = wrap(smp.wrapS, out.wrapS);
            out.wrapT = wrap(smp.wrapT, out.wrapT);
            if (smp.magFilter == 9728 || smp.magFilter == 9729) out.magFilter = static_cast<unsigned>(smp.magFilter);
            if (smp.minFilter == 9728 || smp.minFilter == 9729 || (smp.minFilter >= 9984 && smp.minFilter <= 9987))
                out.minFilter = static_cast<unsigned>(smp.minFilter);
        }
        auto it = extensions.find("KHR_texture_transform");
        if (it != extensions.end()) {
            const auto& e = it->second;
            const glm::vec4 offset = vector(e, "offset", glm::vec4(0.0f), 2);
            const glm::vec4 scale = vector(e, "scale", glm::vec4(1.0f), 2);
            out.offset = glm::vec2(offset);
            out.scale = glm::vec2(scale);
            out.rotation = static_cast<float>(number(e, "rotation", 0.0));
            if (e.Has("texCoord") && e.Get("texCoord").IsNumber()) out.texCoord = e.Get("texCoord").GetNumberAsInt();
        }
        if (out.texCoord != 0 && out.texCoord != 1) {
            ignoredUvSets_ = true;
            out.texCoord = 0;
        }
        return out;
    }

    static glm::vec3 vec3Of(const std::vector<double>& v, glm::vec3 fallback) {
        return v.size() >= 3 ? glm::vec3(v[0], v[1], v[2]) : fallback;
    }

    void importMaterials() {
        materialBase_ = static_cast<int>(scene_.materials.size());
        for (const auto& m : model_.materials) {
            Material out;
            out.name = m.name;
            out.model = MaterialModel::MetallicRoughness;
            const auto& pbr = m.pbrMetallicRoughness;
            if (pbr.baseColorFactor.size() == 4)
                out.baseColor = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1],
                                          pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
            else
                out.baseColor = glm::vec4(1.0f);
            out.baseColorTexture = imageOfTexture(pbr.baseColorTexture.index);
            out.metallic = static_cast<float>(pbr.metallicFactor);
            out.roughness = static_cast<float>(pbr.roughnessFactor);
            out.metallicRoughnessTexture = imageOfTexture(pbr.metallicRoughnessTexture.index);
            out.specularColor = glm::vec3(0.04f);
            out.normalTexture = imageOfTexture(m.normalTexture.index);
            out.normalScale = static_cast<float>(m.normalTexture.scale);
            out.emissive = vec3Of(m.emissiveFactor, glm::vec3(0.0f));
            out.emissiveTexture = imageOfTexture(m.emissiveTexture.index);
            out.alphaMode = m.alphaMode == "MASK"    ? AlphaMode::Mask
                            : m.alphaMode == "BLEND" ? AlphaMode::Blend
                                                     : AlphaMode::Opaque;
            out.alphaCutoff = static_cast<float>(m.alphaCutoff);
            out.doubleSided = m.doubleSided;
            out.occlusionTexture = imageOfTexture(m.occlusionTexture.index);
            out.occlusionStrength = static_cast<float>(m.occlusionTexture.strength);
            out.mapping[Material::BaseColorSlot] =
                mappingOf(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions);
            out.mapping[Material::NormalSlot] =
                mappingOf(m.normalTexture.index, m.normalTexture.texCoord, m.normalTexture.extensions);
            out.mapping[Material::SpecularSlot] = mappingOf(pbr.metallicRoughnessTexture.index,
                                                            pbr.metallicRoughnessTexture.texCoord,
                                                            pbr.metallicRoughnessTexture.extensions);
            out.mapping[Material::EmissiveSlot] =
                mappingOf(m.emissiveTexture.index, m.emissiveTexture.texCoord, m.emissiveTexture.extensions);
            out.mapping[Material::OcclusionSlot] =
                mappingOf(m.occlusionTexture.index, m.occlusionTexture.texCoord, m.occlusionTexture.extensions);
            applyMaterialExtensions(m, out);
            scene_.addMaterial(std::move(out));
        }
    }

    static double number(const tinygltf::Value& obj, const char* key, double fallback) {
        if (!obj.IsObject() || !obj.Has(key) || !obj.Get(key).IsNumber()) return fallback;
        return obj.Get(key).GetNumberAsDouble();
    }
    static glm::vec4 vector(const tinygltf::Value& obj, const char* key, glm::vec4 fallback, int n) {
        if (!obj.IsObject() || !obj.Has(key) || !obj.Get(key).IsArray()) return fallback;
        const auto& a = obj.Get(key);
        glm::vec4 v = fallback;
        for (int i = 0; i < n && i < static_cast<int>(a.ArrayLen()); ++i)
            if (a.Get(i).IsNumber()) v[i] = static_cast<float>(a.Get(i).GetNumberAsDouble());
        return v;
    }
    // A textureInfo inside a material extension: its image, and its sampling into `mapping`.
    int textureOf(const tinygltf::Value& obj, const char* key, TextureMapping& mapping) const {
        if (!obj.IsObject() || !obj.Has(key) || !obj.Get(key).IsObject()) return -1;
        const auto& t = obj.Get(key);
        if (!t.Has("index") || !t.Get("index").IsNumber()) return -1;
        const int idx = t.Get("index").GetNumberAsInt();
        checkIndex(idx, model_.textures, std::string("material extension texture ") + key);
        const int texCoord = t.Has("texCoord") && t.Get("texCoord").IsNumber() ? t.Get("texCoord").GetNumberAsInt() : 0;
        tinygltf::ExtensionMap ext;
        if (t.Has("extensions") && t.Get("extensions").IsObject() && t.Get("extensions").Has("KHR_texture_transform"))
            ext["KHR_texture_transform"] = t.Get("extensions").Get("KHR_texture_transform");
        mapping = mappingOf(idx, texCoord, ext);
        return imageOfTexture(idx);
    }

    void applyMaterialExtensions(const tinygltf::Material& m, Material& out) const {
        auto it = m.extensions.find("KHR_materials_pbrSpecularGlossiness");
        if (it != m.extensions.end()) {
            const auto& e = it->second;
            out.model = MaterialModel::SpecularGlossiness;
            out.baseColor = vector(e, "diffuseFactor", glm::vec4(1.0f), 4);
            out.baseColorTexture = textureOf(e, "diffuseTexture", out.mapping[Material::BaseColorSlot]);
            out.specularColor = glm::vec3(vector(e, "specularFactor", glm::vec4(1.0f), 3));
            out.glossiness = static_cast<float>(number(e, "glossinessFactor", 1.0));
            out.specularTexture = textureOf(e, "specularGlossinessTexture", out.mapping[Material::SpecularSlot]);
        }
        it = m.extensions.find("KHR_materials_specular");
        if (it != m.extensions.end() && out.model == MaterialModel::MetallicRoughness) {
            // Dielectric F0 = min(0.04 * specularColorFactor, 1) * specularFactor.
            const auto& e = it->second;
            const float factor = static_cast<float>(number(e, "specularFactor", 1.0));
            const glm::vec3 color(vector(e, "specularColorFactor", glm::vec4(1.0f), 3));
            out.specularColor = glm::min(glm::vec3(0.04f) * color, glm::vec3(1.0f)) * factor;
        }
        it = m.extensions.find("KHR_materials_emissive_strength");
        if (it != m.extensions.end()) out.emissive *= static_cast<float>(number(it->second, "emissiveStrength", 1.0));
    }

    void importMeshes() {
        meshMap_.assign(model_.meshes.size(), {});
        for (size_t mi = 0; mi < model_.meshes.size(); ++mi) {
            const auto& mesh = model_.meshes[mi];
            for (size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
                const auto& prim = mesh.primitives[pi];
                const std::string what = "mesh[" + std::to_string(mi) + "] '" + mesh.name + "' primitive " + std::to_string(pi);
                Mesh out;
                if (!buildPrimitive(prim, what, out)) continue;
                out.name = mesh.name.empty() ? "mesh" + std::to_string(mi) : mesh.name;
                if (prim.material >= 0) {
                    out.material = materialBase_ + prim.material;
                } else {
                    out.material = defaultMaterial();
                }
                meshMap_[mi].push_back(scene_.addMesh(std::move(out)));
            }
        }
    }

    int defaultMaterial() {
        if (defaultMaterial_ < 0) {
            Material m;
            m.name = "glTF default";
            m.model = MaterialModel::MetallicRoughness;
            m.baseColor = glm::vec4(1.0f);
            defaultMaterial_ = scene_.addMaterial(m);
        }
        return defaultMaterial_;
    }

    bool buildPrimitive(const tinygltf::Primitive& prim, const std::string& what, Mesh& out) {
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            scene_.warnings.push_back(path_ + ": " + what + " is points or lines; skipped");
            return false;
        }
        auto attr = [&](const char* name) {
            auto it = prim.attributes.find(name);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        const int posAcc = attr("POSITION");
        if (posAcc < 0) fail(what + " has no POSITION attribute");
        const auto pos = readAccessor(posAcc, 3, what + " POSITION");
        const size_t n = pos.size() / 3;
        out.vertices.resize(n);
        for (size_t i = 0; i < n; ++i) out.vertices[i].position = glm::vec3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]);
        auto sameCount = [&](int acc, const char* name) {
            if (model_.accessors[acc].count != n)
                fail(what + " " + name + " has " + std::to_string(model_.accessors[acc].count) +
                     " elements but POSITION has " + std::to_string(n));
        };
        const int nrmAcc = attr("NORMAL"), tanAcc = attr("TANGENT"), uvAcc = attr("TEXCOORD_0");
        const int uv1Acc = attr("TEXCOORD_1"), colorAcc = attr("COLOR_0");
        if (uvAcc >= 0) {
            sameCount(uvAcc, "TEXCOORD_0");
            const auto uv = readAccessor(uvAcc, 2, what + " TEXCOORD_0");
            for (size_t i = 0; i < n; ++i) out.vertices[i].uv = glm::vec2(uv[2 * i], uv[2 * i + 1]);
        }
        if (uv1Acc >= 0) {
            sameCount(uv1Acc, "TEXCOORD_1");
            const auto uv = readAccessor(uv1Acc, 2, what + " TEXCOORD_1");
            for (size_t i = 0; i < n; ++i) out.vertices[i].uv1 = glm::vec2(uv[2 * i], uv[2 * i + 1]);
        }
        if (colorAcc >= 0) {
            // VEC3 or VEC4, float or normalised unsigned byte / short (spec 3.7.2.1); alpha 1 for VEC3.
            sameCount(colorAcc, "COLOR_0");
            const int comps = model_.accessors[colorAcc].type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
            const auto c = readAccessor(colorAcc, comps, what + " COLOR_0");
            for (size_t i = 0; i < n; ++i)
                out.vertices[i].color = glm::vec4(c[comps * i], c[comps * i + 1], c[comps * i + 2], comps == 4 ? c[4 * i + 3] : 1.0);
        }
        // Indices, converted to a triangle list.
        std::vector<uint32_t> idx;
        if (prim.indices >= 0) {
            const auto& a = model_.accessors[prim.indices];
            if (a.type != TINYGLTF_TYPE_SCALAR ||
                (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                 a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                 a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                fail(what + " indices (accessor[" + std::to_string(prim.indices) + "]) are not unsigned scalars");
            const auto raw = readAccessor(prim.indices, 1, what + " indices");
            idx.reserve(raw.size());
            for (double d : raw) {
                if (d >= static_cast<double>(n))
                    fail(what + " index " + std::to_string(static_cast<long long>(d)) + " is out of range (" +
                         std::to_string(n) + " vertices)");
                idx.push_back(static_cast<uint32_t>(d));
            }
        } else {
            idx.resize(n);
            for (size_t i = 0; i < n; ++i) idx[i] = static_cast<uint32_t>(i);
        }
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            idx.resize(idx.size() - idx.size() % 3);
            out.indices = std::move(idx);
        } else {
            for (size_t i = 2; i < idx.size(); ++i) {
                if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
                    if (i % 2 == 0) out.indices.insert(out.indices.end(), {idx[i - 2], idx[i - 1], idx[i]});
                    else out.indices.insert(out.indices.end(), {idx[i - 1], idx[i - 2], idx[i]});
                } else {
                    out.indices.insert(out.indices.end(), {idx[0], idx[i - 1], idx[i]});
                }
            }
        }
        if (out.indices.empty()) {
            scene_.warnings.push_back(path_ + ": " + what + " has no triangles; skipped");
            return false;
        }
        if (nrmAcc >= 0) {
            // Normals that are not finite or have no length are regenerated
            // (one warning): real files ship a few, and refusing the file for
            // them helps nobody; non-finite positions stay an error.
            sameCount(nrmAcc, "NORMAL");
            const auto nrm = readAccessor(nrmAcc, 3, what + " NORMAL", true);
            std::vector<bool> broken(n, false);
            for (size_t i = 0; i < n; ++i) {
                const glm::dvec3 v(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]);
                const double len = glm::length(v);
                if (std::isfinite(len) && len > 1e-12) out.vertices[i].normal = glm::vec3(v / len);
                else broken[i] = true;
            }
            const size_t repaired = std::count(broken.begin(), broken.end(), true) > 0 ? repairNormals(out, broken) : 0;
            if (repaired > 0)
                scene_.warnings.push_back(path_ + ": " + what + " NORMAL (accessor[" + std::to_string(nrmAcc) + "]) has " +
                                          std::to_string(repaired) +
                                          " non-finite or zero-length normals; regenerated from the faces around them");
            const size_t reversed = orientTrianglesToNormals(out);
            if (reversed > 0)
                scene_.warnings.push_back(path_ + ": " + what + " has " + std::to_string(reversed) +
                                          " triangle(s) wound against their vertex normals; turned around");
            const size_t corners = splitCornersFacingAway(out);
            if (corners > 0)
                scene_.warnings.push_back(path_ + ": " + what + " has " + std::to_string(corners) +
                                          " triangle corner(s) whose normal points away from the triangle; given the face normal");
        } else {
            generateFlatNormals(out);
        }
        bool haveTangents = false;
        if (tanAcc >= 0) {
            sameCount(tanAcc, "TANGENT");
            const auto t = readAccessor(tanAcc, 4, what + " TANGENT", true);
            size_t broken = 0;
            for (size_t i = 0; i < n; ++i) {
                const glm::dvec4 v(t[4 * i], t[4 * i + 1], t[4 * i + 2], t[4 * i + 3]);
                const double len = glm::length(glm::dvec3(v));
                if (!std::isfinite(len) || !std::isfinite(v.w) || len <= 1e-12) ++broken;
            }
            if (broken > 0) {
                scene_.warnings.push_back(path_ + ": " + what + " TANGENT (accessor[" + std::to_string(tanAcc) + "]) has " +
                                          std::to_string(broken) +
                                          " non-finite or zero-length tangents; the primitive's tangents are regenerated");
            } else {
                for (size_t i = 0; i < n; ++i)
                    out.vertices[i].tangent = glm::vec4(t[4 * i], t[4 * i + 1], t[4 * i + 2], t[4 * i + 3] < 0 ? -1.0 : 1.0);
                haveTangents = true;
            }
        }
        if (!haveTangents) generateTangents(out, UvConvention::GltfVDown);
        out.computeBounds();
        return true;
    }

    // ---- node hierarchy
    static glm::mat4 localTransform(const tinygltf::Node& n) {
        if (n.matrix.size() == 16) {
            glm::dmat4 m = glm::make_mat4(n.matrix.data());
            return glm::mat4(m);
        }
        glm::mat4 t(1.0f);
        if (n.translation.size() == 3) t = glm::translate(t, glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
        if (n.rotation.size() == 4) {
            const glm::quat q(static_cast<float>(n.rotation[3]), static_cast<float>(n.rotation[0]),
                              static_cast<float>(n.rotation[1]), static_cast<float>(n.rotation[2]));
            t *= glm::mat4_cast(glm::normalize(q));
        }
        if (n.scale.size() == 3) t = glm::scale(t, glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
        return t;
    }

    void walkScene(const glm::mat4& root, bool lightsAndCamera, GltfImport& result) {
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            const int s = model_.defaultScene >= 0 && model_.defaultScene < static_cast<int>(model_.scenes.size())
                              ? model_.defaultScene : 0;
            roots = model_.scenes[s].nodes;
        } else {
            std::vector<bool> isChild(model_.nodes.size(), false);
            for (const auto& n : model_.nodes)
                for (int c : n.children) isChild[c] = true;
            for (size_t i = 0; i < model_.nodes.size(); ++i)
                if (!isChild[i]) roots.push_back(static_cast<int>(i));
        }
        std::function<void(int, const glm::mat4&)> visit = [&](int ni, const glm::mat4& parent) {
            const auto& node = model_.nodes[ni];
            const glm::mat4 world = parent * localTransform(node);
            if (node.mesh >= 0) {
                for (int m : meshMap_[node.mesh]) {
                    scene_.instances.push_back({m, world});
                    result.bounds.add(scene_.meshes[m].bounds.transformed(world));
                }
            }
            if (lightsAndCamera) {
                importNodeLight(node, world, result);
                if (node.camera >= 0 && !result.hasCamera) importCamera(model_.cameras[node.camera], world, result);
            }
            for (int c : node.children) visit(c, world);
        };
        for (int r : roots) visit(r, root);
    }

    // The unit vector along world * axis; none when the transform has no
    // extent along it (zero scale) or is not finite. Scaled by the largest
    // component first, so tiny or huge scales neither underflow nor overflow.
    static std::optional<glm::vec3> unitAxis(const glm::mat4& world, const glm::vec4& axis) {
        const glm::vec3 v(world * axis);
        const float m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
        if (!(m > 0.0f) || !std::isfinite(m)) return std::nullopt;
        return glm::normalize(v / m);
    }

    void importNodeLight(const tinygltf::Node& node, const glm::mat4& world, GltfImport& result) {
        auto it = node.extensions.find("KHR_lights_punctual");
        if (it == node.extensions.end() || !it->second.Has("light")) return;
        const int li = it->second.Get("light").GetNumberAsInt();
        checkIndex(li, model_.lights, "node KHR_lights_punctual.light", false);
        const auto& l = model_.lights[li];
        Light out;
        out.name = l.name.empty() ? "light" + std::to_string(li) : l.name;
        const glm::vec3 color = l.color.size() >= 3 ? glm::vec3(l.color[0], l.color[1], l.color[2]) : glm::vec3(1.0f);
        out.intensity = color * static_cast<float>(l.intensity);
        out.position = glm::vec3(world[3]);
        const auto along = unitAxis(world, glm::vec4(0, 0, -1, 0));
        if (!along && l.type != "point")
            fail("light " + std::to_string(li) + " ('" + out.name + "'): its node's transform has zero scale, so the light has no direction");
        if (!std::isfinite(out.position.x + out.position.y + out.position.z))
            fail("light " + std::to_string(li) + " ('" + out.name + "'): its node's transform puts it beyond 32-bit float range");
        out.direction = along.value_or(glm::vec3(0, 0, -1));
        // glTF punctual lights fall off as 1/d^2 (candela units are kept as they are).
        out.attenuation = {0.0f, 0.0f, 1.0f};
        if (l.type == "directional") {
            out.type = LightType::Directional;
        } else if (l.type == "spot") {
            out.type = LightType::Spot;
            // GltfCheck allows pi/2 rounded to a float; the cone itself stops at pi/2.
            const double outer = l.spot.outerConeAngle > 0 ? std::min(l.spot.outerConeAngle, glm::half_pi<double>())
                                                           : glm::pi<double>() / 4.0;
            const double inner = std::clamp(l.spot.innerConeAngle, 0.0, outer);
            out.cutoffDegrees = static_cast<float>(glm::degrees(outer));
            // Half intensity halfway between the inner and outer cone angles.
            const double mid = std::cos(0.5 * (inner + outer));
            out.exponent = mid < 0.999999 ? static_cast<float>(std::log(0.5) / std::log(mid)) : 0.0f;
        } else {
            out.type = LightType::Point;
        }
        scene_.lights.push_back(out);
        ++result.lightCount;
    }

    void importCamera(const tinygltf::Camera& cam, const glm::mat4& world, GltfImport& result) {
        if (cam.type != "perspective") return;
        Camera c;
        const std::string name = "camera[" + std::to_string(&cam - model_.cameras.data()) + "]";
        const auto forward = unitAxis(world, glm::vec4(0, 0, -1, 0)), up = unitAxis(world, glm::vec4(0, 1, 0, 0));
        if (!forward || !up)
            fail(name + ": its node's transform has zero scale (or overflows), so the camera has no view direction");
        c.position = glm::vec3(world[3]);
        c.target = c.position + *forward;
        c.up = *up;
        c.fovYDegrees = static_cast<float>(glm::degrees(cam.perspective.yfov));
        c.nearPlane = static_cast<float>(cam.perspective.znear > 0 ? cam.perspective.znear : 0.05);
        c.farPlane = static_cast<float>(cam.perspective.zfar > c.nearPlane ? cam.perspective.zfar
                                                                     : std::max(1000.0, c.nearPlane * 1e4));
        if (const auto problem = findCameraProblem(c, 0.0f)) fail(name + " (as placed by its node): " + problem->field + " " + problem->what);
        scene_.camera = c;
        result.hasCamera = true;
    }

    // One warning line naming every rule of the glTF 2.0 spec the file breaks
    // in a way the importer reads past (so the file still draws, but a user
    // learns that the file, not the workbench, is wrong), apart from the
    // valid features the workbench does not support (warnIgnored).
    void warnInvalid() {
        if (invalid_.empty()) return;
        std::string line = path_ + ": invalid glTF (drawn anyway): ";
        for (size_t i = 0; i < invalid_.size(); ++i) line += (i ? "; " : "") + invalid_[i];
        scene_.warnings.push_back(line);
    }

    // One warning line naming everything the file uses that the workbench
    // does not draw, so a user knows why the picture differs from a viewer's.
    void warnIgnored() {
        std::vector<std::string> parts;
        if (!model_.skins.empty()) parts.push_back(std::to_string(model_.skins.size()) + " skin(s)");
        size_t morphed = 0;
        for (const auto& m : model_.meshes)
            for (const auto& p : m.primitives) morphed += p.targets.empty() ? 0 : 1;
        if (morphed > 0) parts.push_back("morph targets on " + std::to_string(morphed) + " primitive(s)");
        if (!model_.animations.empty()) parts.push_back(std::to_string(model_.animations.size()) + " animation(s)");
        size_t blended = 0;
        for (const auto& m : model_.materials) blended += m.alphaMode == "BLEND" ? 1 : 0;
        if (blended > 0) parts.push_back("alpha mode BLEND on " + std::to_string(blended) + " material(s), drawn opaque");
        if (ignoredUvSets_) parts.push_back("texture coordinate sets beyond TEXCOORD_1 (TEXCOORD_0 used)");
        for (const auto& ext : model_.extensionsUsed)
            if (!isSupportedExtension(ext)) parts.push_back("extension " + ext);
        if (parts.empty()) return;
        std::string line = path_ + ": ignored (not supported by the workbench): ";
        for (size_t i = 0; i < parts.size(); ++i) line += (i ? ", " : "") + parts[i];
        scene_.warnings.push_back(line);
    }

    struct HiddenIndices {
        std::size_t mesh, primitive;
        int accessor;
    };

    std::string path_;
    Scene& scene_;
    tinygltf::Model model_;
    std::vector<HiddenIndices> hiddenIndices_;
    std::vector<std::string> invalid_;  // spec rules broken but read past (warnInvalid)
    mutable bool ignoredUvSets_ = false;
    std::string imageError_;
    int imageBase_ = 0, materialBase_ = 0, defaultMaterial_ = -1;
    std::vector<std::vector<int>> meshMap_;
};

}  // namespace

GltfImport importGltf(const std::string& path, Scene& scene, const glm::mat4& rootTransform,
                      bool importLightsAndCamera) {
    Importer importer(path, scene);
    return importer.import(rootTransform, importLightsAndCamera);
}

}  // namespace dw
