#include "renderer/passes/LightingPass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>

#include "renderer/Error.h"
#include "renderer/GpuScene.h"
#include "renderer/LightVolume.h"
#include "renderer/PassTimer.h"
#include "renderer/scene/Scene.h"

namespace dw {

namespace {

// std430 mirror of `Light` in shaders/common/lighting.glsl.
struct LightGpu {
    glm::mat4 volume{1.0f};
    glm::vec4 positionRadius{0.0f};
    glm::vec4 directionCutoff{0.0f};
    glm::vec4 intensityExponent{0.0f};
    glm::vec4 attenuation{0.0f};
    glm::mat4 shadowMatrix{1.0f};
    glm::vec4 shadowParams{0.0f};
    glm::vec4 shadowRange{0.0f};
};
static_assert(sizeof(LightGpu) == 224, "std430 layout");

struct LightingParamsGpu {
    glm::ivec4 modes{0};
    glm::vec4 values{0.0f};
};

// Frustum planes (Gribb & Hartmann) from a view-projection matrix, normalised.
std::array<glm::vec4, 6> frustumPlanes(const glm::mat4& m) {
    auto row = [&](int r) { return glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    std::array<glm::vec4, 6> p = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
                                  row(3) - row(1), row(3) + row(2), row(3) - row(2)};
    for (auto& plane : p) plane /= glm::length(glm::vec3(plane));
    return p;
}

bool sphereOutside(const std::array<glm::vec4, 6>& planes, const glm::vec3& c, float r) {
    for (const auto& p : planes)
        if (glm::dot(glm::vec3(p), c) + p.w < -r) return true;
    return false;
}

}  // namespace

LightingPass::LightingPass(KnobRegistry& knobs) : shadows_(knobs) {
    strategy_ = knobs.addEnum("lighting.strategy", {"stencil_volumes", "volumes", "fullscreen"}, StencilVolumes, "lighting",
                              "how point and spot lights find their pixels: stencil-tested light volumes (seed 001), "
                              "volumes without stencil, or every light over every pixel (brute force)");
    stencilCount_ = knobs.addEnum("lighting.stencil_count", {"depth_fail", "depth_pass"}, DepthFail, "lighting",
                                  "stencil counting of the volume test: depth_fail (correct with the camera inside a "
                                  "volume) or depth_pass (seed 001's table as written; loses lights around the camera)");
    threshold_ = knobs.addFloat("lighting.threshold", 1.0 / 255.0, 1e-5, 0.25, "lighting",
                                "intensity at which a light's volume ends: I_max * att(r) = threshold (seed 001 eq. 1); "
                                "larger means smaller volumes, less work, and light cut off sooner",
                                "", true, true);
    attenuation_ = knobs.addEnum("lighting.attenuation", {"classic", "windowed"}, 0, "lighting",
                                 "classic 1/(c + l d + q d^2), cut at the radius; or windowed, multiplied by "
                                 "1 - (d/r)^k so it reaches zero at the radius (Ferko, seed 000 eq. 3.5)");
    windowExponent_ = knobs.addFloat("lighting.window_exponent", 20.0, 2.0, 64.0, "lighting",
                                     "k in the windowed attenuation 1 - (d/r)^k (seed 000 uses 20)");
    ambientSpecular_ = knobs.addBool("lighting.ambient_specular", true, "lighting",
                                     "ambient reflectance = diffuse + specular colour, so metals (no diffuse) still "
                                     "reflect ambient light; off: the seed's k_a = diffuse colour");
    frustumCull_ = knobs.addBool("lighting.frustum_cull", true, "lighting",
                                 "skip light volumes entirely outside the view frustum (volume strategies)");
}

std::vector<OutputDecl> LightingPass::outputs() const {
    std::vector<OutputDecl> out = {
        {"lbuffer", OutputKind::HdrColor, "HDR radiance (RGBA16F): ambient, emission and every light, additively blended"},
        {"lighting.overlap", OutputKind::Count,
         "light-shader invocations per pixel: how many light volumes passed the stencil test (R32F)"}};
    for (int i = 0; i < kPublishedShadowMaps; ++i)
        out.push_back({"shadow.map" + std::to_string(i), OutputKind::Scalar,
                       "depth in the shadow map of shadow-casting light " + std::to_string(i) +
                           " (2D; a cube map as a 3x2 grid of faces; paraboloids side by side)"});
    return out;
}

namespace {
// Texture units 0-4 of the lighting shaders, in this order.
const char* const kGBufferInputs[] = {"gbuffer.albedo", "gbuffer.normal", "gbuffer.specular", "gbuffer.emissive",
                                      "gbuffer.depth"};
}  // namespace

PassIO LightingPass::inputs(const KnobRegistry&) const {
    return {{std::begin(kGBufferInputs), std::end(kGBufferInputs)}, {"ssao.blurred", "sky"}};
}

void LightingPass::setup(gl::ShaderLibrary& shaders) {
    ambientProgram_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/ambient.frag"});
    shade_.fullscreen = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/light.frag"});
    shade_.volume = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag"});
    shadeCounting_.fullscreen = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/light.frag", .defines = {"COUNT_OVERLAP"}});
    shadeCounting_.volume = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag", .defines = {"COUNT_OVERLAP"}});
    stencilProgram_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/stencil.frag"});
    sphere_.create(unitSphereVolume());
    cone_.create(unitConeVolume());
    params_ = gl::Buffer::create(sizeof(LightingParamsGpu), nullptr, true, "lighting params");
    shadows_.setup(shaders);
    white_ = gl::Texture::create2D(GL_R8, 1, 1);
    const std::uint8_t one = 255;
    white_.upload(0, 1, 1, GL_RED, GL_UNSIGNED_BYTE, &one);
}

void LightingPass::resize(int width, int height, OutputRegistry& outputs) {
    lbuffer_ = gl::Texture::create2D(GL_RGBA16F, width, height);
    lbuffer_.setFilter(GL_NEAREST, GL_NEAREST);
    overlap_ = gl::Texture::create2D(GL_R32F, width, height);
    overlap_.setFilter(GL_NEAREST, GL_NEAREST);
    depthStencil_ = gl::Texture::create2D(GL_DEPTH32F_STENCIL8, width, height);
    fbo_ = gl::Framebuffer::create("lbuffer");
    fbo_.attachColor(0, lbuffer_);
    fbo_.attachColor(1, overlap_);
    fbo_.attachDepth(depthStencil_);
    fbo_.setDrawBuffers({0, 1});
    fbo_.checkComplete("L-buffer");
    fbo_.setDrawBuffers({0});
    outputs.bind("lbuffer", &lbuffer_, 4);
    outputs.bind("lighting.overlap", &overlap_, 1);
}

void LightingPass::shade(FrameContext& ctx, int light, Method method, const LightVolumeGeometry* geometry,
                         bool depthFail, bool counting) {
    // Every light sets the state it needs: a shadow map may have been drawn just before.
    gl::resetPipelineState(ctx.width, ctx.height);
    fbo_.bind();
    if (counting) fbo_.setDrawBuffers({0, 1});
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    const gl::Program& fullscreen = counting ? *shadeCounting_.fullscreen : *shade_.fullscreen;
    const gl::Program& volume = counting ? *shadeCounting_.volume : *shade_.volume;
    if (method == Method::FullScreen) {
        fullscreen.use();
        fullscreen.set(0, light);
        triangle_.draw();
        return;
    }
    // Volumes may cross the near and far planes: clamp depth instead of clipping.
    glEnable(GL_DEPTH_CLAMP);
    if (method == Method::Volume) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
        volume.use();
        volume.set(0, light);
        geometry->draw();
        return;
    }
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    // 1. Mark pixels whose surface lies inside the volume.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
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
    stencilProgram_->use();
    stencilProgram_->set(0, light);
    geometry->draw();
    // 2. Shade the marked pixels through the back faces, zeroing the stencil
    //    on the way so the next light starts clean.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
    volume.use();
    volume.set(0, light);
    geometry->draw();
}

void LightingPass::publishShadowMap(FrameContext& ctx, int shadowIndex, ShadowMaps::Kind kind, int slot) {
    if (shadowIndex >= kPublishedShadowMaps) return;
    const std::string name = "shadow.map" + std::to_string(shadowIndex);
    if (!ctx.wants(name)) return;
    shadows_.drawView(kind, slot, shadowViews_[shadowIndex], shadowViewFbos_[shadowIndex]);
    ctx.outputs.bind(name, &shadowViews_[shadowIndex], 1);
}

void LightingPass::execute(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    const auto strategy = static_cast<Strategy>(k.get(strategy_));
    const double threshold = k.get(threshold_);
    const glm::mat4& view = ctx.camera.view;
    const auto planes = frustumPlanes(ctx.camera.viewProjection);
    const bool cull = k.get(frustumCull_) && strategy != FullScreen;
    const bool shadowsOn = shadows_.enabled(k);
    const bool reuse = shadows_.reuse(k);

    // The light table, and how each light is drawn, in the order they are shaded.
    struct Item {
        int index;
        Method method;
        const LightVolumeGeometry* geometry;
        const Light* light;
        double radius;
    };
    std::vector<LightGpu> table;
    std::vector<Item> items;
    counts_ = {};
    int perKind[3] = {0, 0, 0};
    for (const Light& l : ctx.scene.lights) {
        if (!l.enabled) continue;
        const LightVolume v = computeLightVolume(l, threshold);
        if (v.shape == VolumeShape::Culled) {
            ++counts_.belowThreshold;
            continue;
        }
        LightGpu g;
        g.volume = v.transform;
        const glm::vec3 dirView = glm::normalize(glm::vec3(view * glm::vec4(l.direction, 0.0f)));
        g.positionRadius = glm::vec4(glm::vec3(view * glm::vec4(l.position, 1.0f)),
                                     std::isfinite(v.radius) ? static_cast<float>(v.radius) : 0.0f);
        g.directionCutoff = glm::vec4(dirView, std::cos(glm::radians(l.cutoffDegrees)));
        g.intensityExponent = glm::vec4(l.intensity, l.exponent);
        const int type = l.type == LightType::Directional ? 0 : (l.type == LightType::Point ? 1 : 2);
        g.attenuation = glm::vec4(l.attenuation.constant, l.attenuation.linear, l.attenuation.quadratic, static_cast<float>(type));
        const int index = static_cast<int>(table.size());
        Item item{index, Method::FullScreen, nullptr, &l, v.radius};
        if (l.type == LightType::Directional) {
            ++counts_.directional;
        } else if (v.shape == VolumeShape::FullScreen || strategy == FullScreen) {
            ++counts_.fullscreen;
        } else {
            if (cull && sphereOutside(planes, l.position, static_cast<float>(v.radius))) {
                ++counts_.frustumCulled;
                continue;
            }
            item.method = strategy == Volumes ? Method::Volume : Method::StencilVolume;
            item.geometry = v.shape == VolumeShape::Cone ? &cone_ : &sphere_;
            ++counts_.volumes;
        }
        if (shadowsOn && l.castShadows) ++perKind[shadows_.kindOf(l, k)];
        table.push_back(g);
        items.push_back(item);
    }
    // Directional first, then full-screen, then spheres and cones (fewer state changes).
    std::stable_sort(items.begin(), items.end(), [this](const Item& a, const Item& b) {
        auto rank = [this](const Item& i) {
            if (i.light->type == LightType::Directional) return 0;
            if (i.method == Method::FullScreen) return 1;
            return i.geometry == &sphere_ ? 2 : 3;
        };
        return rank(a) < rank(b);
    });
    if (table.empty()) table.push_back(LightGpu{});
    lights_.ensureSize(table.size() * sizeof(LightGpu), "lights");

    // Shadow maps: reused light by light (flip-flop), or all rendered first.
    shadows_.beginFrame(ctx, perKind);
    int nextSlot[3] = {0, 0, 0};
    int shadowIndex = 0;
    auto renderShadow = [&](const Item& item) {
        const ShadowMaps::Kind kind = shadows_.kindOf(*item.light, k);
        const int slot = reuse ? 0 : nextSlot[kind]++;
        if (ctx.timer) ctx.timer->beginSubSpan("shadow maps");
        const ShadowLookup s = shadows_.render(ctx, *item.light, item.radius, slot);
        publishShadowMap(ctx, shadowIndex++, kind, slot);
        if (ctx.timer) ctx.timer->endSubSpan();
        LightGpu& g = table[item.index];
        g.shadowMatrix = s.matrix;
        g.shadowParams = s.params;
        g.shadowRange = s.range;
    };
    if (shadowsOn && !reuse)
        for (const Item& item : items)
            if (item.light->castShadows) renderShadow(item);
    lights_.update(0, table.size() * sizeof(LightGpu), table.data());
    lights_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::kLightSsbo);

    const bool occlusion = ctx.produced("ssao.blurred");
    const bool sky = ctx.produced("sky");
    LightingParamsGpu params;
    params.modes = glm::ivec4(k.get(attenuation_), occlusion ? 1 : 0, k.get(ambientSpecular_) ? 1 : 0, sky ? 1 : 0);
    params.values = glm::vec4(k.get(windowExponent_), 0, 0, 0);
    params_.update(0, sizeof(params), &params);
    params_.bindBase(GL_UNIFORM_BUFFER, binding::kPassUbo);

    // The L-buffer gets its own copy of the G-buffer depth: the stencil routing
    // writes stencil there while the shader samples gbuffer.depth.
    const gl::Texture* gdepth = ctx.outputs.find("gbuffer.depth")->texture;
    glCopyImageSubData(gdepth->id(), GL_TEXTURE_2D, 0, 0, 0, 0, depthStencil_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       ctx.width, ctx.height, 1);

    // Looked up once: with reused shadow maps the inputs are re-bound after every map.
    const gl::Texture* inputTextures[std::size(kGBufferInputs)];
    for (std::size_t i = 0; i < std::size(kGBufferInputs); ++i) inputTextures[i] = ctx.outputs.find(kGBufferInputs[i])->texture;
    const gl::Texture* occlusionTexture = occlusion ? ctx.outputs.find("ssao.blurred")->texture : &white_;
    const gl::Texture* skyTexture = sky ? ctx.outputs.find("sky")->texture : nullptr;
    auto bindInputs = [&] {
        for (std::size_t unit = 0; unit < std::size(kGBufferInputs); ++unit) inputTextures[unit]->bind(static_cast<GLuint>(unit));
        occlusionTexture->bind(5);
        if (skyTexture) skyTexture->bind(9);
        shadows_.bind();
        lights_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::kLightSsbo);
        params_.bindBase(GL_UNIFORM_BUFFER, binding::kPassUbo);
    };
    bindInputs();

    gl::resetPipelineState(ctx.width, ctx.height);
    fbo_.bind();
    // Ambient + emission + background: the first write, no blending.
    fbo_.setDrawBuffers({0});
    ambientProgram_->use();
    ambientProgram_->set(0, ctx.scene.ambient);
    ambientProgram_->set(1, ctx.scene.background);
    triangle_.draw();

    const bool counting = ctx.wants("lighting.overlap");
    if (counting) {
        fbo_.setDrawBuffers({0, 1});
        fbo_.clearColor(1, 0, 0, 0, 0);
    }
    const bool depthFail = k.get(stencilCount_) == DepthFail;
    for (const Item& item : items) {
        if (shadowsOn && reuse && item.light->castShadows) {
            renderShadow(item);
            const LightGpu& g = table[item.index];
            lights_.update(item.index * sizeof(LightGpu), sizeof(LightGpu), &g);
            bindInputs();
        }
        shade(ctx, item.index, item.method, item.geometry, depthFail, counting);
    }
    fbo_.setDrawBuffers({0});
    counts_.shadowed = shadows_.mapsRendered();
    for (int i = counts_.shadowed; i < kPublishedShadowMaps; ++i)
        if (ctx.wants("shadow.map" + std::to_string(i)))
            throw Error("shadow.map" + std::to_string(i) + " is not produced: " + std::to_string(counts_.shadowed) +
                        " shadow map(s) this frame (lights need \"shadow\": true, and shadows.enabled)");
    const int total = counts_.directional + counts_.fullscreen + counts_.volumes + counts_.frustumCulled + counts_.belowThreshold;
    stats_ = std::to_string(total) + " lights: " + std::to_string(counts_.directional) + " directional, " +
             std::to_string(counts_.volumes) + " volumes, " + std::to_string(counts_.fullscreen) + " full-screen, " +
             std::to_string(counts_.frustumCulled) + " outside the frustum, " + std::to_string(counts_.belowThreshold) +
             " below threshold";
    if (counts_.shadowed > 0) {
        auto mib = [](std::size_t b) {
            char buf[32];
            std::snprintf(buf, sizeof(buf), "%.1f MiB", static_cast<double>(b) / (1024.0 * 1024.0));
            return std::string(buf);
        };
        stats_ += "; " + std::to_string(counts_.shadowed) + " shadow maps, " + (reuse ? "one reused" : "kept") + ": " +
                  mib(shadows_.bytesInUse()) + " (one per light: " + mib(shadows_.bytesKeepingAll()) + ")";
    }
}

}  // namespace dw
