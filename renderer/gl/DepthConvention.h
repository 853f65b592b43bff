#pragma once
// The depth convention every pass draws, tests and reconstructs with.
//
// Clip space is always z in [0, 1] (glClipControl(GL_LOWER_LEFT,
// GL_ZERO_TO_ONE)), so window depth equals NDC z and no precision is lost to
// the [-1, 1] -> [0, 1] remap. Two mappings of view distance to depth:
//  - Reversed (default): near -> 1, far -> 0, clear to 0, GL_GREATER.
//    With a 32-bit float depth buffer the float exponent cancels the 1/z
//    hyperbola, so the depth error is about constant in relative terms at
//    every distance (Lapidous and Jiao 1999; Reed 2015, "Depth Precision
//    Visualized"). Near 1e-5 and far 5000 still reconstruct positions to
//    about 1e-6 relative error.
//  - Conventional: near -> 0, far -> 1, clear to 1, GL_LESS (the mapping
//    before this convention existed, kept so the accuracy lab can measure
//    the difference: all of its precision is spent close to the near plane).
// Shaders see the mode in camera.depth (shaders/common/camera.glsl).
#include <epoxy/gl.h>
#include <glm/glm.hpp>
#include <string>

namespace dw {

enum class DepthMode { Reversed, Conventional };

class DepthConvention {
public:
    explicit DepthConvention(DepthMode mode = DepthMode::Reversed) : mode_(mode) {}
    // From CameraUniforms::depth (x = 1 reversed, 0 conventional).
    static DepthConvention fromUniform(const glm::vec4& depth) {
        return DepthConvention(depth.x > 0.5f ? DepthMode::Reversed : DepthMode::Conventional);
    }

    DepthMode mode() const { return mode_; }
    bool reversed() const { return mode_ == DepthMode::Reversed; }
    // Window depth of the far plane (the clear value) and of the near plane.
    float farDepth() const { return reversed() ? 0.0f : 1.0f; }
    float nearDepth() const { return reversed() ? 1.0f : 0.0f; }
    // Whether a stored depth is the cleared background (nothing drawn).
    bool isFar(float depth) const { return reversed() ? depth <= 0.0f : depth >= 1.0f; }
    // Depth test passing for the nearer fragment (GL_GREATER / GL_LESS), the
    // same or equal (GL_GEQUAL / GL_LEQUAL), and for the farther one.
    GLenum nearer() const { return reversed() ? GL_GREATER : GL_LESS; }
    GLenum nearerOrEqual() const { return reversed() ? GL_GEQUAL : GL_LEQUAL; }
    GLenum farther() const { return reversed() ? GL_LESS : GL_GREATER; }
    // Sign of a glPolygonOffset that pushes a surface away from the eye.
    float awaySign() const { return reversed() ? -1.0f : 1.0f; }
    // The CameraUniforms::depth vector: reversed flag, far depth, near depth.
    glm::vec4 uniform() const { return {reversed() ? 1.0f : 0.0f, farDepth(), nearDepth(), 0.0f}; }

    // Right-handed projections onto [0, 1] depth in this convention, built in
    // double precision (near 1e-5 and far 1e7 are both representable).
    // fovY in radians; near > 0, far > near (the caller validates).
    glm::dmat4 perspective(double fovY, double aspect, double near, double far) const;
    glm::dmat4 orthographic(double left, double right, double bottom, double top, double near, double far) const;
    // Window depth of a point `distance` along the view axis of a
    // perspective projection with these planes.
    double perspectiveDepth(double distance, double near, double far) const;

    // Sets GL_ZERO_TO_ONE clip control for the current context (part of the
    // state every pass starts from: gl::resetPipelineState calls it).
    static void applyClipControl();

    static const char* name(DepthMode mode) { return mode == DepthMode::Reversed ? "reversed" : "conventional"; }

private:
    DepthMode mode_;
};

}  // namespace dw
