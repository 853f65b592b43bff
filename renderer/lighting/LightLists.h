#pragma once
// What the tiled and clustered strategies share (seed 003 section 2.2.1; Olsson,
// Billeter and Assarsson 2012): the screen-tile size knob, the lights they
// take, and the one-light-at-a-time path for lights with a shadow map.
//
// Why shadowed lights go one at a time: with shadows.reuse_map one map layer
// serves every light and is rendered just before its light is shaded
// (LightingFrame::beginLight), so no moment exists at which the maps of all
// lights in a tile are there together. Those lights are drawn like
// VolumesStrategy draws (their back faces, after their map), and the grid
// shades the rest in one pass. They still count in the grid's lists
// (lighting.tile_counts, lighting.cluster_counts), which say which lights can
// reach a tile, not which of them the grid shaded.
#include <cstdint>
#include <vector>

#include "renderer/gl/Buffer.h"
#include "renderer/gl/Texture.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/lighting/LightingStrategy.h"
#include "shaders/common/bindings.glsl"  // dw::binding, the binding points

namespace dw {

// lighting.tile_size, declared by whichever strategy asks first.
IntKnob declareTileSizeKnob(KnobRegistry& knobs);
// Its value in pixels (4 to 32).
int tileSizeOf(const KnobRegistry& knobs, IntKnob knob);

// The grid strategies' candidates on the GPU: their light-table rows (SSBO
// at LIGHT_CANDIDATES_SSBO) and, in the same order, the four vec4 of each
// candidate's light that culling and shading read (positionRadius,
// directionCutoff, intensityExponent, attenuation; directionCutoff is
// (0, 0, 0, -1) for a light that is not a spot), as an RGBA32F buffer
// texture at LIGHT_CANDIDATE_DATA_TEXTURE. The shaders fetch light data as texels
// rather than from the light table's SSBO: on llvmpipe a texel fetch at a
// per-invocation index is one vector gather, an SSBO or shared-memory read a
// loop over the SIMD lanes (tiled lighting pass at 1000 lights, 640x360:
// see docs/bench.md).
struct CandidateBuffers {
    gl::Buffer rows;
    gl::Buffer data;
    gl::Texture dataTexture;
    GLint maxTexels = 0;  // GL_MAX_TEXTURE_BUFFER_SIZE, read by create()
    void create();
};

struct LightLists {
    // Light-table rows the grid culls: the first `shaded` it shades, the
    // rest (with a shadow map) it only counts. In LightingFrame::lights'
    // order within each part.
    std::vector<std::uint32_t> rows;
    int shaded = 0;
    // The first of the shaded lights: a fragment pass over the grid calls
    // frame.beginLight with it to get the L-buffer target (it has no map to render).
    const LightTableEntry* firstShaded = nullptr;
    // Lights with a shadow map, for shadeOneByOne.
    std::vector<const LightTableEntry*> oneByOne;
    int culled = 0;  // outside the view frustum (LightTableEntry::inFrustum)

    static LightLists split(const LightingFrame& frame);
    // Uploads `rows` and their lights' data from `table` (at least one
    // element each) and binds both (see CandidateBuffers).
    void upload(CandidateBuffers& buffers, const LightTable& table) const;
    // Shades oneByOne like VolumesStrategy (frame.beginLight first, so a
    // reused map is rendered), returning how many it drew.
    int shadeOneByOne(LightingFrame& frame) const;
};

}  // namespace dw
