#include "renderer/lighting/VolumesStrategy.h"

namespace dw {

StrategyCounts VolumesStrategy::shade(LightingFrame& f) {
    StrategyCounts c;
    const gl::Program& program = f.shading.volume(f.counting);
    for (const LightTableEntry* e : f.lights) {
        if (!e->inFrustum) {
            ++c.culled;
            continue;
        }
        f.beginLight(*e);
        // Volumes may cross the near and far planes: clamp depth instead of clipping.
        glEnable(GL_DEPTH_CLAMP);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        program.use();
        program.set(0, e->row);
        f.shading.geometry(*e).draw();
        ++c.volumes;
    }
    return c;
}

}  // namespace dw
