#include "renderer/lighting/LightLists.h"
#include "renderer/gl/MemoryLedger.h"

#include <string>

#include "renderer/Error.h"
#include "renderer/lighting/LightTable.h"
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

void CandidateBuffers::create() {
    gl::MemoryOwner owner("light lists");
    rows = gl::Buffer::create(sizeof(std::uint32_t), nullptr, true, "lighting candidates");
    data = gl::Buffer::create(sizeof(glm::vec4) * 4, nullptr, true, "lighting candidate data");
    dataTexture = gl::Texture::createBuffer(GL_RGBA32F);
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
}

void LightLists::upload(CandidateBuffers& buffers, const LightTable& table) const {
    const std::size_t n = std::max<std::size_t>(rows.size(), 1);
    gl::MemoryOwner owner("light lists");
    buffers.rows.ensureSize(n * sizeof(std::uint32_t), "lighting candidates");
    if (!rows.empty()) buffers.rows.update(0, rows.size() * sizeof(std::uint32_t), rows.data());
    buffers.rows.bindBase(GL_SHADER_STORAGE_BUFFER, binding::LIGHT_CANDIDATES_SSBO);

    // GL 4.5 guarantees 65536 texels (16384 candidates); llvmpipe and the
    // desktop drivers allow far more, but past the limit texelFetch reads 0.
    if (buffers.maxTexels > 0 && rows.size() * 4 > static_cast<std::size_t>(buffers.maxTexels))
        throw GlUnsupportedError(std::to_string(rows.size()) + " lights for the tiled or clustered lists need " +
                                 std::to_string(rows.size() * 4) + " texels of light data; this GL allows at most " +
                                 std::to_string(buffers.maxTexels) + " (GL_MAX_TEXTURE_BUFFER_SIZE)");

    std::vector<glm::vec4> texels;
    texels.reserve(rows.size() * 4);
    for (std::uint32_t row : rows) {
        const LightGpu& l = table.rows[row];
        // Only a spot light's cone limits it: the others get one that holds
        // every direction, so tiles.glsl's candidateReaches tests no type.
        const bool spot = table.entries[row].light->type == LightType::Spot;
        texels.insert(texels.end(), {l.positionRadius, spot ? l.directionCutoff : glm::vec4(0.0f, 0.0f, 0.0f, -1.0f),
                                     l.intensityExponent, l.attenuation});
    }
    buffers.data.ensureSize(n * 4 * sizeof(glm::vec4), "lighting candidate data");
    if (!texels.empty()) buffers.data.update(0, texels.size() * sizeof(glm::vec4), texels.data());
    // ensureSize may have re-created the buffer: point the texture at today's.
    buffers.dataTexture.attachBuffer(buffers.data.id());
    buffers.dataTexture.bind(binding::LIGHT_CANDIDATE_DATA_TEXTURE);
}

int LightLists::shadeOneByOne(LightingFrame& frame) const {
    for (const LightTableEntry* e : oneByOne) VolumesStrategy::drawVolume(frame, *e);
    return static_cast<int>(oneByOne.size());
}

}  // namespace dw
