#include "renderer/passes/ShadowPass.h"

#include <cstdio>

#include "renderer/Error.h"
#include "renderer/graph/PassTimer.h"
#include "renderer/lighting/LightTable.h"
#include "renderer/scene/Scene.h"

namespace dw {

namespace {
const char* const kMapOutputs[3] = {"shadow.maps", "shadow.cubes", "shadow.paraboloids"};

std::string mib(std::size_t b) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.1f MiB", static_cast<double>(b) / (1024.0 * 1024.0));
    return buf;
}
}  // namespace

ShadowPass::ShadowPass(KnobRegistry& knobs) : maps_(knobs) {}

std::vector<OutputDecl> ShadowPass::outputs() const {
    // Scalar, not Depth: a map's depth is the light's (orthographic for the
    // sun, perspective for spots), so the camera's linearisation would be wrong;
    // the view shows the raw window depth with an automatic range.
    return {{kMapOutputs[0], OutputKind::Scalar,
             "window depth of every directional and spot light's shadow map, a layer each (2D array, DEPTH32F)", imported(), 1},
            {kMapOutputs[1], OutputKind::Scalar,
             "linear distance from the light of every point light's (and wide spot's) cube shadow map (cube array, DEPTH32F)", imported(), 1},
            {kMapOutputs[2], OutputKind::Scalar,
             "linear distance from the light in the dual-paraboloid maps, front and back layer per light (2D array, DEPTH32F)", imported(), 1}};
}

std::string ShadowPass::skipReason(const KnobRegistry& knobs, const Scene& scene) const {
    if (!maps_.enabled(knobs)) return "switched off (shadows.enabled = false)";
    for (const Light& l : scene.lights)
        if (l.enabled && l.castShadows) return {};
    return "no light casts shadows (a light needs \"shadow\": true)";
}

void ShadowPass::setup(gl::ShaderLibrary& shaders) { maps_.setup(shaders); }

ShadowLookup ShadowPass::render(FrameContext& ctx, const LightTableEntry& entry, int slot) {
    if (ctx.timer) ctx.timer->beginSubSpan("shadow maps");
    const ShadowLookup s = maps_.render(ctx, *entry.light, entry.volume.radius, slot);
    if (ctx.timer) ctx.timer->endSubSpan();
    LightGpu& row = ctx.lightTable->rows[entry.row];
    row.shadowMatrix = s.matrix;
    row.shadowParams = s.params;
    row.shadowRange = s.range;
    return s;
}

void ShadowPass::execute(FrameContext& ctx) {
    LightTable& table = *ctx.lightTable;
    const KnobRegistry& k = ctx.knobs;
    // Asked to show the maps, or the light table with its lookups: keep every
    // map, whatever shadows.reuse_map says (reused maps exist one at a time,
    // and a reused light's lookup is written only just before it is shaded).
    const bool shown = ctx.wants(kMapOutputs[0]) || ctx.wants(kMapOutputs[1]) || ctx.wants(kMapOutputs[2]) ||
                       ctx.requested.count("lights.table");
    reuse_ = maps_.reuse(k) && !shown;
    // Maps for the lights that cast shadows and can be seen (a light outside
    // the frustum lights nothing in view).
    int counts[3] = {0, 0, 0};
    for (LightTableEntry& e : table.entries) {
        e.shadowed = e.light->castShadows && e.inFrustum;
        if (e.shadowed) ++counts[maps_.kindOf(*e.light, k)];
    }
    static const char* const kWhich[3] = {"directional or spot light (up to 60 degrees)",
                                          "point light or wider spot with shadows.point_method = cube",
                                          "point light or wider spot with shadows.point_method = dual_paraboloid"};
    for (int kind = 0; kind < 3; ++kind)
        if (counts[kind] == 0 && ctx.wants(kMapOutputs[kind]))
            throw Error(std::string(kMapOutputs[kind]) + " is empty this frame: no " + kWhich[kind] +
                        " in view casts shadows");
    maps_.beginFrame(ctx, counts, reuse_);
    for (int kind = 0; kind < 3; ++kind)
        ctx.outputs.bind(kMapOutputs[kind], counts[kind] > 0 ? &maps_.maps(static_cast<ShadowMaps::Kind>(kind)) : nullptr, 1);
    if (!reuse_) {
        int slot[3] = {0, 0, 0};
        for (const LightTableEntry& e : table.entries)
            if (e.shadowed) render(ctx, e, slot[maps_.kindOf(*e.light, k)]++);
        if (!table.rows.empty()) table.buffer->update(0, table.rows.size() * sizeof(LightGpu), table.rows.data());
    }
    ctx.shadows = this;
    for (int kind = 0; kind < 3; ++kind) counts_[kind] = counts[kind];
}

std::string ShadowPass::stats() const {
    const int total = counts_[0] + counts_[1] + counts_[2];
    const ShadowMaps::CasterCounts& c = maps_.casters();
    return std::to_string(total) + " shadow maps (" + std::to_string(counts_[0]) + " 2D, " + std::to_string(counts_[1]) +
           " cube, " + std::to_string(counts_[2]) + " paraboloid), " + (reuse_ ? "one reused per kind: " : "all kept: ") +
           mib(maps_.bytesInUse()) + " (one per light: " + mib(maps_.bytesKeepingAll()) + "); casters " +
           std::to_string(c.drawn) + "/" + std::to_string(c.total) + ", " + std::to_string(c.trianglesDrawn) + "/" +
           std::to_string(c.trianglesTotal) + " triangles";
}

bool ShadowPass::prepare(FrameContext& ctx, const LightTableEntry& entry) {
    if (!reuse_ || !entry.shadowed) return false;
    render(ctx, entry, 0);
    ctx.lightTable->uploadRow(entry.row);
    return true;
}

}  // namespace dw
