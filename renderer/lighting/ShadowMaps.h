#pragma once
// Shadow maps (seed 000 sections 4.4 and 5.5, seed 002 section 3.3), owned by
// the shadow pass: directional lights get an orthographic map fitted to what
// the camera sees, spot lights a perspective map matching the cutoff, point
// lights a cube map (or two paraboloids). Maps live in texture arrays (2D,
// cube, paraboloid pairs); by default one layer per kind is reused light after
// light ("flip-flop", seed 002 3.3), or every shadowed light keeps its own
// layer. Bias is slope-scaled and constant polygon offset; filtering is PCF
// through comparison samplers, so the arrays stay plain depth textures.
// Each map (a cube face, a paraboloid half) draws only the casters whose box
// meets its volume (shadows.cull_casters; renderer/lighting/CasterCulling),
// and counts them (casters()).
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "renderer/graph/FrameContext.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/Sampler.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "renderer/scene/Light.h"

namespace dw {

class CasterVolume;
class GpuScene;
struct Scene;

// What the light shader needs to sample a light's map (part of the light table).
struct ShadowLookup {
    glm::mat4 matrix{1.0f};
    glm::vec4 params{0.0f};  // mode (0 none, 1 2D, 2 cube, 3 paraboloid), PCF radius, texel size, layer
    glm::vec4 range{0.0f};   // near, far; constant bias: fixed distance, distance per unit from the light
};

class ShadowMaps {
public:
    enum Kind { Map2D = 0, Cube = 1, Paraboloid = 2 };
    // Spot lights wider than this get a point light's map (cube or paraboloids).
    static constexpr float kWideSpotDegrees = 60.0f;

    explicit ShadowMaps(KnobRegistry& knobs);
    void setup(gl::ShaderLibrary& shaders);

    bool enabled(const KnobRegistry& knobs) const { return knobs.get(enabled_); }
    bool reuse(const KnobRegistry& knobs) const { return knobs.get(reuse_); }
    // Allocates layers for this frame: `counts` shadowed lights of each kind,
    // one layer per kind when `reuse`, else one per light.
    void beginFrame(const FrameContext& ctx, const int counts[3], bool reuse);
    // Renders `light`'s map into `slot` of its kind and says how to sample it.
    ShadowLookup render(const FrameContext& ctx, const Light& light, double radius, int slot);
    // The maps at units 6 (2D), 7 (cube), 8 (paraboloid) with comparison samplers.
    void bind() const;
    Kind kindOf(const Light& light, const KnobRegistry& knobs) const;
    // The depth array of a kind (layers: 1 per 2D map, 6 per cube, 2 per paraboloid pair).
    const gl::Texture& maps(Kind kind) const { return maps_[kind]; }

    // Bytes the maps in use take, and what keeping one map per light would take.
    std::size_t bytesInUse() const { return bytesInUse_; }
    std::size_t bytesKeepingAll() const { return bytesKeepingAll_; }
    int mapsRendered() const { return rendered_; }

    // Shadow casters this frame, summed over every map (each cube face and
    // paraboloid half a map): draws and triangles drawn after culling against
    // the map's volume (shadows.cull_casters), and what all of them would be
    // without culling. Reset by beginFrame.
    struct CasterCounts {
        std::size_t drawn = 0, total = 0;
        std::size_t trianglesDrawn = 0, trianglesTotal = 0;
    };
    const CasterCounts& casters() const { return casters_; }

private:
    // A 2D map's projection, its light view (absolute world space to light
    // space, double precision), the eye it is drawn relative to, and the
    // lookup's constant bias (ShadowLookup::range).
    struct MapFit {
        glm::dmat4 proj{1.0}, lightView{1.0};
        glm::dvec3 eye{0.0};
        glm::vec4 range{0.0f};
    };
    void ensure(Kind kind, int layers, int size);
    // The map's far distance from `light`: its radius, clamped to the scene.
    float farDistance(const FrameContext& ctx, const Light& light, double radius) const;
    MapFit fitDirectional(const FrameContext& ctx, const Light& light) const;
    void fitDirectionalBox(const FrameContext& ctx, MapFit& fit, const glm::vec2& sphereC, float sphereR, glm::vec3 lo,
                           glm::vec3 hi) const;
    MapFit fitSpot(const FrameContext& ctx, const Light& light, float near, float far) const;
    void render2D(const FrameContext& ctx, const Light& light, float near, float far, int slot, ShadowLookup& out);
    void renderCube(const FrameContext& ctx, const Light& light, float near, float far, int slot, ShadowLookup& out);
    void renderParaboloid(const FrameContext& ctx, const Light& light, float near, float far, int slot, ShadowLookup& out);
    // The draws that may cast into a map of `volume` (all of them when
    // shadows.cull_casters is off), counted into casters_.
    std::vector<std::size_t> cullCasters(const FrameContext& ctx, const CasterVolume& volume);
    void drawCasters(const FrameContext& ctx, const gl::Program& program, const CasterVolume& volume);
    void target(Kind kind, int layer);  // attaches and clears one layer
    BoolKnob enabled_, reuse_, blendedCasters_, cullCasters_;
    IntKnob size_, pcf_;
    FloatKnob biasConstant_, biasSlope_, distance_;
    EnumKnob pointMethod_;
    gl::ShaderLibrary::Handle depth_, pointDistance_, paraboloid_;  // 2D maps; cube maps; paraboloids (shadow/distance.frag)
    gl::Texture maps_[3];
    gl::Sampler compare_;
    DepthConvention depthConvention_;  // of the frame (beginFrame): projections, clear, test, comparison
    int layers_[3] = {0, 0, 0};
    int mapSize_ = 0;
    gl::Framebuffer fbo_;
    std::size_t bytesInUse_ = 0, bytesKeepingAll_ = 0;
    int rendered_ = 0;
    CasterCounts casters_;
};

}  // namespace dw
