#pragma once
// A scene's animation, kept beside the scene and not in the passes (issue 36):
// glTF 2.0 nodes, skins, morph targets and animation clips (spec 3.7.3
// "Skins", 3.7.2.2 "Morph Targets", 3.11 "Animations", Appendix C "Animation
// Sampler Interpolation Modes"), evaluated at a scene time T in seconds.
// poseScene (ScenePose.h) writes the result into the Scene the renderer, the
// CPU reference and the culling read, so every pass sees a posed scene.
//
// Evaluation rules (Appendix C): keyframe times are seconds and increase;
// before the first keyframe the first value holds, after the last the last
// (clamping: a clip does not loop unless the player wraps T); STEP holds v_k;
// LINEAR interpolates (rotations by slerp along the shorter arc); CUBICSPLINE
// is the cubic Hermite spline of the in-tangent a, value v, out-tangent b
// triplets, tangents scaled by the keyframe interval t_d; rotations it
// produces are normalised.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

#include "renderer/scene/Mesh.h"

namespace dw {

enum class Interpolation { Step, Linear, CubicSpline };
enum class AnimationPath { Translation, Rotation, Scale, Weights };

// One glTF animation sampler: keyframe times (s, increasing) and the output
// values, `components` floats per value (3 T/S, 4 rotation quaternion xyzw,
// the morph-target count for weights); CUBICSPLINE holds three values per
// keyframe (in-tangent, value, out-tangent).
struct AnimationSampler {
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;
    std::vector<float> values;
    int components = 3;
};

struct AnimationChannel {
    int sampler = 0;  // into AnimationClip::samplers
    int node = 0;     // into SceneAnimation::nodes
    AnimationPath path = AnimationPath::Translation;
};

struct AnimationClip {
    std::string name;
    int file = 0;  // which imported glTF file (SceneAnimation::files) it came from
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels;
    float start = 0.0f, end = 0.0f;  // first and last keyframe time over its samplers (s)
};

// A glTF node's local transform: a matrix, or translation, rotation, scale.
struct AnimationNode {
    int parent = -1;
    glm::mat4 root{1.0f};  // what a node without a parent sits under (the import's root transform)
    bool hasMatrix = false;
    glm::mat4 matrix{1.0f};
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    std::vector<float> weights;  // the node's morph weights (node.weights, else its mesh's weights)
};

struct Skin {
    std::vector<int> joints;               // into SceneAnimation::nodes
    std::vector<glm::mat4> inverseBind;    // one per joint (identity when the file gives none)
};

// Per-vertex deltas of one morph target, one per Mesh vertex (empty: absent).
struct MorphTarget {
    std::vector<glm::vec3> position, normal, tangent;
};

// One mesh instance whose vertices move: skinned, morphed or both. Its Mesh
// (Scene::meshes[mesh]) is its own, holds the posed vertices; `rest` the file's.
struct Deformer {
    int mesh = 0;
    int node = 0;   // the node that instantiates the mesh (its morph weights)
    int skin = -1;  // into SceneAnimation::skins; -1: morph targets only
    std::vector<Vertex> rest;
    // JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1 (empty when absent), per vertex.
    std::vector<glm::uvec4> joints[2];
    std::vector<glm::vec4> weights[2];
    std::vector<MorphTarget> targets;
};

// A mesh instance placed by a node (Scene::instances[instance] follows it).
struct NodeInstance {
    int instance = 0;
    int node = 0;
    bool skinned = false;  // placed by the import's root alone (glTF: a skinned mesh's node transform is ignored)
};

struct SceneAnimation {
    std::vector<AnimationNode> nodes;
    std::vector<Skin> skins;
    std::vector<AnimationClip> clips;
    std::vector<Deformer> deformers;
    std::vector<NodeInstance> instances;
    std::vector<std::string> files;  // the glTF files, in import order
    // Which clip plays, per file (index into clips, -1 none): the file's
    // first animation unless chosen otherwise.
    std::vector<int> playing;
    double posedAt = -1.0;  // the scene time the Scene was last posed at (s); < 0: never

    bool empty() const { return nodes.empty(); }
    bool moves() const { return !deformers.empty() || !clips.empty(); }
    // The longest playing clip's end (s); 0 without clips.
    double duration() const;
};

// The sampler's value at time `t` (seconds), `components` floats, by its
// interpolation; rotation: whether to slerp (LINEAR) and normalise (CUBICSPLINE).
std::vector<float> sampleAnimation(const AnimationSampler& s, double t, bool rotation);

// Every node's local transform, and morph weights, at time `t` with the
// playing clips applied; then the world matrices (parents first).
struct NodePose {
    std::vector<glm::mat4> world;
    std::vector<std::vector<float>> weights;
};
NodePose evaluateNodes(const SceneAnimation& anim, double t);

// The skin's joint matrices: world(joint) * inverseBind(joint).
std::vector<glm::mat4> jointMatrices(const SceneAnimation& anim, const Skin& skin, const NodePose& pose);

// The deformer's vertices posed: morph targets by `weights`, then skinned by
// `joints` (empty: not skinned). Normals and tangents follow, renormalised.
void poseVertices(const Deformer& d, const std::vector<float>& weights, const std::vector<glm::mat4>& joints,
                  std::vector<Vertex>& out);

}  // namespace dw
