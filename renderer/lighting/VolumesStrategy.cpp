#include "renderer/lighting/VolumesStrategy.h"

namespace dw {

void VolumesStrategy::drawVolume(LightingFrame& f, const LightTableEntry& e) {
    f.beginLight(e);
    // Volumes may cross the near and far planes: clamp depth instead of clipping.
    glEnable(GL_DEPTH_CLAMP);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    const gl::Program& program = f.shading.volume(f.counting);
    program.use();
    program.set(0, e.row);
    f.shading.geometry(e).draw();
}

StrategyCounts VolumesStrategy::shade(LightingFrame& f) {
    StrategyCounts c;
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

}  // namespace dw
