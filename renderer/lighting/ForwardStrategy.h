#pragma once
// Forward shading as lighting strategies (seed 000 section 2 and listing 2.6),
// for comparing against the deferred ones on the same L-buffer. Both draw the
// scene again (GpuScene::drawEach, the G-buffer pass's vertex shader) with
// shaders/lighting/forward.frag, which evaluates each fragment's material as
// the G-buffer pass does (common/material_eval.glsl) but unquantised, and
// shades with the deferred strategies' lightRadiance (lighting/shade.glsl).
// The depth is already laid down: lbuffer.depth, the G-buffer depth copy, is
// tested GL_EQUAL, without depth writes, and light is added by the blender,
// after the lighting pass's ambient and directional lights.
//
// forward: one pass over the scene. For each draw (instance) the CPU keeps
//   the lights whose bounding sphere (position, volume radius) meets the
//   draw's world box (GpuScene::Draw::bounds), draws outside the view frustum
//   getting none, as a range of a light-index
//   SSBO (binding 4); the shader sums those lights in 32-bit floats.
//   Lights with a shadow map are not in the lists: with shadows.reuse_map a
//   single map layer serves every light in turn, so they are shaded one at a
//   time through their volume (LightLists::shadeOneByOne), as tiled does.
// forward_multipass: for each light, one additive pass over the visible draws
//   whose box its sphere meets, shading that one light, shadow lookup included
//   (frame.beginLight renders a reused map first).
#include <cstdint>
#include <vector>

#include "renderer/gl/Buffer.h"
#include "renderer/lighting/LightingStrategy.h"

namespace dw {

class GpuScene;
struct Bounds;

// Whether a sphere meets an axis-aligned box (closest point of the box).
bool sphereMeetsBox(const glm::vec3& centre, float radius, const Bounds& box);

// Per-draw light lists of the forward strategy.
struct ForwardLightLists {
    std::vector<std::uint32_t> rows;                  // light-table rows, draw after draw
    std::vector<std::uint32_t> first, count;          // per GpuScene draw, into `rows`
    // For each draw, the lights of `lights` whose sphere meets its box; none
    // for draws whose box is outside the frustum of `worldToClip` (if given:
    // absolute world space to clip space, CameraUniforms::worldToClip).
    static ForwardLightLists build(const GpuScene& gpu, const std::vector<const LightTableEntry*>& lights,
                                   const glm::dmat4* worldToClip = nullptr);
};

class ForwardStrategy : public LightingStrategy {
public:
    explicit ForwardStrategy(KnobRegistry&) {}
    const char* name() const override { return "forward"; }
    std::string description() const override {
        return "forward single-pass: the scene drawn again over the G-buffer depth, each object summing the lights "
               "culled to its bounds on the CPU (shadowed lights one at a time through their volume)";
    }
    void setup(gl::ShaderLibrary& shaders) override;
    StrategyCounts shade(LightingFrame& frame) override;
    bool shadesFromGBuffer() const override { return false; }
    // Light-object pairs shaded in the last frame (the sum of the lists' lengths).
    std::size_t lastPairs() const { return lastPairs_; }

private:
    gl::ShaderLibrary::Handle program_, countingProgram_;
    gl::Buffer indices_;
    std::size_t lastPairs_ = 0;
    // gl::shaderLoopIterationLimit() of the setup's context: a draw's list
    // longer than 90% of it is drawn in parts (llvmpipe ends the loop early).
    int loopLimit_ = 0;
};

class ForwardMultipassStrategy : public LightingStrategy {
public:
    explicit ForwardMultipassStrategy(KnobRegistry&) {}
    const char* name() const override { return "forward_multipass"; }
    std::string description() const override {
        return "forward multi-pass: one additive pass per light over the objects its sphere meets, over the "
               "G-buffer depth (GL_EQUAL)";
    }
    void setup(gl::ShaderLibrary& shaders) override;
    StrategyCounts shade(LightingFrame& frame) override;
    bool shadesFromGBuffer() const override { return false; }
    std::size_t lastPairs() const { return lastPairs_; }

private:
    gl::ShaderLibrary::Handle program_, countingProgram_;
    std::size_t lastPairs_ = 0;
};

}  // namespace dw
