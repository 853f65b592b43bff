#pragma once
// The animation part of glTF import (issue 36): nodes, skins (3.7.3), morph
// targets (3.7.2.2) and animations (3.11) of one file into
// Scene::animation (Animation.h), which ScenePose evaluates at a scene time.
// Only files that have skins, morph targets or animations add anything.
// A broken animation channel (a node or sampler out of range, an accessor
// of the wrong type or count) is skipped with one warning; the rest plays.
#include <tiny_gltf.h>

#include <glm/glm.hpp>
#include <map>
#include <string>
#include <vector>

#include "renderer/scene/GltfAccessors.h"
#include "renderer/scene/Scene.h"

namespace dw {

class GltfAnimationImporter {
public:
    GltfAnimationImporter(const tinygltf::Model& model, const std::string& path, Scene& scene,
                          const GltfAccessorReader& accessors);

    // Whether the file has anything that moves (skins, morph targets or
    // animations); then adds the file's nodes, under `root`. Call first,
    // after the model is parsed.
    void begin(const glm::mat4& root);
    bool active() const { return active_; }
    // Whether `prim` has joints or morph targets, i.e. needs origin tags
    // (which file vertex each Mesh vertex was copied from) when it is built.
    bool deforms(const tinygltf::Primitive& prim) const;
    // After a deforming primitive became Mesh `mesh` (its vertex i copied from
    // file vertex origins[i]): reads JOINTS_n, WEIGHTS_n and the morph targets.
    void notePrimitive(const tinygltf::Primitive& prim, int mesh, const std::vector<std::uint32_t>& origins,
                       const std::string& what);
    // Scene::instances[instance] is mesh `mesh` placed by file node `node`.
    void noteInstance(int node, int instance);
    // Skins and animations; the file's first animation plays. Call last.
    void finish();

private:
    struct PrimitiveData {
        std::vector<glm::uvec4> joints[2];
        std::vector<glm::vec4> weights[2];
        std::vector<MorphTarget> targets;
    };
    bool skinUsable(int skin) const;
    void addDeformer(int node, int instance, const PrimitiveData& data);
    void addSkins();
    void addAnimation(std::size_t index);
    bool readChannel(const tinygltf::Animation& a, const tinygltf::AnimationChannel& c, AnimationClip& clip,
                     std::string& why) const;

    const tinygltf::Model& model_;
    const std::string& path_;
    Scene& scene_;
    SceneAnimation& anim_;
    const GltfAccessorReader& accessors_;
    bool active_ = false;
    int nodeBase_ = 0, skinBase_ = 0;
    std::map<int, PrimitiveData> primitives_;  // by scene mesh
    std::vector<char> meshTaken_;               // scene meshes a deformer already owns
};

}  // namespace dw
