#pragma once
// GPU copy of a light-volume mesh (unit sphere or cone, renderer/lighting/LightVolume.h),
// positions only, shared by the lighting pass and the volume wireframes.
#include "renderer/gl/Buffer.h"
#include "renderer/gl/VertexArray.h"

namespace dw {

struct VolumeMesh;

class LightVolumeGeometry {
public:
    void create(const VolumeMesh& mesh);
    void draw() const;

private:
    gl::Buffer vertices_, indices_;
    gl::VertexArray vao_;
    GLsizei indexCount_ = 0;
};

}  // namespace dw
