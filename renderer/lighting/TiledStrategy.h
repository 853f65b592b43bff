#pragma once
// Tiled deferred shading (seed 003 section 2.2.1, seed 004 "Moving forward"):
// a compute pass (shaders/lighting/tiled.comp) with one work group per screen
// tile of lighting.tile_size pixels. Each group takes the nearest and farthest
// depth of its tile's surfaces (gbuffer.depth), culls every light's bounding
// sphere against the tile's frustum between them (and, with
// lighting.tile_depth_mask, against the tile's depth slices that hold a
// surface: 2.5D culling, Harada 2012) into a list in shared memory, and adds
// the list's lights that reach each pixel into the L-buffer (imageStore on
// lbuffer) with the light shader's lightRadiance (shaders/lighting/
// shade.glsl), so the image is the volume strategies'. With
// lighting.tile_ambient (the default) the pass also makes the L-buffer's first
// write (the ambient term, emission, the sky: shaders/lighting/ambient.glsl)
// with its lights in one store per pixel, and the lighting pass draws no
// ambient pass before it; without, it adds to what the ambient pass wrote
// (imageLoad + imageStore), as every dispatch after the first does (more
// than one dispatch's candidates: 4096, fewer on llvmpipe). lighting.tile_walk
// chooses how a pixel walks the list: marking which lights reach first and
// shading only those (the default on llvmpipe), or testing and shading each
// in turn (elsewhere). Lights with a shadow map are shaded one at a time
// (see LightLists.h). Writes lighting.tile_counts (per pixel, its tile's list
// length) when asked for, and adds its per-pixel work into lighting.overlap.
// With lighting.tile_coarse (the default) a coarse pass
// (shaders/lighting/tiled_coarse.comp) first culls the lights against coarse
// tiles of 4 x 4 tiles into a bit mask each, and a tile tests only its
// coarse tile's lights: a two-level light grid, whose coarse test keeps
// everything a tile's test keeps. lighting.tile_threads sets the
// invocations per group; the image is the same for every value, either
// depth-mask setting, either walk and with or without the coarse pass (each
// pixel sums its reaching lights in candidate order).
#include <map>
#include <tuple>

#include "renderer/gl/Buffer.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/lighting/LightLists.h"
#include "renderer/lighting/LightingStrategy.h"

namespace dw {

class TiledStrategy : public LightingStrategy {
public:
    explicit TiledStrategy(KnobRegistry& knobs);
    const char* name() const override { return "tiled"; }
    std::string description() const override {
        return "a compute pass per screen tile: depth bounds, the lights that meet the tile's frustum, all shaded "
               "at once (lighting.tile_size)";
    }
    std::vector<OutputDecl> outputs() const override;
    void setup(gl::ShaderLibrary& shaders) override;
    // lighting.tile_ambient: the first dispatch writes every pixel's first
    // radiance with its lights.
    bool writesFirstRadiance(const FrameContext& ctx) const override { return ctx.knobs.get(ambient_); }
    StrategyCounts shade(LightingFrame& frame) override;
    void writeOutputs(LightingFrame& frame) override;

private:
    // Culls (and shades, when `shade`) every tile.
    void dispatch(LightingFrame& frame, const LightLists& lists, bool shade);
    // lighting.tile_threads = 0 means one invocation per pixel, except on
    // llvmpipe one SIMD batch: its vector width / 32 lanes, which this
    // returns (0 on other drivers).
    static int simdLanes();

    IntKnob tileSize_;
    IntKnob tileThreads_;
    BoolKnob depthMask_;
    BoolKnob coarse_;
    BoolKnob ambient_;
    EnumKnob walk_;  // lighting.tile_walk: auto, mark, branch
    int walkMark_ = 0, walkBranch_ = 0;
    int cpuLanes_ = 0;  // simdLanes() of the context setup ran in
    int loopLimit_ = 0;  // gl::shaderLoopIterationLimit() there: bounds the candidates per dispatch
    gl::ShaderLibrary* shaders_ = nullptr;
    // The coarse culling pass and the tiles' pass.
    struct Programs {
        gl::ShaderLibrary::Handle coarse, fine;
    };
    // Per tile size, threads, depth mask, coarse pass and walk, compiled on first use.
    std::map<std::tuple<int, int, bool, bool, bool>, Programs> programs_;
    CandidateBuffers candidates_;
    // Per coarse tile, MAX_CANDIDATES bits: the candidates its pass kept.
    gl::Buffer coarseMask_;
};

}  // namespace dw
