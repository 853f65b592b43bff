#pragma once
// Shadow maps for every shadow-casting light in view (seed 000 sections 4.4
// and 5.5, seed 002 section 3.3), through renderer/lighting/ShadowMaps. Reads
// the light table and adds each light's shadow lookup into it (modifies
// lights.table); writes shadow.maps (2D array: directional and spot lights),
// shadow.cubes (cube array: point lights and wide spots) and
// shadow.paraboloids (2D array, two layers a light). With shadows.reuse_map
// (seed 002's flip-flop) it renders nothing up front: the lighting pass asks
// for each map just before shading its light, and one layer serves all; when
// a shadow output is asked for, every map is kept so all can be seen.
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/lighting/ShadowMaps.h"
#include "renderer/lighting/ShadowService.h"

namespace dw {

class ShadowPass : public RenderPass, public ShadowService {
public:
    explicit ShadowPass(KnobRegistry& knobs);
    const char* name() const override { return "shadows"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry&) const override { return {{}, {}, {"lights.table"}}; }
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    // "N shadow maps (...), one reused per kind: X MiB (one per light: Y MiB);
    // casters D/N, T/U triangles": D draws drawn into all maps this frame
    // over the N that would be without culling (shadows.cull_casters), and
    // the triangles likewise. Read after the frame: with shadows.reuse_map
    // the lighting pass renders the maps after this pass ran.
    std::string stats() const override;

    bool prepare(FrameContext& ctx, const LightTableEntry& entry) override;
    void bind() const override { maps_.bind(); }
    bool everyMapKept() const override { return !reuse_; }

    // Maps rendered in the last frame, the bytes they took, and what one map
    // per light would take.
    int mapsRendered() const { return maps_.mapsRendered(); }
    std::size_t bytesInUse() const { return maps_.bytesInUse(); }
    std::size_t bytesKeepingAll() const { return maps_.bytesKeepingAll(); }

private:
    ShadowLookup render(FrameContext& ctx, const LightTableEntry& entry, int slot);
    ShadowMaps maps_;
    bool reuse_ = true;
    int counts_[3] = {0, 0, 0};  // shadowed lights by ShadowMaps::Kind this frame
};

}  // namespace dw
