#include "renderer/scene/ScenePose.h"

#include "renderer/scene/Scene.h"

namespace dw {

bool poseScene(Scene& scene, double seconds) {
    SceneAnimation& anim = scene.animation;
    if (anim.empty() || anim.posedAt == seconds) return false;
    const NodePose pose = evaluateNodes(anim, seconds);
    for (const NodeInstance& ni : anim.instances) {
        const auto node = static_cast<std::size_t>(ni.node);
        scene.instances[static_cast<std::size_t>(ni.instance)].transform =
            ni.skinned ? anim.nodes[node].root : pose.world[node];
    }
    std::vector<std::vector<glm::mat4>> joints(anim.skins.size());
    for (std::size_t s = 0; s < anim.skins.size(); ++s) joints[s] = jointMatrices(anim, anim.skins[s], pose);
    static const std::vector<glm::mat4> kNoJoints;
    for (const Deformer& d : anim.deformers) {
        Mesh& mesh = scene.meshes[static_cast<std::size_t>(d.mesh)];
        const std::vector<glm::mat4>& j = d.skin >= 0 ? joints[static_cast<std::size_t>(d.skin)] : kNoJoints;
        poseVertices(d, pose.weights[static_cast<std::size_t>(d.node)], j, mesh.vertices);
        mesh.computeBounds();
    }
    anim.posedAt = seconds;
    return true;
}

}  // namespace dw
