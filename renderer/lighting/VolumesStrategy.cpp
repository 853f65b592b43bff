#include "renderer/lighting/VolumesStrategy.h"

#include "renderer/lighting/LightLists.h"

namespace dw {

BoolKnob declareBatchedVolumesKnob(KnobRegistry& knobs) {
    if (knobs.find("lighting.batched_volumes")) return knobs.requireBool("lighting.batched_volumes");
    return knobs.addBool("lighting.batched_volumes", true, "lighting",
                         "volume strategies: draw many lights' volumes per call, their meshes placed on the CPU into "
                         "one vertex buffer (stencil_volumes: one batch of lights with disjoint screen rectangles per "
                         "call) instead of one call per light");
}

namespace {
// Back faces only; volumes may cross the near and far planes: clamp depth instead of clipping.
void volumeState() {
    glEnable(GL_DEPTH_CLAMP);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
}
}  // namespace

void VolumesStrategy::drawVolume(LightingFrame& f, const LightTableEntry& e) {
    f.beginLight(e);
    volumeState();
    const gl::Program& program = f.shading.volume(f.counting);
    program.use();
    program.set(0, e.row);
    f.shading.geometry(e).draw();
}

StrategyCounts VolumesStrategy::shade(LightingFrame& f) {
    if (!f.ctx.knobs.get(batched_)) return drawEachLightInView(f, [&](const LightTableEntry& e) { drawVolume(f, e); });
    StrategyCounts c;
    // Lights without a map, spheres and cones, in one draw.
    const LightLists lists = LightLists::split(f);
    c.culled = lists.culled;
    if (lists.shaded > 0) {
        f.beginLight(*lists.firstShaded);  // the L-buffer target and blending; it has no map
        volumeState();
        const gl::Program& program = f.shading.volumeBatch(f.counting);
        program.use();
        f.shading.uploadVolumeBatch(f.table, {lists.rows.begin(), lists.rows.begin() + lists.shaded});
        f.shading.drawVolumeBatch(program, 0, lists.shaded);
        c.batches = 1;
    }
    c.volumes = lists.shaded + lists.shadeOneByOne(f);
    return c;
}

}  // namespace dw
