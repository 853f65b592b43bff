#include "renderer/lighting/FullscreenStrategy.h"

namespace dw {

StrategyCounts FullscreenStrategy::shade(LightingFrame& f) {
    StrategyCounts c;
    const gl::Program& program = f.shading.fullscreen(f.counting);
    for (const LightTableEntry* e : f.lights) {
        f.beginLight(*e);
        program.use();
        program.set(0, e->row);
        f.shading.drawFullscreenTriangle();
        ++c.fullscreen;
    }
    return c;
}

}  // namespace dw
