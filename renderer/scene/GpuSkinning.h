#pragma once
// glTF skinning and morphing on the GPU (issue 36): one compute pass in the
// scene layer that writes the posed positions, normals and tangents of every
// deformed mesh (Deformer, Animation.h) into the scene's vertex buffer, the
// one every pass draws from (G-buffer, shadow maps, AO, transparency,
// forward), so the passes see an already-posed vertex buffer.
//
// upload(): once per scene, the rest (bind-pose) positions, normals and
// tangents, the JOINTS_0/WEIGHTS_0 and JOINTS_1/WEIGHTS_1 sets and the morph
// targets' position, normal and tangent deltas go to static storage buffers.
// pose(): per pose, only the skins' joint matrices (world(joint) *
// inverseBind(joint), 64 bytes each) and the morph weights (4 bytes each) are
// uploaded, then shaders/scene/skin.comp runs once per deformer (64 vertices
// a work group) and a glMemoryBarrier makes its writes visible to vertex
// fetch. The shader repeats poseVertices (Animation.cpp) operation for
// operation: morph deltas weighted and summed, normals and tangents
// renormalised; then the weighted sum of the joint matrices, positions by it,
// normals by its cofactor matrix (det * inverse transpose, sign of det),
// tangents by its upper 3x3, renormalised. So the GPU's vertices equal the
// CPU's to float rounding (GpuSkinningTest).
#include <cstddef>
#include <vector>

#include "renderer/gl/Buffer.h"
#include "renderer/gl/ShaderLibrary.h"

namespace dw {

struct Scene;

class GpuSkinning {
public:
    // `baseVertex`: per mesh, its first vertex in `vertices` (GpuScene's
    // vertex buffer, Vertex layout, 72 bytes a vertex). `program`: the
    // library's shaders/scene/skin.comp. No-op for a scene without deformers.
    void upload(const Scene& scene, const std::vector<int>& baseVertex, gl::ShaderLibrary::Handle program);
    // Writes the deformers' vertices at the scene's pose (Scene::animation
    // evaluated at its posedAt, as poseScene did) into `vertices`.
    void pose(const Scene& scene, const gl::Buffer& vertices) const;
    bool empty() const { return deformers_.empty(); }
    // Bytes uploaded by the last pose() (joint matrices and morph weights).
    std::size_t lastUploadBytes() const { return lastUploadBytes_; }

private:
    struct DeformerRange {
        int restFirst = 0, count = 0, dstFirst = 0, morphFirst = 0, targets = 0;
        bool skinned = false;
    };
    std::vector<DeformerRange> deformers_;
    gl::ShaderLibrary::Handle program_;
    gl::Buffer rest_, influences_, morphs_;
    mutable gl::Buffer joints_, weights_;
    mutable std::size_t lastUploadBytes_ = 0;
};

}  // namespace dw
