#include "renderer/scene/GltfLoader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <filesystem>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <new>
#include <nlohmann/json.hpp>
#include <string_view>

#include "renderer/Error.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"
#include "renderer/scene/GltfAccessors.h"
#include "renderer/scene/GltfAnimation.h"
#include "renderer/scene/GltfCheck.h"
#include "renderer/scene/GltfLights.h"
#include "renderer/scene/GltfMaterials.h"
#include "renderer/scene/GltfModelCheck.h"
#include "renderer/scene/GltfSchema.h"
#include "renderer/scene/NormalGenerator.h"
#include "renderer/scene/ScenePose.h"
#include "renderer/scene/TangentGenerator.h"

namespace dw {

namespace fs = std::filesystem;

namespace {

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
        // Nesting depth, numbers beyond a float by JSON path (integer
        // properties beyond a float named as integers, GltfSchema.h), then the parse.
        JsonGuardOptions guard;
        guard.integerProblem = gltfIntegerProblem;
        nlohmann::json j = parseJson(text, path_, guard);
        if (!j.is_object()) fail("not a glTF file: the top level is not a JSON object");
        GltfContainer container;
        container.glb = glb;
        if (glb) container.binLength = glbBinLength(bytes);
        checkGltfValues(j, path_, &invalid_, container);  // schema, buffers, cameras, lights, data: URIs (GltfCheck.h)
        noteExternalUris(j);
        if (j.contains("extensionsRequired") && j["extensionsRequired"].is_array()) {
            for (const auto& e : j["extensionsRequired"])
                if (e.is_string() && !GltfModelCheck::isSupportedExtension(e.get<std::string>()))
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

    // The buffers' and images' external URIs, for the record (Scene::gltfExternalUris).
    void noteExternalUris(const nlohmann::json& j) {
        std::vector<std::string>& uris = scene_.gltfExternalUris[fs::path(path_).lexically_normal().string()];
        uris.clear();
        for (const char* key : {"buffers", "images"})
            if (j.contains(key) && j[key].is_array())
                for (const auto& item : j[key])
                    if (item.is_object() && item.contains("uri") && item["uri"].is_string()) {
                        const std::string u = item["uri"].get<std::string>();
                        if (!u.empty() && u.rfind("data:", 0) != 0) uris.push_back(u);
                    }
    }

    // glTF 2.0 (3.6.2.3): an accessor without bufferView holds zeros (plus its
    // sparse values). tinygltf 2.7 parses such accessors but refuses a
    // primitive whose *indices* use one ("invalid bufferView", in its pass that
    // assigns bufferView targets). So those primitives' "indices" are removed
    // from the JSON tinygltf sees, remembered, and put back after parsing
    // (restoreZeroIndexAccessors); GltfAccessorReader supplies the zeros.
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

    void load() {
        const std::string bytes = precheck(readWholeFile(path_, "file not found", "cannot open file", kBinaryFileLimit));
        tinygltf::TinyGLTF loader;
        loader.SetImageLoader(&GltfMaterialImporter::decodeImageCallback, &materials_);
        // Existence by stat: tinygltf's own FileExists opens the file, which
        // waits forever on a pipe with no writer.
        const tinygltf::FileExistsFunction exists = [](const std::string& p, void*) {
            std::error_code ec;
            return std::filesystem::exists(p, ec);
        };
        loader.SetFsCallbacks({exists, &tinygltf::ExpandFilePath,
                               &GltfMaterialImporter::readExternalFileCallback, &tinygltf::WriteWholeFile, &materials_});
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
        if (!materials_.imageError().empty()) fail(materials_.imageError());
        if (!ok) fail("not a valid glTF 2.0 file: " + firstLines(err.empty() ? warn : err));
        restoreZeroIndexAccessors();
    }

    GltfImport import(const glm::mat4& root, bool lightsAndCamera) {
        load();
        const GltfModelCheck check(model_, path_);  // the parsed model's checks, one checker for all three
        check.validate();
        check.noteInvalid(invalid_);
        materials_.importImages();
        materials_.importMaterials();
        animation_.begin(root);
        importMeshes();
        GltfImport result;
        const std::size_t firstInstance = scene_.instances.size();
        walkScene(root, lightsAndCamera, result);
        animation_.finish();
        // Every reader of the scene sees the pose at t = 0 until posed again,
        // the camera framing it included.
        if (poseScene(scene_, 0.0)) {
            result.bounds = Bounds{};
            for (std::size_t i = firstInstance; i < scene_.instances.size(); ++i)
                result.bounds.add(scene_.meshes[scene_.instances[i].mesh].bounds.transformed(scene_.instances[i].transform));
        }
        warnInvalid();
        warnIgnored(check);
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

    // ---- meshes (spec 3.7.2 "Meshes"): each triangle primitive one Mesh
    void importMeshes() {
        meshMap_.assign(model_.meshes.size(), {});
        for (size_t mi = 0; mi < model_.meshes.size(); ++mi) {
            const auto& mesh = model_.meshes[mi];
            for (size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
                const auto& prim = mesh.primitives[pi];
                const std::string what = "mesh[" + std::to_string(mi) + "] '" + mesh.name + "' primitive " + std::to_string(pi);
                Mesh out;
                std::vector<std::uint32_t> origins;
                const bool deforms = animation_.deforms(prim);
                if (!buildPrimitive(prim, what, out, deforms ? &origins : nullptr)) continue;
                out.name = mesh.name.empty() ? "mesh" + std::to_string(mi) : mesh.name;
                out.material = materials_.sceneMaterial(prim.material);
                meshMap_[mi].push_back(scene_.addMesh(std::move(out)));
                if (deforms) animation_.notePrimitive(prim, meshMap_[mi].back(), origins, what);
            }
        }
    }

    // The primitive as a triangle mesh with normals and tangents; false (with
    // a warning) when it has none: points, lines, or too few indices.
    // Every per-vertex attribute (TEXCOORD_n, COLOR_0, TANGENT) is read into
    // out.vertices, and its count checked against POSITION's, before any step
    // that adds vertices: splitting a corner whose normal faces away, flat
    // normals and tangent generation copy whole Vertex records, so an added
    // vertex carries every attribute of the one it came from. (Tangents read
    // after the split were counted against the grown vertex list and the
    // file refused.) An attribute added to Vertex later is read here too.
    // `origins`, when given, receives which file vertex each vertex of `out`
    // was copied from (skins and morph targets are per file vertex).
    bool buildPrimitive(const tinygltf::Primitive& prim, const std::string& what, Mesh& out,
                        std::vector<std::uint32_t>* origins = nullptr) {
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            scene_.warnings.push_back(path_ + ": " + what + " is points or lines; skipped");
            return false;
        }
        const size_t n = readPositions(prim, what, out);
        readTexCoordsAndColour(prim, what, out);
        std::vector<glm::vec4> colours;
        if (origins) colours = tagOrigins(out);
        const bool fileTangents = readTangents(prim, what, out);
        toTriangleList(mode, readIndices(prim, what, n), out);
        if (out.indices.empty()) {
            scene_.warnings.push_back(path_ + ": " + what + " has no triangles; skipped");
            return false;
        }
        const bool fileNormals = readNormals(prim, what, out);
        // glTF 2.0 3.7.2.1: without NORMAL the flat normals are computed and
        // "the provided tangents (if present) MUST be ignored".
        if (!fileTangents || !fileNormals) generateTangents(out, UvConvention::GltfVDown);
        if (origins) *origins = untagOrigins(out, colours);
        out.computeBounds();
        return true;
    }

    // The steps after reading copy whole Vertex records when they add a
    // vertex and never read the colour: the file vertex's index rides in
    // colour.r (exact below 2^24) and comes out after them. Returns the colours.
    std::vector<glm::vec4> tagOrigins(Mesh& out) const {
        if (out.vertices.size() >= (std::size_t(1) << 24)) fail("a skinned or morphed primitive has 2^24 vertices or more");
        std::vector<glm::vec4> colours;
        colours.reserve(out.vertices.size());
        for (std::size_t i = 0; i < out.vertices.size(); ++i) {
            colours.push_back(out.vertices[i].color);
            out.vertices[i].color.r = static_cast<float>(i);
        }
        return colours;
    }
    static std::vector<std::uint32_t> untagOrigins(Mesh& out, const std::vector<glm::vec4>& colours) {
        std::vector<std::uint32_t> origins(out.vertices.size());
        for (std::size_t i = 0; i < out.vertices.size(); ++i) {
            origins[i] = static_cast<std::uint32_t>(out.vertices[i].color.r);
            out.vertices[i].color = colours[origins[i]];
        }
        return origins;
    }

    // The accessor of the primitive's attribute `name`, or -1.
    static int attribute(const tinygltf::Primitive& prim, const char* name) {
        auto it = prim.attributes.find(name);
        return it == prim.attributes.end() ? -1 : it->second;
    }

    // Every attribute has as many elements as POSITION (spec 3.7.2.1): the
    // accessors' counts, whatever vertices the importer has added since.
    void requireVertexCount(int accessor, const char* name, const std::string& what,
                            const tinygltf::Primitive& prim) const {
        const size_t n = model_.accessors[static_cast<size_t>(attribute(prim, "POSITION"))].count;
        if (model_.accessors[accessor].count != n)
            fail(what + " " + name + " has " + std::to_string(model_.accessors[accessor].count) +
                 " elements but POSITION has " + std::to_string(n));
    }

    // The vertices, from POSITION (required, finite); returns their number.
    size_t readPositions(const tinygltf::Primitive& prim, const std::string& what, Mesh& out) const {
        const int posAcc = attribute(prim, "POSITION");
        if (posAcc < 0) fail(what + " has no POSITION attribute");
        const auto pos = accessors_.read(posAcc, 3, what + " POSITION");
        const size_t n = pos.size() / 3;
        out.vertices.resize(n);
        for (size_t i = 0; i < n; ++i) out.vertices[i].position = glm::vec3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]);
        return n;
    }

    // TEXCOORD_0, TEXCOORD_1 and COLOR_0, when the primitive has them.
    void readTexCoordsAndColour(const tinygltf::Primitive& prim, const std::string& what, Mesh& out) const {
        const size_t n = out.vertices.size();
        const int uvAcc = attribute(prim, "TEXCOORD_0"), uv1Acc = attribute(prim, "TEXCOORD_1");
        const int colorAcc = attribute(prim, "COLOR_0");
        if (uvAcc >= 0) {
            requireVertexCount(uvAcc, "TEXCOORD_0", what, prim);
            const auto uv = accessors_.read(uvAcc, 2, what + " TEXCOORD_0");
            for (size_t i = 0; i < n; ++i) out.vertices[i].uv = glm::vec2(uv[2 * i], uv[2 * i + 1]);
        }
        if (uv1Acc >= 0) {
            requireVertexCount(uv1Acc, "TEXCOORD_1", what, prim);
            const auto uv = accessors_.read(uv1Acc, 2, what + " TEXCOORD_1");
            for (size_t i = 0; i < n; ++i) out.vertices[i].uv1 = glm::vec2(uv[2 * i], uv[2 * i + 1]);
        }
        if (colorAcc >= 0) {
            // VEC3 or VEC4, float or normalised unsigned byte / short (spec 3.7.2.1); alpha 1 for VEC3.
            requireVertexCount(colorAcc, "COLOR_0", what, prim);
            const int comps = model_.accessors[colorAcc].type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
            const auto c = accessors_.read(colorAcc, comps, what + " COLOR_0");
            for (size_t i = 0; i < n; ++i)
                out.vertices[i].color = glm::vec4(c[comps * i], c[comps * i + 1], c[comps * i + 2], comps == 4 ? c[4 * i + 3] : 1.0);
        }
    }

    // The primitive's indices (unsigned scalars below the vertex count `n`),
    // or 0 to n - 1 when it has none.
    std::vector<uint32_t> readIndices(const tinygltf::Primitive& prim, const std::string& what, size_t n) const {
        std::vector<uint32_t> idx;
        if (prim.indices >= 0) {
            const auto& a = model_.accessors[prim.indices];
            if (a.type != TINYGLTF_TYPE_SCALAR ||
                (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                 a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                 a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                fail(what + " indices (accessor[" + std::to_string(prim.indices) + "]) are not unsigned scalars");
            const auto raw = accessors_.read(prim.indices, 1, what + " indices");
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
        return idx;
    }

    // Triangles, strips and fans as one triangle list in out.indices (a strip's
    // odd triangles turned to keep the winding, spec 3.7.2.1).
    static void toTriangleList(int mode, std::vector<uint32_t> idx, Mesh& out) {
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
    }

    // NORMAL, repaired where broken (with warnings), or flat normals without
    // it; returns whether the file has NORMAL. May add vertices (copies).
    bool readNormals(const tinygltf::Primitive& prim, const std::string& what, Mesh& out) {
        const size_t n = out.vertices.size();
        const int nrmAcc = attribute(prim, "NORMAL");
        if (nrmAcc >= 0) {
            // Normals that are not finite or have no length are regenerated
            // (one warning): real files ship a few, and refusing the file for
            // them helps nobody; non-finite positions stay an error.
            requireVertexCount(nrmAcc, "NORMAL", what, prim);
            const auto nrm = accessors_.read(nrmAcc, 3, what + " NORMAL", true);
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
            return true;
        }
        generateFlatNormals(out);
        return false;
    }

    // TANGENT into out.vertices when all of it is usable; false when the
    // primitive has none or a broken one (with a warning), to be generated.
    bool readTangents(const tinygltf::Primitive& prim, const std::string& what, Mesh& out) {
        const size_t n = out.vertices.size();
        const int tanAcc = attribute(prim, "TANGENT");
        bool haveTangents = false;
        if (tanAcc >= 0) {
            requireVertexCount(tanAcc, "TANGENT", what, prim);
            const auto t = accessors_.read(tanAcc, 4, what + " TANGENT", true);
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
        return haveTangents;
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
        GltfLightImporter lights(model_, path_, scene_);
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
                    animation_.noteInstance(ni, static_cast<int>(scene_.instances.size() - 1));
                    result.bounds.add(scene_.meshes[m].bounds.transformed(world));
                }
            }
            if (lightsAndCamera) {
                lights.importNodeLight(node, world, result);
                if (node.camera >= 0 && !result.hasCamera) lights.importCamera(model_.cameras[node.camera], world, result);
            }
            for (int c : node.children) visit(c, world);
        };
        for (int r : roots) visit(r, root);
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
    void warnIgnored(const GltfModelCheck& check) {
        const std::vector<std::string> parts = check.ignoredFeatures(materials_.ignoredUvSets());
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
    GltfAccessorReader accessors_{model_, path_};
    GltfMaterialImporter materials_{model_, path_, scene_};  // also tinygltf's image loader
    GltfAnimationImporter animation_{model_, path_, scene_, accessors_};
    std::vector<std::vector<int>> meshMap_;
};

}  // namespace

GltfImport importGltf(const std::string& path, Scene& scene, const glm::mat4& rootTransform,
                      bool importLightsAndCamera) {
    Importer importer(path, scene);
    return importer.import(rootTransform, importLightsAndCamera);
}

}  // namespace dw
