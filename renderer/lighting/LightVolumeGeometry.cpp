#include "renderer/lighting/LightVolumeGeometry.h"

#include "renderer/lighting/LightVolume.h"

namespace dw {

void LightVolumeGeometry::create(const VolumeMesh& mesh) {
    vertices_ = gl::Buffer::fromVector(mesh.positions, false, "light volume vertices");
    indices_ = gl::Buffer::fromVector(mesh.indices, false, "light volume indices");
    vao_ = gl::VertexArray::create();
    vao_.setVertexBuffer(0, vertices_, 0, sizeof(glm::vec3));
    vao_.setIndexBuffer(indices_);
    vao_.setAttribute(0, 0, 3, 0);
    indexCount_ = static_cast<GLsizei>(mesh.indices.size());
}

void LightVolumeGeometry::draw() const {
    vao_.bind();
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace dw
