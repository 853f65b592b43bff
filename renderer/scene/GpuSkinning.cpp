#include "renderer/scene/GpuSkinning.h"

#include <algorithm>

#include "renderer/scene/Animation.h"
#include "renderer/scene/Scene.h"
#include "shaders/common/bindings.glsl"

namespace dw {

namespace {

// std430 mirrors of shaders/scene/skin.comp's RestVertex, Influence and Delta.
struct RestGpu {
    glm::vec4 position, normal, tangent;  // xyz; tangent.w the bitangent sign
};
struct InfluenceGpu {
    glm::uvec4 joints[2];
    glm::vec4 weights[2];  // zero where the set is absent
};
struct DeltaGpu {
    glm::vec4 position, normal, tangent;  // xyz; zero where the target has no such delta
};
static_assert(sizeof(RestGpu) == 48 && sizeof(InfluenceGpu) == 64 && sizeof(DeltaGpu) == 48, "std430 layout");

constexpr int kGroupSize = 64;  // skin.comp's local_size_x

void appendRest(const Deformer& d, std::vector<RestGpu>& rest) {
    for (const Vertex& v : d.rest)
        rest.push_back({glm::vec4(v.position, 1.0f), glm::vec4(v.normal, 0.0f), v.tangent});
}

void appendInfluences(const Deformer& d, std::vector<InfluenceGpu>& out) {
    for (std::size_t i = 0; i < d.rest.size(); ++i) {
        InfluenceGpu g{};
        for (int set = 0; set < 2; ++set)
            if (!d.joints[set].empty()) {
                g.joints[set] = d.joints[set][i];
                g.weights[set] = d.weights[set][i];
            }
        out.push_back(g);
    }
}

void appendDeltas(const Deformer& d, std::vector<DeltaGpu>& out) {
    for (const MorphTarget& m : d.targets)
        for (std::size_t i = 0; i < d.rest.size(); ++i) {
            DeltaGpu g{};
            if (!m.position.empty()) g.position = glm::vec4(m.position[i], 0.0f);
            if (!m.normal.empty()) g.normal = glm::vec4(m.normal[i], 0.0f);
            if (!m.tangent.empty()) g.tangent = glm::vec4(m.tangent[i], 0.0f);
            out.push_back(g);
        }
}

// A storage buffer never empty (a zero-sized buffer cannot be bound).
template <typename T>
gl::Buffer storage(std::vector<T> v, bool dynamic, const char* label) {
    if (v.empty()) v.resize(1);
    return gl::Buffer::fromVector(v, dynamic, label);
}

}  // namespace

void GpuSkinning::upload(const Scene& scene, const std::vector<int>& baseVertex, gl::ShaderLibrary::Handle program) {
    const SceneAnimation& anim = scene.animation;
    if (anim.deformers.empty()) return;
    program_ = program;
    std::vector<RestGpu> rest;
    std::vector<InfluenceGpu> influences;
    std::vector<DeltaGpu> deltas;
    for (const Deformer& d : anim.deformers) {
        DeformerRange r;
        r.restFirst = static_cast<int>(rest.size());
        r.count = static_cast<int>(d.rest.size());
        r.dstFirst = baseVertex[static_cast<std::size_t>(d.mesh)];
        r.morphFirst = static_cast<int>(deltas.size());
        r.targets = static_cast<int>(d.targets.size());
        r.skinned = d.skin >= 0 && !d.joints[0].empty();
        appendRest(d, rest);
        appendInfluences(d, influences);
        appendDeltas(d, deltas);
        deformers_.push_back(r);
    }
    rest_ = storage(std::move(rest), false, "skinning rest vertices");
    influences_ = storage(std::move(influences), false, "skinning joints and weights");
    morphs_ = storage(std::move(deltas), false, "morph target deltas");
}

void GpuSkinning::pose(const Scene& scene, const gl::Buffer& vertices) const {
    if (deformers_.empty()) return;
    const SceneAnimation& anim = scene.animation;
    const NodePose nodes = evaluateNodes(anim, anim.posedAt);
    // Every skin's joint matrices in one array, each skin from its offset.
    std::vector<glm::mat4> joints;
    std::vector<int> jointFirst;
    for (const Skin& s : anim.skins) {
        jointFirst.push_back(static_cast<int>(joints.size()));
        const std::vector<glm::mat4> m = jointMatrices(anim, s, nodes);
        joints.insert(joints.end(), m.begin(), m.end());
    }
    std::vector<float> weights;
    std::vector<int> weightFirst, weightCount;
    for (std::size_t i = 0; i < deformers_.size(); ++i) {
        const std::vector<float>& w = nodes.weights[static_cast<std::size_t>(anim.deformers[i].node)];
        weightFirst.push_back(static_cast<int>(weights.size()));
        weightCount.push_back(std::min(static_cast<int>(w.size()), deformers_[i].targets));
        weights.insert(weights.end(), w.begin(), w.end());
    }
    lastUploadBytes_ = joints.size() * sizeof(glm::mat4) + weights.size() * sizeof(float);
    joints_ = storage(std::move(joints), false, "joint matrices");
    weights_ = storage(std::move(weights), false, "morph weights");

    const gl::Program& p = *program_;
    p.use();
    vertices.bindBase(GL_SHADER_STORAGE_BUFFER, binding::SKIN_VERTICES_SSBO);
    rest_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::SKIN_REST_SSBO);
    influences_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::SKIN_INFLUENCES_SSBO);
    morphs_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::SKIN_MORPH_SSBO);
    joints_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::SKIN_JOINTS_SSBO);
    weights_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::SKIN_WEIGHTS_SSBO);
    for (std::size_t i = 0; i < deformers_.size(); ++i) {
        const DeformerRange& r = deformers_[i];
        const int skin = anim.deformers[i].skin;
        const bool skinned = r.skinned && !anim.skins[static_cast<std::size_t>(skin)].joints.empty();
        p.set(0, r.restFirst);
        p.set(1, r.count);
        p.set(2, r.dstFirst);
        p.set(3, skinned ? jointFirst[static_cast<std::size_t>(skin)] : 0);
        p.set(4, skinned ? static_cast<int>(anim.skins[static_cast<std::size_t>(skin)].joints.size()) : 0);
        p.set(5, r.morphFirst);
        p.set(6, r.targets > 0 ? weightCount[i] : -1);  // -1: no morph targets (the rest normal kept as is)
        p.set(7, weightFirst[i]);
        glDispatchCompute(static_cast<GLuint>((r.count + kGroupSize - 1) / kGroupSize), 1, 1);
    }
    // The draws fetch the vertices next; a later upload or readback sees them too.
    glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace dw
