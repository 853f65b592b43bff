#include "renderer/lighting/VolumesStrategy.h"

#include "renderer/lighting/LightLists.h"

namespace dw {

BoolKnob declareInstancedVolumesKnob(KnobRegistry& knobs) {
    if (knobs.find("lighting.instanced_volumes")) return knobs.requireBool("lighting.instanced_volumes");
    return knobs.addBool("lighting.instanced_volumes", true, "lighting",
                         "volume strategies: draw many lights' volumes per instanced call (stencil_volumes: one "
                         "batch of lights with disjoint screen rectangles per call) instead of one call per light");
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
    StrategyCounts c;
    if (!f.ctx.knobs.get(instanced_)) {
        for (const LightTableEntry* e : f.lights) {
            if (!e->inFrustum) {
                ++c.culled;
                continue;
            }
            drawVolume(f, *e);
            ++c.volumes;
        }
        return c;
    }
    // Lights without a map: spheres, then cones (LightingFrame::lights' order).
    const LightLists lists = LightLists::split(f);
    c.culled = lists.culled;
    if (lists.shaded > 0) {
        int spheres = 0;
        for (int i = 0; i < lists.shaded; ++i)
            spheres += f.table.entries[lists.rows[static_cast<std::size_t>(i)]].volume.shape == VolumeShape::Sphere ? 1 : 0;
        f.beginLight(*lists.firstShaded);  // the L-buffer target and blending; it has no map
        volumeState();
        const gl::Program& program = f.shading.volume(f.counting);
        program.use();
        f.shading.uploadVolumeRows(lists.rows);
        f.shading.drawVolumes(program, VolumeShape::Sphere, 0, spheres);
        f.shading.drawVolumes(program, VolumeShape::Cone, spheres, lists.shaded - spheres);
        c.batches = (spheres > 0 ? 1 : 0) + (lists.shaded > spheres ? 1 : 0);
    }
    c.volumes = lists.shaded + lists.shadeOneByOne(f);
    return c;
}

}  // namespace dw
