#pragma once
// The viewer's non-deferred modes (seed 001 section 3.4: 't' textured, 'w'
// wireframe): the scene drawn forward into an RGBA8 image, for orientation and
// for comparing against the deferred result. Not part of the pipeline.
#include "renderer/graph/FrameContext.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"

namespace dw {

class GpuScene;

class ForwardPreview {
public:
    enum class Mode { Textured, Wireframe };
    void setup(gl::ShaderLibrary& shaders);
    // Draws `gpu` with the camera UBO already bound (Pipeline::render binds
    // it); `depth` must be the convention that camera's projection was built in.
    const gl::Texture& render(const GpuScene& gpu, int width, int height, Mode mode,
                              DepthConvention depth = DepthConvention());
    const gl::Texture& depth() const { return depth_; }

private:
    gl::ShaderLibrary::Handle program_;
    gl::Texture color_, depth_;
    gl::Framebuffer fbo_;
};

}  // namespace dw
