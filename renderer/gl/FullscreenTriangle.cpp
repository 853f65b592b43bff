#include "renderer/gl/FullscreenTriangle.h"

#include "renderer/gl/DepthConvention.h"
#include "renderer/gl/Sampler.h"

namespace dw::gl {

void FullscreenTriangle::draw() const {
    if (!vao_.id()) vao_ = VertexArray::create();
    vao_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void resetPipelineState(int width, int height) {
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_SAMPLE_MASK);
    glDisable(GL_MULTISAMPLE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // filtering (and PCF) across cube faces
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glDepthFunc(GL_LESS);
    // What a pass may have set and the next must not inherit: stencil
    // function and operations, blend function and equation (every draw
    // buffer), and every sample-mask word (the A-buffer's stencil routing
    // sets them one sample at a time).
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glBlendFunc(GL_ONE, GL_ZERO);
    glBlendEquation(GL_FUNC_ADD);
    static const GLint maskWords = [] {
        GLint n = 1;
        glGetIntegerv(GL_MAX_SAMPLE_MASK_WORDS, &n);
        return n;
    }();
    for (GLint w = 0; w < maskWords; ++w) glSampleMaski(static_cast<GLuint>(w), ~0u);
    DepthConvention::applyClipControl();  // depth in [0, 1], either mapping
    glFrontFace(GL_CCW);
    glViewport(0, 0, width, height);
    glBindSamplers(0, Sampler::kResetUnits, nullptr);  // textures' own sampling state
}

}  // namespace dw::gl
