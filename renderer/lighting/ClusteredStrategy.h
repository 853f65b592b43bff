#pragma once
// Clustered deferred shading (Olsson, Billeter and Assarsson, "Clustered
// Deferred and Forward Shading", HPG 2012; seed 003 section 2.2.1): view-space
// clusters, screen tiles of lighting.tile_size pixels times
// lighting.cluster_slices exponential depth slices, with light lists built on
// the GPU in three steps:
//   1. cluster_bounds.comp: each surface pixel widens its cluster's explicit
//      depth bounds (paper section 4.4), so empty clusters get no lights and
//      occupied ones are as thin as their surfaces;
//   2. cluster_assign.comp: one invocation per occupied cluster tests the
//      candidate lights (those whose conservative cluster range, worked out
//      here on the CPU, holds it) against the cluster's volume and writes its
//      count and its slice of one index list (an atomic add hands out the
//      slices; the list's size is the sum of the ranges, so it cannot
//      overflow), counting and filling over slices of the candidates;
//   3. clustered.frag: full screen, each pixel adds its cluster's lights with
//      the light shader's lightRadiance, blended into the L-buffer (and its
//      count into lighting.overlap), in more than one pass when a list could
//      be longer than one invocation's loop may run.
// Where the driver ends an invocation's loops after a number of iterations
// (llvmpipe: 65 535, renderer/gl/ShaderLoopLimit.h), the slices of step 2
// and the passes of step 3 keep every invocation within 90% of it: without
// them, more than about 32 000 lights in view lost lights.
// Lights with a shadow map are shaded one at a time (LightLists.h). Writes
// lighting.cluster_counts (the pixel's cluster list length) when asked for.
#include "renderer/gl/Buffer.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/lighting/LightLists.h"
#include "renderer/lighting/LightingStrategy.h"

namespace dw {

class ClusteredStrategy : public LightingStrategy {
public:
    explicit ClusteredStrategy(KnobRegistry& knobs);
    const char* name() const override { return "clustered"; }
    std::string description() const override {
        return "view-space clusters (screen tiles x exponential depth slices, lighting.cluster_slices) with light "
               "lists built on the GPU, then one full-screen pass (Olsson et al. 2012)";
    }
    std::vector<OutputDecl> outputs() const override;
    void setup(gl::ShaderLibrary& shaders) override;
    StrategyCounts shade(LightingFrame& frame) override;
    void writeOutputs(LightingFrame& frame) override;

private:
    struct Grid {
        int tile = 16, tilesX = 0, tilesY = 0, slices = 1;
        float nearPlane = 0.1f, scale = 1.0f;  // slice(d) = floor(log(d / near) * scale)
        int longestList = 0;                    // a bound on every cluster's list length
        int clusters() const { return tilesX * tilesY * slices; }
    };
    // Steps 1 and 2: the grid's bounds and light lists for `lists`.
    Grid build(LightingFrame& frame, const LightLists& lists);
    void setGridUniforms(const gl::Program& program, const Grid& grid) const;
    void bindBuffers() const;
    void writeCounts(LightingFrame& frame, const Grid& grid);

    IntKnob tileSize_;
    IntKnob slices_;
    int loopLimit_ = 0;  // gl::shaderLoopIterationLimit() of the context setup ran in
    // Compiled on first use, so sessions that never pick this strategy pay nothing.
    const gl::Program& program(gl::ShaderLibrary::Handle& handle, const gl::ProgramDesc& desc);
    gl::ShaderLibrary* shaders_ = nullptr;
    gl::ShaderLibrary::Handle bounds_, assign_, shade_, shadeCounting_, counts_;
    CandidateBuffers candidates_;
    gl::Buffer ranges_, cells_, index_;
    gl::Buffer filled_;  // per cluster, the list entries cluster_assign.comp's FILL stage has written
    gl::Texture rangesTexture_;  // ranges_ as RGBA32UI texels
};

}  // namespace dw
