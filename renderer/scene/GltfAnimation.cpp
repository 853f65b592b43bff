#include "renderer/scene/GltfAnimation.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

#include "renderer/Error.h"

namespace dw {

GltfAnimationImporter::GltfAnimationImporter(const tinygltf::Model& model, const std::string& path, Scene& scene,
                                             const GltfAccessorReader& accessors)
    : model_(model), path_(path), scene_(scene), anim_(scene.animation), accessors_(accessors) {}

namespace {

// An accessor index the file may give out of range (GltfModelCheck checks
// mesh attributes, not morph targets, skins or animation samplers).
bool accessorIn(const tinygltf::Model& model, int a) { return a >= 0 && static_cast<std::size_t>(a) < model.accessors.size(); }

int attributeOf(const std::map<std::string, int>& attributes, const std::string& name) {
    const auto it = attributes.find(name);
    return it == attributes.end() ? -1 : it->second;
}

}  // namespace

bool GltfAnimationImporter::deforms(const tinygltf::Primitive& prim) const {
    return active_ && (attributeOf(prim.attributes, "JOINTS_0") >= 0 || !prim.targets.empty());
}

void GltfAnimationImporter::notePrimitive(const tinygltf::Primitive& prim, int mesh, const std::vector<std::uint32_t>& origins,
                                          const std::string& what) {
    PrimitiveData data;
    const std::size_t n = origins.size();
    const std::size_t fileVertices = model_.accessors[static_cast<std::size_t>(attributeOf(prim.attributes, "POSITION"))].count;
    // count * comps values of accessor `a`, or empty when absent or of another element count.
    // (Of the wrong type: a warning, and the part is left out.)
    auto read = [&](int a, int comps, const std::string& name) {
        std::vector<double> v;
        if (!accessorIn(model_, a) || model_.accessors[static_cast<std::size_t>(a)].count != fileVertices) return v;
        try {
            v = accessors_.read(a, comps, what + " " + name);
        } catch (const FileError& e) {
            scene_.warnings.push_back(std::string(e.what()) + " (left out of the pose)");
        }
        return v;
    };
    for (int set = 0; set < 2; ++set) {
        const std::string js = "JOINTS_" + std::to_string(set), ws = "WEIGHTS_" + std::to_string(set);
        const auto j = read(attributeOf(prim.attributes, js), 4, js), w = read(attributeOf(prim.attributes, ws), 4, ws);
        if (j.empty() || w.empty()) continue;
        data.joints[set].resize(n);
        data.weights[set].resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t o = origins[i] * 4;
            data.joints[set][i] = glm::uvec4(j[o], j[o + 1], j[o + 2], j[o + 3]);
            data.weights[set][i] = glm::vec4(w[o], w[o + 1], w[o + 2], w[o + 3]);
        }
    }
    for (std::size_t t = 0; t < prim.targets.size(); ++t) {
        MorphTarget target;
        const std::pair<const char*, std::vector<glm::vec3>*> parts[] = {
            {"POSITION", &target.position}, {"NORMAL", &target.normal}, {"TANGENT", &target.tangent}};
        for (const auto& [name, out] : parts) {
            const auto v = read(attributeOf(prim.targets[t], name), 3, "target " + std::to_string(t) + " " + name);
            if (v.empty()) continue;
            out->resize(n);
            for (std::size_t i = 0; i < n; ++i) (*out)[i] = glm::vec3(v[origins[i] * 3], v[origins[i] * 3 + 1], v[origins[i] * 3 + 2]);
        }
        data.targets.push_back(std::move(target));
    }
    primitives_[mesh] = std::move(data);
}

void GltfAnimationImporter::begin(const glm::mat4& root) {
    active_ = !model_.animations.empty() || !model_.skins.empty();
    for (const auto& m : model_.meshes)
        for (const auto& p : m.primitives) active_ = active_ || !p.targets.empty();
    if (!active_) return;
    nodeBase_ = static_cast<int>(anim_.nodes.size());
    skinBase_ = static_cast<int>(anim_.skins.size());
    anim_.files.push_back(path_);
    for (const auto& n : model_.nodes) {
        AnimationNode a;
        a.root = root;
        if (n.matrix.size() == 16) {
            a.hasMatrix = true;
            a.matrix = glm::mat4(glm::make_mat4(n.matrix.data()));
        }
        if (n.translation.size() == 3) a.translation = glm::vec3(n.translation[0], n.translation[1], n.translation[2]);
        if (n.rotation.size() == 4)
            a.rotation = glm::normalize(glm::quat(static_cast<float>(n.rotation[3]), static_cast<float>(n.rotation[0]),
                                                  static_cast<float>(n.rotation[1]), static_cast<float>(n.rotation[2])));
        if (n.scale.size() == 3) a.scale = glm::vec3(n.scale[0], n.scale[1], n.scale[2]);
        const std::vector<double>& w =
            !n.weights.empty() || n.mesh < 0 ? n.weights : model_.meshes[static_cast<std::size_t>(n.mesh)].weights;
        a.weights.assign(w.begin(), w.end());
        anim_.nodes.push_back(std::move(a));
    }
    for (std::size_t i = 0; i < model_.nodes.size(); ++i)
        for (int c : model_.nodes[i].children) anim_.nodes[static_cast<std::size_t>(nodeBase_ + c)].parent = nodeBase_ + static_cast<int>(i);
}

bool GltfAnimationImporter::skinUsable(int skin) const {
    if (skin < 0 || static_cast<std::size_t>(skin) >= model_.skins.size()) return false;
    for (int j : model_.skins[static_cast<std::size_t>(skin)].joints)
        if (j < 0 || static_cast<std::size_t>(j) >= model_.nodes.size()) return false;
    return true;
}

void GltfAnimationImporter::noteInstance(int node, int instance) {
    if (!active_) return;
    const int mesh = scene_.instances[static_cast<std::size_t>(instance)].mesh;
    const auto it = primitives_.find(mesh);
    const bool skinned = it != primitives_.end() && !it->second.joints[0].empty() && skinUsable(model_.nodes[static_cast<std::size_t>(node)].skin);
    anim_.instances.push_back({instance, nodeBase_ + node, skinned});
    if (it != primitives_.end() && (skinned || !it->second.targets.empty())) addDeformer(node, instance, it->second);
}

// The instance gets a Mesh of its own (a copy when another deformer has the file's), posed by the deformer.
void GltfAnimationImporter::addDeformer(int node, int instance, const PrimitiveData& data) {
    MeshInstance& inst = scene_.instances[static_cast<std::size_t>(instance)];
    meshTaken_.resize(scene_.meshes.size(), 0);
    if (meshTaken_[static_cast<std::size_t>(inst.mesh)]) inst.mesh = scene_.addMesh(scene_.meshes[static_cast<std::size_t>(inst.mesh)]);
    meshTaken_.resize(scene_.meshes.size(), 0);
    meshTaken_[static_cast<std::size_t>(inst.mesh)] = 1;
    Deformer d;
    d.mesh = inst.mesh;
    d.node = nodeBase_ + node;
    const int skin = model_.nodes[static_cast<std::size_t>(node)].skin;
    d.skin = !data.joints[0].empty() && skinUsable(skin) ? skinBase_ + skin : -1;
    d.rest = scene_.meshes[static_cast<std::size_t>(inst.mesh)].vertices;
    for (int set = 0; set < 2; ++set) {
        d.joints[set] = data.joints[set];
        d.weights[set] = data.weights[set];
    }
    d.targets = data.targets;
    anim_.deformers.push_back(std::move(d));
}

void GltfAnimationImporter::addSkins() {
    for (std::size_t s = 0; s < model_.skins.size(); ++s) {
        const tinygltf::Skin& skin = model_.skins[s];
        Skin out;
        out.inverseBind.assign(skin.joints.size(), glm::mat4(1.0f));
        if (skinUsable(static_cast<int>(s))) {
            for (int j : skin.joints) out.joints.push_back(nodeBase_ + j);
            if (accessorIn(model_, skin.inverseBindMatrices) &&
                model_.accessors[static_cast<std::size_t>(skin.inverseBindMatrices)].count >= skin.joints.size()) {
                try {
                    const auto m = accessors_.read(skin.inverseBindMatrices, 16, "skins[" + std::to_string(s) + "].inverseBindMatrices");
                    for (std::size_t j = 0; j < skin.joints.size(); ++j) out.inverseBind[j] = glm::mat4(glm::make_mat4(&m[16 * j]));
                } catch (const FileError& e) {
                    scene_.warnings.push_back(std::string(e.what()) + " (identity used)");
                }
            }
        } else {
            out.inverseBind.clear();
        }
        anim_.skins.push_back(std::move(out));
    }
}

bool GltfAnimationImporter::readChannel(const tinygltf::Animation& a, const tinygltf::AnimationChannel& c,
                                        AnimationClip& clip, std::string& why) const {
    static const std::map<std::string, std::pair<AnimationPath, int>> kPaths = {
        {"translation", {AnimationPath::Translation, 3}}, {"rotation", {AnimationPath::Rotation, 4}},
        {"scale", {AnimationPath::Scale, 3}}, {"weights", {AnimationPath::Weights, 0}}};
    const auto path = kPaths.find(c.target_path);
    if (path == kPaths.end()) return why = "target path '" + c.target_path + "'", false;
    if (c.target_node < 0 || static_cast<std::size_t>(c.target_node) >= model_.nodes.size()) return why = "no target node", false;
    if (c.sampler < 0 || static_cast<std::size_t>(c.sampler) >= a.samplers.size()) return why = "sampler out of range", false;
    const tinygltf::AnimationSampler& s = a.samplers[static_cast<std::size_t>(c.sampler)];
    if (!accessorIn(model_, s.input) || !accessorIn(model_, s.output)) return why = "sampler accessor out of range", false;
    AnimationSampler out;
    out.interpolation = s.interpolation == "STEP" ? Interpolation::Step
                        : s.interpolation == "CUBICSPLINE" ? Interpolation::CubicSpline : Interpolation::Linear;
    const auto times = accessors_.read(s.input, 1, "sampler input");
    out.times.assign(times.begin(), times.end());
    for (std::size_t i = 1; i < out.times.size(); ++i)
        if (!(out.times[i] > out.times[i - 1])) return why = "keyframe times do not increase", false;
    const std::size_t keys = out.times.size() * (out.interpolation == Interpolation::CubicSpline ? 3 : 1);
    const tinygltf::Accessor& o = model_.accessors[static_cast<std::size_t>(s.output)];
    out.components = path->second.second;
    if (path->second.first == AnimationPath::Weights) out.components = keys == 0 ? 0 : static_cast<int>(o.count / keys);
    const std::size_t accessorComps = path->second.first == AnimationPath::Weights ? 1 : static_cast<std::size_t>(out.components);
    if (keys == 0 || out.components == 0 || o.count * accessorComps != keys * static_cast<std::size_t>(out.components))
        return why = "output has " + std::to_string(o.count) + " values for " + std::to_string(out.times.size()) + " keyframes", false;
    const auto values = accessors_.read(s.output, static_cast<int>(accessorComps), "sampler output");
    out.values.assign(values.begin(), values.end());
    clip.start = std::min(clip.start, out.times.front());
    clip.end = std::max(clip.end, out.times.back());
    clip.samplers.push_back(std::move(out));
    clip.channels.push_back({static_cast<int>(clip.samplers.size() - 1), nodeBase_ + c.target_node, path->second.first});
    return true;
}

void GltfAnimationImporter::addAnimation(std::size_t index) {
    const tinygltf::Animation& a = model_.animations[index];
    AnimationClip clip;
    clip.name = a.name.empty() ? "animation " + std::to_string(index) : a.name;
    clip.file = static_cast<int>(anim_.files.size() - 1);
    clip.start = 1e30f;
    clip.end = -1e30f;
    for (std::size_t c = 0; c < a.channels.size(); ++c) {
        std::string why;
        bool ok = false;
        try {
            ok = readChannel(a, a.channels[c], clip, why);
        } catch (const FileError& e) {
            why = e.what();
        }
        if (!ok)
            scene_.warnings.push_back(path_ + ": animations[" + std::to_string(index) + "].channels[" + std::to_string(c) +
                                      "] skipped: " + why);
    }
    if (clip.channels.empty()) clip.start = clip.end = 0.0f;
    anim_.clips.push_back(std::move(clip));
}

void GltfAnimationImporter::finish() {
    if (!active_) return;
    addSkins();
    const int first = static_cast<int>(anim_.clips.size());
    for (std::size_t a = 0; a < model_.animations.size(); ++a) addAnimation(a);
    anim_.playing.push_back(model_.animations.empty() ? -1 : first);
    anim_.posedAt = -1.0;
}

}  // namespace dw
