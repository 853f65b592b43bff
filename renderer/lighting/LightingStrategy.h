#pragma once
// How the lighting pass finds the pixels each bounded (point or spot) light
// touches (seed 000 section 6.1, seed 001 section 2.2, seed 003 section
// 2.2.1): one class per strategy, each a value of the knob lighting.strategy.
// Every strategy shades with the same light shader into the same L-buffer, so
// their images agree up to rounding; they differ in what they cost. A new
// strategy is one class and one registration line:
//     static dw::RegisterLightingStrategy<MyStrategy> registerMine;
// (built-in ones are listed in BuiltinStrategies.cpp).
#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <string>
#include <vector>

#include "renderer/graph/FrameContext.h"
#include "renderer/graph/MethodSet.h"
#include "renderer/lighting/LightVolumeGeometry.h"
#include "renderer/graph/OutputRegistry.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/lighting/LightTable.h"
#include "renderer/lighting/LightVolume.h"

namespace dw {

class KnobRegistry;


// What strategies share: the light shader (and its overlap-counting variant)
// as a full-screen pass and over a volume mesh, the stencil-marking program,
// and the unit sphere and cone volume meshes (renderer/lighting/LightVolume.h).
class LightShading {
public:
    void setup(gl::ShaderLibrary& shaders);
    const gl::Program& fullscreen(bool counting) const { return counting ? *fullscreenCounting_ : *fullscreen_; }
    const gl::Program& volume(bool counting) const { return counting ? *volumeCounting_ : *volume_; }
    // The light shader for drawVolumeBatch: built without the shadow lookup
    // (UNSHADOWED), since a batch holds only lights without a shadow map; on
    // llvmpipe the lookup's code costs even where its branch is never taken.
    const gl::Program& volumeBatch(bool counting) const { return counting ? *volumeBatchCounting_ : *volumeBatch_; }
    const gl::Program& stencil() const { return *stencil_; }
    const LightVolumeGeometry& geometry(const LightTableEntry& e) const {
        return e.volume.shape == VolumeShape::Cone ? cone_ : sphere_[sphereSubdivisions_];
    }
    // The sphere mesh this frame uses (lighting.volume_subdivisions, unitSphereVolume).
    void setSphereSubdivisions(int k) { sphereSubdivisions_ = std::clamp(k, 0, kMaxSphereSubdivisions); }
    int sphereSubdivisions() const { return sphereSubdivisions_; }
    void drawFullscreenTriangle() const { triangle_.draw(); }

    // Batched volume draws: the volume meshes of `rows` (light-table rows of
    // `table`, spheres and cones alike) placed on the CPU, camera-relative,
    // into one vertex buffer whose vertices carry their row; then
    // drawVolumeBatch draws the meshes of rows[first .. first + count) in one
    // call with `program` (in use: a volume or the stencil program). Placing
    // 12 or 26 vertices per light costs the CPU far less than a draw call or
    // an instance on a CPU rasteriser.
    void uploadVolumeBatch(const LightTable& table, const std::vector<std::uint32_t>& rows) const;
    void drawVolumeBatch(const gl::Program& program, int first, int count) const;
    // The unit mesh's local bounding box (for screen rectangles).
    std::pair<glm::vec3, glm::vec3> localBox(VolumeShape shape) const;

private:
    gl::ShaderLibrary::Handle fullscreen_, volume_, fullscreenCounting_, volumeCounting_, volumeBatch_, volumeBatchCounting_,
        stencil_;
    LightVolumeGeometry sphere_[kMaxSphereSubdivisions + 1], cone_;
    int sphereSubdivisions_ = kDefaultSphereSubdivisions;
    struct BatchVertex {
        glm::vec3 position;
        float row;
    };
    mutable std::vector<BatchVertex> batchVertices_;
    mutable std::vector<std::uint32_t> batchIndices_, batchIndexStart_, batchVertexStart_;
    mutable gl::Buffer batchVertexBuffer_, batchIndexBuffer_;
    mutable gl::VertexArray batchVao_;
    gl::FullscreenTriangle triangle_;
};

// One frame of a strategy's work.
struct LightingFrame {
    FrameContext& ctx;
    const LightTable& table;
    // The bounded lights to shade (rows of `table`), spheres before cones.
    std::vector<const LightTableEntry*> lights;
    // Also count light-shader invocations per pixel into lighting.overlap
    // (draw buffer 1); use LightShading's counting programs.
    bool counting = false;
    const LightShading& shading;
    // Call before drawing a light: renders its shadow map when maps are
    // reused, then leaves GL state reset with the L-buffer target bound,
    // additive blending on and the lighting inputs bound.
    std::function<void(const LightTableEntry&)> beginLight;
};

// Where the statistics line says the lights shaded from lists went, unless
// the strategy says otherwise (forward: per-object lists).
inline constexpr const char* kGridInTilesOrClusters = "in tiles or clusters";

// What a strategy did, for the pass's statistics line.
struct StrategyCounts {
    int volumes = 0;     // lights drawn through a volume mesh
    int fullscreen = 0;  // lights drawn over the whole screen
    int culled = 0;      // lights skipped (outside the view frustum)
    int grid = 0;        // lights shaded many at once from lists (tile, cluster or per-object)
    // Where the statistics line says the grid lights went.
    const char* gridWhere = kGridInTilesOrClusters;
    int batches = 0;     // batched volume draws (each covers many lights)
};

class LightingStrategy {
public:
    virtual ~LightingStrategy() = default;
    // The knob value (lighting.strategy = name).
    virtual const char* name() const = 0;
    // One sentence for `list knobs` and the parameter tooltip.
    virtual std::string description() const = 0;
    // Outputs of its own (e.g. per-tile light counts), published by the lighting pass.
    virtual std::vector<OutputDecl> outputs() const { return {}; }
    virtual void setup(gl::ShaderLibrary& shaders) { (void)shaders; }
    // Whether shade() makes this frame's first write of the L-buffer itself
    // (every pixel: shaders/lighting/ambient.glsl's firstRadiance, the
    // ambient term, emission and the sky) in the pass that adds its lights,
    // as tiled shading does (Andersson 2009: one compute pass per tile reads
    // the G-buffer and writes the final radiance). The lighting pass
    // then draws no ambient pass, and blends the directional and unbounded
    // lights after shade() instead of before.
    virtual bool writesFirstRadiance(const FrameContext& ctx) const { (void)ctx; return false; }
    // Whether shade() reads its surfaces from the G-buffer, so that a
    // G-buffer holding one MSAA sample's attributes is shaded as that sample
    // (aa.method=msaa, MsaaPass.h). The forward strategies draw the scene
    // again at the pixel centres instead: false.
    virtual bool shadesFromGBuffer() const { return true; }
    virtual StrategyCounts shade(LightingFrame& frame) = 0;
    // In a frame another strategy shades: writes those of this strategy's own
    // outputs that were asked for (ctx.wants), without shading, so its light
    // lists can be looked at whichever strategy lights the image.
    virtual void writeOutputs(LightingFrame& frame) { (void)frame; }
};

// One light at a time: `draw` for every light of the frame inside the view
// frustum (counted as volumes), the rest counted as culled.
StrategyCounts drawEachLightInView(LightingFrame& frame, const std::function<void(const LightTableEntry&)>& draw);

// The family's registration is graph/MethodSet's, as every method family's;
// strategies registered from outside the library (tests, plug-ins) come after the built-ins.
using LightingStrategyFactory = MethodFactory<LightingStrategy>;
using LightingStrategyCatalog = MethodCatalog<LightingStrategy>;

// The built-in strategies, in the order of the knob's choices (BuiltinStrategies.cpp).
std::vector<LightingStrategyFactory> builtinLightingStrategies();

template <typename T>
using RegisterLightingStrategy = RegisterMethod<LightingStrategy, T>;

}  // namespace dw
