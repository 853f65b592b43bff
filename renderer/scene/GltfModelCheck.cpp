#include "renderer/scene/GltfModelCheck.h"

#include <algorithm>
#include <cmath>

#include "renderer/scene/GltfAccessors.h"
#include "renderer/scene/GltfCheck.h"
#include "renderer/scene/GltfMaterials.h"

namespace dw {

bool GltfModelCheck::isSupportedExtension(const std::string& ext) {
    // KHR_mesh_quantization: GltfAccessorReader reads every component type, normalised or not.
    static const char* supported[] = {"KHR_lights_punctual", "KHR_materials_pbrSpecularGlossiness",
                                      "KHR_materials_specular", "KHR_materials_emissive_strength",
                                      "KHR_texture_transform", "KHR_mesh_quantization", "EXT_texture_webp"};
    return std::find(std::begin(supported), std::end(supported), ext) != std::end(supported);
}

// Runs one object's checks; its first problem goes into `problems` (without
// the file name) and the other objects are still checked.
template <typename F>
void GltfModelCheck::collect(std::vector<std::string>& problems, F check) const {
    try {
        check();
    } catch (const FileError& e) {
        const std::string text = e.what();
        problems.push_back(text.rfind(path_ + ": ", 0) == 0 ? text.substr(path_.size() + 2) : text);
    }
}

void GltfModelCheck::validate() const {
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
        collect(problems, [&] { GltfAccessorReader(model_, path_).check(static_cast<int>(i)); });
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
        checkIndex(GltfMaterialImporter::webpSource(model_.textures[i]), model_.images,
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
        // Alpha has one rule in every scene format: scene JSON refuses an
        // opacity outside [0, 1], so glTF does too (clamping it would silently
        // turn 1.5 into opaque and -0.5 into invisible).
        const auto& f = m.pbrMetallicRoughness.baseColorFactor;
        if (f.size() == 4 && !(f[3] >= 0.0 && f[3] <= 1.0))
            fail(what + ".pbrMetallicRoughness.baseColorFactor[3] (alpha): must be between 0 (invisible) and 1 (opaque), got " +
                 std::to_string(f[3]));
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
// stop the file from drawing (the animation importer skips a skin or morph
// target it cannot use): named for the "invalid glTF (drawn anyway)" warning.
void GltfModelCheck::noteInvalid(std::vector<std::string>& invalid) const {
    auto targetCount = [&](size_t mesh) { return model_.meshes[mesh].primitives.empty() ? size_t(0)
                                                                                           : model_.meshes[mesh].primitives[0].targets.size(); };
    for (size_t m = 0; m < model_.meshes.size(); ++m) {
        const auto& mesh = model_.meshes[m];
        const std::string what = "meshes[" + std::to_string(m) + "]";
        for (size_t p = 1; p < mesh.primitives.size(); ++p)
            if (mesh.primitives[p].targets.size() != targetCount(m)) {
                invalid.push_back(what + ": primitive 0 has " + std::to_string(targetCount(m)) + " morph target(s), primitive " +
                                   std::to_string(p) + " " + std::to_string(mesh.primitives[p].targets.size()) +
                                   " (spec: every primitive of a mesh has the same number)");
                break;
            }
        if (!mesh.weights.empty() && mesh.weights.size() != targetCount(m))
            invalid.push_back(what + ".weights: " + std::to_string(mesh.weights.size()) + " weight(s) for " +
                               std::to_string(targetCount(m)) + " morph target(s) (spec: one weight per morph target)");
    }
    for (size_t i = 0; i < model_.skins.size(); ++i)
        for (int joint : model_.skins[i].joints)
            if (joint < 0 || static_cast<size_t>(joint) >= model_.nodes.size()) {
                invalid.push_back("skins[" + std::to_string(i) + "].joints: refers to node " + std::to_string(joint) +
                                   " but there are only " + std::to_string(model_.nodes.size()));
                break;
            }
    for (size_t i = 0; i < model_.nodes.size(); ++i) {
        const auto& n = model_.nodes[i];
        const std::string what = "nodes[" + std::to_string(i) + "]";
        if (n.skin >= 0) {
            if (static_cast<size_t>(n.skin) >= model_.skins.size())
                invalid.push_back(what + ".skin: refers to skin " + std::to_string(n.skin) + " but there are only " +
                                   std::to_string(model_.skins.size()));
            else if (n.mesh < 0)
                invalid.push_back(what + ": has skin " + std::to_string(n.skin) +
                                   " but no mesh (spec: a node with a skin has a mesh)");
            else
                for (size_t p = 0; p < model_.meshes[n.mesh].primitives.size(); ++p) {
                    const auto& attrs = model_.meshes[n.mesh].primitives[p].attributes;
                    if (attrs.count("JOINTS_0") && attrs.count("WEIGHTS_0")) continue;
                    invalid.push_back(what + ": has skin " + std::to_string(n.skin) + " but mesh " + std::to_string(n.mesh) +
                                       " primitive " + std::to_string(p) +
                                       " has no JOINTS_0 and WEIGHTS_0 (spec: the primitives of a skinned node's mesh have both)");
                    break;
                }
        }
        if (!n.weights.empty()) {
            if (n.mesh < 0)
                invalid.push_back(what + ".weights: set on a node without a mesh (spec: weights need a mesh)");
            else if (n.weights.size() != targetCount(static_cast<size_t>(n.mesh)))
                invalid.push_back(what + ".weights: " + std::to_string(n.weights.size()) + " weight(s) for the " +
                                   std::to_string(targetCount(static_cast<size_t>(n.mesh))) + " morph target(s) of mesh " +
                                   std::to_string(n.mesh) + " (spec: one weight per morph target)");
        }
    }
    // Materials (spec: "Materials"): what the workbench does instead is said.
    for (size_t i = 0; i < model_.materials.size(); ++i) {
        const auto& mat = model_.materials[i];
        const std::string what = "materials[" + std::to_string(i) + "]";
        if (mat.alphaMode != "OPAQUE" && mat.alphaMode != "MASK" && mat.alphaMode != "BLEND")
            invalid.push_back(what + ".alphaMode: '" + mat.alphaMode + "' is not OPAQUE, MASK or BLEND (drawn as OPAQUE)");
        const auto& f = mat.pbrMetallicRoughness.baseColorFactor;
        for (size_t c = 0; c < f.size() && c < 3; ++c)  // alpha (3) outside [0, 1] is refused above
            if (!(f[c] >= 0.0 && f[c] <= 1.0)) {
                invalid.push_back(what + ".pbrMetallicRoughness.baseColorFactor[" + std::to_string(c) + "]: " +
                                  std::to_string(f[c]) + " is outside [0, 1] (clamped)");
                break;
            }
    }
}

void GltfModelCheck::checkNodeGraph() const {
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

std::vector<std::string> GltfModelCheck::ignoredFeatures(bool ignoredUvSets) const {
    std::vector<std::string> parts;
    if (ignoredUvSets) parts.push_back("texture coordinate sets beyond TEXCOORD_1 (TEXCOORD_0 used)");
    // KHR_lights_punctual's range (a distance where a light stops): the
    // light volumes end where the 1/d^2 falloff drops under
    // lighting.threshold, whatever the range says.
    size_t ranged = 0;
    for (const auto& l : model_.lights) ranged += l.range > 0.0 ? 1 : 0;
    if (ranged > 0)
        parts.push_back("KHR_lights_punctual range on " + std::to_string(ranged) +
                        " light(s) (they fall off as 1/d^2 to the lighting.threshold volume)");
    for (const auto& ext : model_.extensionsUsed)
        if (!isSupportedExtension(ext)) parts.push_back("extension " + ext);
    return parts;
}

}  // namespace dw
