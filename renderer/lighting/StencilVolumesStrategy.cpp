#include "renderer/lighting/StencilVolumesStrategy.h"

namespace dw {

StencilVolumesStrategy::StencilVolumesStrategy(KnobRegistry& knobs) {
    stencilCount_ = knobs.addEnum("lighting.stencil_count", {"depth_fail", "depth_pass"}, DepthFail, "lighting",
                                  "stencil counting of the volume test: depth_fail (correct with the camera inside a "
                                  "volume) or depth_pass (seed 001's table as written; loses lights around the camera)");
}

StrategyCounts StencilVolumesStrategy::shade(LightingFrame& f) {
    StrategyCounts c;
    const bool depthFail = f.ctx.knobs.get(stencilCount_) == DepthFail;
    const gl::Program& volume = f.shading.volume(f.counting);
    for (const LightTableEntry* e : f.lights) {
        if (!e->inFrustum) {
            ++c.culled;
            continue;
        }
        f.beginLight(*e);
        const LightVolumeGeometry& geometry = f.shading.geometry(*e);
        glEnable(GL_DEPTH_CLAMP);
        glEnable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
        // 1. Mark pixels whose surface lies inside the volume.
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDisable(GL_BLEND);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(f.ctx.depth().nearer());
        glDepthMask(GL_FALSE);
        glDisable(GL_CULL_FACE);
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        if (depthFail) {
            glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
            glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
        } else {
            glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
            glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
        }
        f.shading.stencil().use();
        f.shading.stencil().set(0, e->row);
        geometry.draw();
        // 2. Shade the marked pixels through the back faces, zeroing the
        //    stencil on the way so the next light starts clean.
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glEnable(GL_BLEND);
        glDisable(GL_DEPTH_TEST);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
        volume.use();
        volume.set(0, e->row);
        geometry.draw();
        ++c.volumes;
    }
    return c;
}

}  // namespace dw
