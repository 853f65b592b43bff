#include "renderer/lighting/ClusteredStrategy.h"
#include "renderer/gl/MemoryLedger.h"

#include <algorithm>
#include <cmath>

#include "renderer/gl/ShaderLoopLimit.h"
#include "renderer/gl/Texture.h"
#include "renderer/lighting/LightTable.h"

namespace dw {

namespace {

constexpr const char* kClusterCounts = "lighting.cluster_counts";

struct ClusterCell {
    std::uint32_t distMin, distMax, offset, count;
};

std::uint32_t packRange(int lo, int hi) {
    return static_cast<std::uint32_t>(lo) | (static_cast<std::uint32_t>(hi) << 16);
}

}  // namespace

ClusteredStrategy::ClusteredStrategy(KnobRegistry& knobs) : tileSize_(declareTileSizeKnob(knobs)) {
    slices_ = knobs.addInt("lighting.cluster_slices", 16, 1, 64, "lighting",
                           "depth slices of the clustered strategy, spaced exponentially from the near plane to the "
                           "farthest light's reach (Olsson et al. 2012)",
                           "", true);
}

std::vector<OutputDecl> ClusteredStrategy::outputs() const {
    return {{kClusterCounts, OutputKind::Count,
             "clustered: the bounded lights in each surface pixel's cluster list (its tile between the cluster's "
             "nearest and farthest surface), lights with a shadow map included (R32F)",
             texture2D(GL_R32F), 1, true}};
}

void ClusteredStrategy::setup(gl::ShaderLibrary& shaders) {
    shaders_ = &shaders;
    loopLimit_ = gl::shaderLoopIterationLimit();
    gl::MemoryOwner owner("light lists");
    candidates_.create();
    ranges_ = gl::Buffer::create(16, nullptr, true, "cluster ranges");
    rangesTexture_ = gl::Texture::createBuffer(GL_RGBA32UI);
    cells_ = gl::Buffer::create(sizeof(ClusterCell), nullptr, true, "cluster grid");
    index_ = gl::Buffer::create(8, nullptr, true, "cluster light index");
    filled_ = gl::Buffer::create(4, nullptr, true, "cluster fill counts");
}

const gl::Program& ClusteredStrategy::program(gl::ShaderLibrary::Handle& handle, const gl::ProgramDesc& desc) {
    if (!handle) handle = shaders_->get(desc);
    return *handle;
}

void ClusteredStrategy::bindBuffers() const {
    candidates_.rows.bindBase(GL_SHADER_STORAGE_BUFFER, binding::LIGHT_CANDIDATES_SSBO);
    candidates_.dataTexture.bind(binding::LIGHT_CANDIDATE_DATA_TEXTURE);
    cells_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::CLUSTER_GRID_SSBO);
    index_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::CLUSTER_INDEX_SSBO);
    filled_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::CLUSTER_FILL_SSBO);
    rangesTexture_.attachBuffer(ranges_.id());  // ensureSize may have re-created it
    rangesTexture_.bind(binding::CLUSTER_RANGE_TEXTURE);
}

void ClusteredStrategy::setGridUniforms(const gl::Program& p, const Grid& g) const {
    p.set(4, glm::ivec2(g.tilesX, g.tilesY));
    p.set(5, glm::ivec2(g.tile, g.slices));
    p.set(6, glm::vec2(g.nearPlane, g.scale));
}

ClusteredStrategy::Grid ClusteredStrategy::build(LightingFrame& f, const LightLists& lists) {
    FrameContext& ctx = f.ctx;
    Grid g;
    g.tile = tileSizeOf(ctx.knobs, tileSize_);
    g.tilesX = (ctx.width + g.tile - 1) / g.tile;
    g.tilesY = (ctx.height + g.tile - 1) / g.tile;
    g.slices = ctx.knobs.get(slices_);
    g.nearPlane = ctx.camera.clip.x;
    // Slices reach from the near plane to the farthest point any light
    // reaches (nothing beyond is lit; farther surfaces fall in the last slice).
    float reach = 0.0f;
    for (std::uint32_t row : lists.rows) {
        const glm::vec4& pr = f.table.rows[row].positionRadius;
        reach = std::max(reach, -pr.z + pr.w);
    }
    const float farPlane = std::clamp(reach, g.nearPlane * 1.01f, std::max(ctx.camera.clip.y, g.nearPlane * 1.01f));
    g.scale = static_cast<float>(g.slices) / std::log(farPlane / g.nearPlane);
    auto slice = [&](float dist) {
        const float k = std::floor(std::log(std::max(dist, g.nearPlane) / g.nearPlane) * g.scale);
        return static_cast<int>(std::clamp(k, 0.0f, static_cast<float>(g.slices - 1)));
    };

    // Each candidate's cluster range: the tiles its sphere's bounding box
    // covers on screen and the slices its depth extent covers, widened by one
    // pixel and one slice against rounding. The GPU assigns a light only
    // inside its range, so the ranges' sizes bound the index list.
    std::vector<glm::uvec4> ranges(std::max<std::size_t>(lists.rows.size(), 1), glm::uvec4(0));
    std::size_t capacity = 0;
    const glm::mat4& proj = ctx.camera.projection;
    for (std::size_t i = 0; i < lists.rows.size(); ++i) {
        const glm::vec4& pr = f.table.rows[lists.rows[i]].positionRadius;
        const glm::vec3 c(pr);
        const float r = pr.w * 1.001f;
        int x0 = 0, x1 = g.tilesX - 1, y0 = 0, y1 = g.tilesY - 1;
        if (-c.z - r > g.nearPlane) {  // wholly in front of the near plane: project its box
            glm::vec2 lo(1e30f), hi(-1e30f);
            for (int k = 0; k < 8; ++k) {
                const glm::vec3 p = c + glm::vec3(k & 1 ? r : -r, k & 2 ? r : -r, k & 4 ? r : -r);
                const glm::vec4 clip = proj * glm::vec4(p, 1.0f);
                const glm::vec2 w = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(ctx.width, ctx.height);
                lo = glm::min(lo, w);
                hi = glm::max(hi, w);
            }
            x0 = std::max(0, static_cast<int>(std::floor((lo.x - 1.0f) / g.tile)));
            y0 = std::max(0, static_cast<int>(std::floor((lo.y - 1.0f) / g.tile)));
            x1 = std::min(g.tilesX - 1, static_cast<int>(std::floor((hi.x + 1.0f) / g.tile)));
            y1 = std::min(g.tilesY - 1, static_cast<int>(std::floor((hi.y + 1.0f) / g.tile)));
        }
        const int s0 = std::max(0, slice(-c.z - r) - 1), s1 = std::min(g.slices - 1, slice(-c.z + r) + 1);
        if (x0 > x1 || y0 > y1 || -c.z + r < g.nearPlane) {  // off screen or behind the camera: no cluster
            ranges[i] = glm::uvec4(packRange(1, 0));
            continue;
        }
        ranges[i] = glm::uvec4(packRange(x0, x1), packRange(y0, y1), packRange(s0, s1), 0u);
        capacity += static_cast<std::size_t>(x1 - x0 + 1) * static_cast<std::size_t>(y1 - y0 + 1) *
                    static_cast<std::size_t>(s1 - s0 + 1);
    }

    gl::MemoryOwner owner("light lists");
    lists.upload(candidates_, f.table);
    ranges_.ensureSize(ranges.size() * sizeof(glm::uvec4), "cluster ranges");
    ranges_.update(0, ranges.size() * sizeof(glm::uvec4), ranges.data());
    cells_.ensureSize(static_cast<std::size_t>(g.clusters()) * sizeof(ClusterCell), "cluster grid");
    const ClusterCell empty{0xFFFFFFFFu, 0u, 0u, 0u};
    glClearNamedBufferData(cells_.id(), GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, &empty);
    filled_.ensureSize(static_cast<std::size_t>(g.clusters()) * sizeof(std::uint32_t), "cluster fill counts");
    const std::uint32_t none = 0;
    glClearNamedBufferData(filled_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
    index_.ensureSize((capacity + 1) * sizeof(std::uint32_t), "cluster light index");
    const std::uint32_t zero = 0;
    index_.update(0, sizeof(zero), &zero);
    bindBuffers();

    const gl::Program& bounds = program(bounds_, {.compute = "lighting/cluster_bounds.comp"});
    bounds.use();
    setGridUniforms(bounds, g);
    glDispatchCompute(static_cast<GLuint>((ctx.width + 15) / 16), static_cast<GLuint>((ctx.height + 15) / 16), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    const gl::Program& assign = program(assign_, {.compute = "lighting/cluster_assign.comp"});
    assign.use();
    setGridUniforms(assign, g);
    assign.set(7, static_cast<unsigned>(capacity));
    // cluster_assign.comp's stages, over slices of the candidates small
    // enough for the driver's loop limit (one slice where there is none).
    const int total = static_cast<int>(lists.rows.size());
    const int perSlice = loopLimit_ > 0 ? loopLimit_ * 9 / 10 : std::max(total, 1);
    auto stage = [&](int which, int first, int end) {
        assign.set(1, first);
        assign.set(2, end);
        assign.set(3, which);
        glDispatchCompute(static_cast<GLuint>((g.tilesX * g.tilesY + 63) / 64), static_cast<GLuint>(g.slices), 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    };
    constexpr int kCount = 0, kOffsets = 1, kFill = 2;  // STAGE_* in cluster_assign.comp
    for (int first = 0; first < total; first += perSlice) stage(kCount, first, std::min(total, first + perSlice));
    stage(kOffsets, 0, 0);
    for (int first = 0; first < total; first += perSlice) stage(kFill, first, std::min(total, first + perSlice));
    g.longestList = total;  // no cluster's list is longer than the candidates
    return g;
}

void ClusteredStrategy::writeCounts(LightingFrame& f, const Grid& g) {
    const gl::Program& counts = program(counts_, {.compute = "lighting/cluster_counts.comp"});
    bindBuffers();
    glBindImageTexture(binding::CLUSTER_COUNTS_IMAGE, f.ctx.texture(kClusterCounts).id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    counts.use();
    setGridUniforms(counts, g);
    glDispatchCompute(static_cast<GLuint>((f.ctx.width + 15) / 16), static_cast<GLuint>((f.ctx.height + 15) / 16), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_PIXEL_BUFFER_BARRIER_BIT);
}

StrategyCounts ClusteredStrategy::shade(LightingFrame& f) {
    const LightLists lists = LightLists::split(f);
    StrategyCounts c;
    c.culled = lists.culled;
    const bool counts = f.ctx.wants(kClusterCounts);
    if (lists.shaded > 0 || counts) {
        const Grid g = build(f, lists);
        if (lists.shaded > 0) {
            f.beginLight(*lists.firstShaded);  // the L-buffer target and blending; it has no map
            const gl::Program& p =
                f.counting ? program(shadeCounting_, {.vertex = "fullscreen.vert", .fragment = "lighting/clustered.frag",
                                                      .defines = {"COUNT_OVERLAP"}})
                           : program(shade_, {.vertex = "fullscreen.vert", .fragment = "lighting/clustered.frag"});
            bindBuffers();
            p.use();
            setGridUniforms(p, g);
            p.set(2, lists.shaded);
            // Each pass shades list entries first .. first + perPass of every
            // pixel's cluster (one pass unless a list could outrun the loop limit).
            const int perPass = loopLimit_ > 0 ? loopLimit_ * 9 / 10 : std::max(g.longestList, 1);
            for (int first = 0; first == 0 || first < g.longestList; first += perPass) {
                p.set(7, first);
                p.set(8, first + perPass);
                f.shading.drawFullscreenTriangle();
            }
            c.grid = lists.shaded;
        }
        if (counts) writeCounts(f, g);
    }
    c.volumes = lists.shadeOneByOne(f);
    return c;
}

void ClusteredStrategy::writeOutputs(LightingFrame& f) {
    if (!f.ctx.wants(kClusterCounts)) return;
    const Grid g = build(f, LightLists::split(f));
    writeCounts(f, g);
}

}  // namespace dw
