#include "renderer/lighting/ForwardStrategy.h"
#include "renderer/gl/MemoryLedger.h"

#include <algorithm>
#include <array>

#include "renderer/gl/ShaderLoopLimit.h"
#include "renderer/gl/Texture.h"
#include "renderer/lighting/LightLists.h"
#include "renderer/scene/GpuScene.h"

namespace dw {

namespace {

// The lighting inputs the scene's material textures displace (the run from
// GBUFFER_ALBEDO_TEXTURE, lighting/gbuffer_read.glsl; the material maps'
// units), bound again for whatever runs after.
void rebindGBuffer(FrameContext& ctx) {
    const char* const names[] = {"gbuffer.albedo", "gbuffer.normal", "gbuffer.specular", "gbuffer.emissive"};
    for (GLuint i = 0; i < 4; ++i) ctx.texture(names[i]).bind(binding::GBUFFER_ALBEDO_TEXTURE + i);
}

// After frame.beginLight: test against the laid-down depth, write none.
void forwardDepthState() {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_EQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_STENCIL_TEST);
}

// The draws whose world box meets the view frustum (seed 000 listing 2.6's
// "visible object"): Gribb-Hartmann planes, a box is out when its corner
// farthest along a plane's normal lies behind it. Culls only what has no
// pixel in the laid-down depth, so it changes no image.
std::vector<char> visibleDraws(const GpuScene& gpu, const glm::dmat4& worldToClip) {
    const glm::dmat4& m = worldToClip;
    auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    // Clip depth in [0, 1] (DepthConvention): the depth planes are z >= 0 and
    // z <= w. Double precision: world positions may be far from the origin.
    std::array<glm::dvec4, 6> planes = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
                                        row(3) - row(1), row(2), row(3) - row(2)};
    for (glm::dvec4& p : planes) p /= glm::length(glm::dvec3(p));
    std::vector<char> visible;
    for (const GpuScene::Draw& d : gpu.draws()) {
        bool in = !d.bounds.empty();
        for (const glm::dvec4& p : planes) {
            if (!in) break;
            const glm::dvec3 far(p.x >= 0 ? d.bounds.max.x : d.bounds.min.x, p.y >= 0 ? d.bounds.max.y : d.bounds.min.y,
                                p.z >= 0 ? d.bounds.max.z : d.bounds.min.z);
            in = glm::dot(glm::dvec3(p), far) + p.w >= -1e-3;  // a little slack: keep, never lose
        }
        visible.push_back(in ? 1 : 0);
    }
    return visible;
}

bool meets(const LightTableEntry& e, const Bounds& box) {
    return sphereMeetsBox(e.light->position, static_cast<float>(e.volume.radius), box);
}

}  // namespace

bool sphereMeetsBox(const glm::vec3& centre, float radius, const Bounds& box) {
    if (box.empty()) return false;
    const glm::vec3 d = centre - glm::clamp(centre, box.min, box.max);
    return glm::dot(d, d) <= radius * radius * 1.0001f;
}

ForwardLightLists ForwardLightLists::build(const GpuScene& gpu, const std::vector<const LightTableEntry*>& lights,
                                           const glm::dmat4* worldToClip) {
    ForwardLightLists l;
    const auto& draws = gpu.draws();
    const std::vector<char> visible = worldToClip ? visibleDraws(gpu, *worldToClip) : std::vector<char>(draws.size(), 1);
    l.first.resize(draws.size());
    l.count.resize(draws.size());
    for (std::size_t i = 0; i < draws.size(); ++i) {
        l.first[i] = static_cast<std::uint32_t>(l.rows.size());
        if (visible[i])
            for (const LightTableEntry* e : lights)
            if (meets(*e, draws[i].bounds)) l.rows.push_back(static_cast<std::uint32_t>(e->row));
        l.count[i] = static_cast<std::uint32_t>(l.rows.size()) - l.first[i];
    }
    return l;
}

void ForwardStrategy::setup(gl::ShaderLibrary& shaders) {
    loopLimit_ = gl::shaderLoopIterationLimit();
    program_ = shaders.get({.vertex = "geometry.vert", .fragment = "lighting/forward.frag"});
    countingProgram_ = shaders.get({.vertex = "geometry.vert", .fragment = "lighting/forward.frag", .defines = {"COUNT_OVERLAP"}});
    gl::MemoryOwner owner("light lists");
    indices_ = gl::Buffer::create(sizeof(std::uint32_t), nullptr, true, "forward light indices");
}

StrategyCounts ForwardStrategy::shade(LightingFrame& f) {
    StrategyCounts c;
    // In the frustum, without a shadow map: the per-draw lists; the rest one at a time.
    std::vector<const LightTableEntry*> listed;
    LightLists oneByOne;
    for (const LightTableEntry* e : f.lights) {
        if (!e->inFrustum) ++c.culled;
        else if (f.ctx.shadows && e->shadowed) oneByOne.oneByOne.push_back(e);
        else listed.push_back(e);
    }
    // First, while the G-buffer is still bound to the volume shader's units.
    c.volumes = oneByOne.shadeOneByOne(f);
    c.grid = static_cast<int>(listed.size());
    c.gridWhere = "in per-object light lists";
    lastPairs_ = 0;
    if (listed.empty()) return c;

    const glm::dmat4 worldToClip = f.ctx.camera.worldToClip();
    const ForwardLightLists lists = ForwardLightLists::build(f.ctx.gpu, listed, &worldToClip);
    lastPairs_ = lists.rows.size();
    if (lists.rows.empty()) return c;
    gl::MemoryOwner owner("light lists");
    indices_.ensureSize(lists.rows.size() * sizeof(std::uint32_t), "forward light indices");
    indices_.update(0, lists.rows.size() * sizeof(std::uint32_t), lists.rows.data());
    indices_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::LIGHT_CANDIDATES_SSBO);

    f.beginLight(*listed.front());  // the L-buffer target (no map: not shadowed)
    forwardDepthState();
    const gl::Program& program = f.counting ? *countingProgram_ : *program_;
    program.use();
    // A list longer than the driver's loop limit lets one fragment run
    // (gl::shaderLoopIterationLimit) is drawn in parts, blended together.
    const std::uint64_t longest = *std::max_element(lists.count.begin(), lists.count.end());
    const std::uint64_t perDraw = loopLimit_ > 0 ? static_cast<std::uint64_t>(loopLimit_) * 9 / 10 : std::max<std::uint64_t>(longest, 1);
    const std::uint64_t parts = std::max<std::uint64_t>(1, (longest + perDraw - 1) / perDraw);
    for (std::uint64_t part = 0; part < parts; ++part) {
        f.ctx.gpu.drawEach(program, GpuScene::Filter::Opaque, [&](std::size_t i, const GpuScene::Draw&) {
            const std::uint64_t skip = part * perDraw;
            if (lists.count[i] <= skip) return false;
            program.set(2, static_cast<int>(lists.first[i] + skip));
            program.set(3, static_cast<int>(std::min<std::uint64_t>(perDraw, lists.count[i] - skip)));
            return true;
        });
    }
    rebindGBuffer(f.ctx);
    return c;
}

void ForwardMultipassStrategy::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "geometry.vert", .fragment = "lighting/forward.frag", .defines = {"FORWARD_ONE_LIGHT"}});
    countingProgram_ = shaders.get(
        {.vertex = "geometry.vert", .fragment = "lighting/forward.frag", .defines = {"FORWARD_ONE_LIGHT", "COUNT_OVERLAP"}});
}

StrategyCounts ForwardMultipassStrategy::shade(LightingFrame& f) {
    StrategyCounts c;
    lastPairs_ = 0;
    const gl::Program& program = f.counting ? *countingProgram_ : *program_;
    const auto& draws = f.ctx.gpu.draws();
    const std::vector<char> visible = visibleDraws(f.ctx.gpu, f.ctx.camera.worldToClip());
    std::vector<std::size_t> touched;
    for (const LightTableEntry* e : f.lights) {
        if (!e->inFrustum) {
            ++c.culled;
            continue;
        }
        touched.clear();
        for (std::size_t i = 0; i < draws.size(); ++i)
            if (visible[i] && meets(*e, draws[i].bounds)) touched.push_back(i);
        ++c.volumes;
        if (touched.empty()) continue;  // its map is not needed either
        lastPairs_ += touched.size();
        f.beginLight(*e);  // renders a reused shadow map first
        forwardDepthState();
        program.use();
        program.set(2, e->row);
        std::size_t next = 0;  // draws come in index order
        f.ctx.gpu.drawEach(program, GpuScene::Filter::Opaque, [&](std::size_t i, const GpuScene::Draw&) {
            while (next < touched.size() && touched[next] < i) ++next;
            return next < touched.size() && touched[next] == i;
        });
    }
    rebindGBuffer(f.ctx);
    return c;
}

}  // namespace dw
