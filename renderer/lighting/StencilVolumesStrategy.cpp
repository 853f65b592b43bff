#include "renderer/lighting/StencilVolumesStrategy.h"

#include <algorithm>

#include "renderer/lighting/LightLists.h"
#include "renderer/lighting/ScreenBatches.h"
#include "renderer/lighting/VolumesStrategy.h"

namespace dw {

StencilVolumesStrategy::StencilVolumesStrategy(KnobRegistry& knobs) : batched_(declareBatchedVolumesKnob(knobs)) {
    stencilCount_ = knobs.addEnum("lighting.stencil_count", {"depth_fail", "depth_pass"}, DepthFail, "lighting",
                                  "stencil counting of the volume test: depth_fail (correct with the camera inside a "
                                  "volume) or depth_pass (seed 001's table as written; loses lights around the camera)");
}

namespace {

// 1. Mark pixels whose surface lies inside the volume.
void markState(const FrameContext& ctx, bool depthFail) {
    glEnable(GL_DEPTH_CLAMP);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(ctx.depth().nearer());
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
}

// 2. Shade the marked pixels through the back faces, zeroing the stencil on
//    the way so the next light (or batch) starts clean.
void shadeState() {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
}

}  // namespace

StrategyCounts StencilVolumesStrategy::shade(LightingFrame& f) {
    const bool depthFail = f.ctx.knobs.get(stencilCount_) == DepthFail;
    const gl::Program& volume = f.shading.volume(f.counting);
    const gl::Program& stencil = f.shading.stencil();
    auto oneLight = [&](const LightTableEntry& e) {
        f.beginLight(e);
        const LightVolumeGeometry& geometry = f.shading.geometry(e);
        markState(f.ctx, depthFail);
        stencil.use();
        stencil.set(0, e.row);
        geometry.draw();
        shadeState();
        volume.use();
        volume.set(0, e.row);
        geometry.draw();
    };

    if (!f.ctx.knobs.get(batched_)) return drawEachLightInView(f, oneLight);
    StrategyCounts c;

    // Lights without a map, batched: within a batch no two screen rectangles
    // overlap, so one draw marks them all and one shades them all.
    const LightLists lists = LightLists::split(f);
    c.culled = lists.culled;
    if (lists.shaded > 0) {
        const glm::dmat4 worldToClip = f.ctx.camera.worldToClip();
        struct Batch {
            int first = 0, count = 0;
        };
        // Spheres and cones alike: the batch's meshes share one vertex buffer.
        std::vector<std::uint32_t> rows(lists.rows.begin(), lists.rows.begin() + lists.shaded), ordered;
        std::vector<PixelRect> rects;
        for (const std::uint32_t row : rows) {
            const LightTableEntry& e = f.table.entries[row];
            const auto [boxMin, boxMax] = f.shading.localBox(e.volume.shape);
            rects.push_back(screenRect(worldToClip * glm::dmat4(e.volume.transform), boxMin, boxMax, f.ctx.width, f.ctx.height));
        }
        const std::vector<int> batchOf = disjointBatches(rects, f.ctx.width, f.ctx.height);
        const int n = *std::max_element(batchOf.begin(), batchOf.end()) + 1;
        std::vector<Batch> batches(static_cast<std::size_t>(n));
        std::vector<std::vector<std::uint32_t>> members(static_cast<std::size_t>(n));
        for (std::size_t i = 0; i < rows.size(); ++i) members[static_cast<std::size_t>(batchOf[i])].push_back(rows[i]);
        for (int b = 0; b < n; ++b) {
            batches[static_cast<std::size_t>(b)] = {static_cast<int>(ordered.size()), static_cast<int>(members[static_cast<std::size_t>(b)].size())};
            ordered.insert(ordered.end(), members[static_cast<std::size_t>(b)].begin(), members[static_cast<std::size_t>(b)].end());
        }
        f.beginLight(*lists.firstShaded);  // the L-buffer target and blending; it has no map
        const gl::Program& batchVolume = f.shading.volumeBatch(f.counting);
        f.shading.uploadVolumeBatch(f.table, ordered);
        for (const Batch& b : batches) {
            markState(f.ctx, depthFail);
            stencil.use();
            f.shading.drawVolumeBatch(stencil, b.first, b.count);
            shadeState();
            batchVolume.use();
            f.shading.drawVolumeBatch(batchVolume, b.first, b.count);
        }
        c.batches = static_cast<int>(batches.size());
    }
    for (const LightTableEntry* e : lists.oneByOne) oneLight(*e);
    c.volumes = lists.shaded + static_cast<int>(lists.oneByOne.size());
    return c;
}

}  // namespace dw
