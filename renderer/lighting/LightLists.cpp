#include "renderer/lighting/LightLists.h"

#include "renderer/lighting/ShadowService.h"
#include "renderer/lighting/VolumesStrategy.h"

namespace dw {

IntKnob declareTileSizeKnob(KnobRegistry& knobs) {
    if (knobs.find("lighting.tile_size")) return knobs.requireInt("lighting.tile_size");
    return knobs.addInt("lighting.tile_size", 16, 4, 32, "lighting",
                        "screen tile edge of the tiled and clustered strategies (one work group per tile): smaller "
                        "tiles cull tighter but cull more often (seed 003 section 2.2.1)",
                        "px", true);
}

int tileSizeOf(const KnobRegistry& knobs, IntKnob knob) { return knobs.get(knob); }

LightLists LightLists::split(const LightingFrame& frame) {
    LightLists l;
    std::vector<std::uint32_t> shadowed;
    for (const LightTableEntry* e : frame.lights) {
        if (!e->inFrustum) {
            ++l.culled;
            continue;
        }
        if (frame.ctx.shadows && e->shadowed) {
            l.oneByOne.push_back(e);
            shadowed.push_back(static_cast<std::uint32_t>(e->row));
        } else {
            if (!l.firstShaded) l.firstShaded = e;
            l.rows.push_back(static_cast<std::uint32_t>(e->row));
        }
    }
    l.shaded = static_cast<int>(l.rows.size());
    l.rows.insert(l.rows.end(), shadowed.begin(), shadowed.end());
    return l;
}

void LightLists::upload(gl::Buffer& buffer) const {
    const std::size_t bytes = std::max<std::size_t>(rows.size(), 1) * sizeof(std::uint32_t);
    buffer.ensureSize(bytes, "lighting candidates");
    if (!rows.empty()) buffer.update(0, rows.size() * sizeof(std::uint32_t), rows.data());
    buffer.bindBase(GL_SHADER_STORAGE_BUFFER, binding::kLightCandidatesSsbo);
}

int LightLists::shadeOneByOne(LightingFrame& frame) const {
    for (const LightTableEntry* e : oneByOne) VolumesStrategy::drawVolume(frame, *e);
    return static_cast<int>(oneByOne.size());
}

}  // namespace dw
