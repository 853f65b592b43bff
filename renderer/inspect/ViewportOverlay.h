#pragma once
// Draws over a viewport image: the light volumes as wireframes (all lights or
// the selected one, coloured per light; parts behind geometry dimmed), light
// position markers and the world axes. The result is a new RGBA8 image the UI
// shows; the UI itself creates no GL objects.
#include <glm/glm.hpp>
#include <vector>

#include "renderer/graph/FrameContext.h"
#include "renderer/lighting/LightVolume.h"
#include "renderer/lighting/LightVolumeGeometry.h"
#include "renderer/gl/Buffer.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "renderer/gl/VertexArray.h"

namespace dw {

struct Scene;

struct OverlaySettings {
    bool lightVolumes = false;
    bool onlySelected = false;
    int selectedLight = -1;
    // When set, only these lights' volumes and markers (the probed pixel's
    // lights, lightsCovering): the readable default over a scene of many lights.
    bool onlySubset = false;
    std::vector<int> subset;
    bool axes = false;
    float threshold = 1.0f / 255.0f;  // lighting.threshold, for the volume sizes
    int sphereSubdivisions = kDefaultSphereSubdivisions;  // lighting.volume_subdivisions: the mesh the stencil draws
};

class ViewportOverlay {
public:
    void setup(gl::ShaderLibrary& shaders);
    // `depth` (same size as `base`, DEPTH32F_ or DEPTH24_STENCIL8) hides lines behind
    // geometry; pass null to draw everything in front.
    const gl::Texture& compose(const gl::Texture& base, const gl::Texture* depth, const Scene& scene,
                               const CameraUniforms& camera, const OverlaySettings& settings);
    // The colour a light's wireframe and marker get.
    static glm::vec4 lightColor(const glm::vec3& intensity, bool selected);

private:
    void drawLines(const std::vector<glm::vec3>& points, const glm::mat4& mvp, const glm::vec4& color);
    gl::ShaderLibrary::Handle program_;
    LightVolumeGeometry sphere_[kMaxSphereSubdivisions + 1], cone_;
    gl::Buffer lines_;
    gl::VertexArray linesVao_;
    gl::Texture color_, depth_;
    gl::Framebuffer fbo_;
};

}  // namespace dw
