#include "renderer/passes/LightingPass.h"

#include <algorithm>
#include <cstdio>
#include <iterator>

#include "renderer/Error.h"
#include "renderer/scene/GpuScene.h"
#include "renderer/lighting/AutoStrategy.h"
#include "renderer/passes/AaMethod.h"
#include "renderer/lighting/LightTable.h"
#include "renderer/lighting/ScreenBatches.h"
#include "renderer/lighting/ShadowService.h"
#include "renderer/scene/Scene.h"

namespace dw {

namespace {

// Texture units 0-4 of the lighting shaders, in this order.
const char* const kGBufferInputs[] = {"gbuffer.albedo", "gbuffer.normal", "gbuffer.specular", "gbuffer.emissive",
                                      "gbuffer.depth"};
// Bound as a run from GBUFFER_ALBEDO_TEXTURE (shaders/lighting/gbuffer_read.glsl).
static_assert(binding::GBUFFER_NORMAL_TEXTURE == binding::GBUFFER_ALBEDO_TEXTURE + 1 &&
              binding::GBUFFER_SPECULAR_TEXTURE == binding::GBUFFER_ALBEDO_TEXTURE + 2 &&
              binding::GBUFFER_EMISSIVE_TEXTURE == binding::GBUFFER_ALBEDO_TEXTURE + 3 &&
              binding::GBUFFER_DEPTH_TEXTURE == binding::GBUFFER_ALBEDO_TEXTURE + 4);

}  // namespace

LightingPass::LightingPass(KnobRegistry& knobs) {
    strategies_.emplace(knobs, builtinLightingStrategies(),
                        MethodKnob{"lighting.strategy", "lighting", "how point and spot lights find their pixels:",
                                   {{"auto", "per frame, stencil_volumes while the bounded lights in view cover the "
                                             "screen fewer than lighting.auto_coverage times over, clustered from "
                                             "lighting.auto_cluster_coverage times, tiled between (the statistics say "
                                             "which and why)"}},
                                   false});
    autoCoverage_ = knobs.addFloat("lighting.auto_coverage", kAutoCoverage, 0.0, 1e6, "lighting",
                                   "auto: the screen coverage (the bounded lights' screen rectangles summed, in "
                                   "screens) from which a grid strategy (tiled or clustered) is picked instead of "
                                   "stencil_volumes (docs/bench.md)");
    autoClusterCoverage_ = knobs.addFloat("lighting.auto_cluster_coverage", kAutoClusterCoverage, 0.0, 1e6, "lighting",
                                          "auto: the screen coverage from which clustered is picked instead of tiled; "
                                          "the default 1e6 means never: on llvmpipe tiled was faster at every "
                                          "coverage measured, up to 657 (docs/bench.md)");
    attenuation_ = knobs.addEnum("lighting.attenuation", {"classic", "windowed"}, "classic", "lighting",
                                 "classic 1/(c + l d + q d^2), cut at the radius; or windowed, multiplied by "
                                 "1 - (d/r)^k so it reaches zero at the radius (Ferko, seed 000 eq. 3.5)");
    windowed_ = knobs.choiceIndex(attenuation_, "windowed");
    windowExponent_ = knobs.addFloat("lighting.window_exponent", 20.0, 2.0, 64.0, "lighting",
                                     "k in the windowed attenuation 1 - (d/r)^k (seed 000 uses 20)");
    ambientSpecular_ = knobs.addBool("lighting.ambient_specular", true, "lighting",
                                     "ambient reflectance = diffuse + specular colour, so metals (no diffuse) still "
                                     "reflect ambient light; off: the seed's k_a = diffuse colour");
    ambientOcclusion_ = knobs.addEnum("lighting.ambient_occlusion", {"both", "baked", "screen"}, "both", "lighting",
                                      "which ambient occlusion scales the ambient term: the materials' baked occlusion "
                                      "textures (gbuffer.occlusion), the screen-space one (ao.filtered, when ao.enabled; the "
                                      "value was called ssao before), or their product");
    volumeSubdivisions_ = knobs.addInt(
        "lighting.volume_subdivisions", kDefaultSphereSubdivisions, 0, kMaxSphereSubdivisions, "lighting",
        "sphere light volumes: the icosahedron subdivided k times (20, 80, 320 or 1280 faces), circumscribing the "
        "light's sphere. Fewer faces: less vertex work per light; more: fewer pixels marked outside the radius "
        "(which the shader rejects). The image is the same for every k");
    aoBaked_ = knobs.choiceIndex(ambientOcclusion_, "baked");
    aoScreen_ = knobs.choiceIndex(ambientOcclusion_, "screen");
    knobs.addValueAlias("lighting.ambient_occlusion", "ssao", "screen", "the screen-space AO is any ao.method now");
}

LightingPass::~LightingPass() = default;

std::vector<OutputDecl> LightingPass::outputs() const {
    std::vector<OutputDecl> out = {
        {"lbuffer", OutputKind::HdrColor,
         "HDR radiance (RGBA32F, so lights up to 1e20 and their sums stay finite): ambient, emission and every light, "
         "additively blended",
         texture2D(GL_RGBA32F)},
        {"lbuffer.depth", OutputKind::Depth,
         "the G-buffer depth copied for the L-buffer, with the stencil the light volumes used (DEPTH32F_STENCIL8, "
         "DEPTH24_STENCIL8 with gbuffer.depth_format=unorm24)",
         texture2D(GL_DEPTH32F_STENCIL8), 1},
        {"lighting.overlap", OutputKind::Count,
         "light-shader invocations per pixel: how many light volumes passed the stencil test, or how many lights "
         "of its tile or cluster list a pixel evaluated (R32F)", texture2D(GL_R32F), 1,
         true},
        {"lighting.shadow", OutputKind::Scalar,
         "the shadow factor: luminance of the shadow-mapped lights' radiance with their shadow lookups over that "
         "without them, 1 where none reaches and on the sky (the reference's shadow buffer, R32F)",
         texture2D(GL_R32F), 1, true}};
    strategies_->appendOutputs(out);
    return out;
}

void LightingPass::connect(const KnobRegistry& knobs) {
    directionalInGBuffer_ = knobs.requireBool("lighting.directional_in_gbuffer");
    depthFormat_ = knobs.requireEnum("gbuffer.depth_format");
    aoMethod_ = knobs.requireEnum("ao.method");
    aoGtao_ = knobs.choiceIndex(aoMethod_, "gtao");
    gtaoMultibounce_ = knobs.requireBool("gtao.multibounce");
    aaMethod_ = knobs.requireEnum(kAaMethodKnob);
    aaMsaa_ = knobs.choiceIndex(aaMethod_, "msaa");
}

ResourceDesc LightingPass::resource(const OutputDecl& output, const KnobRegistry& knobs) const {
    ResourceDesc d = output.resource;
    // A copy of gbuffer.depth (glCopyImageSubData needs the same format).
    if (output.name == "lbuffer.depth" && knobs.get(depthFormat_) == knobs.choiceIndex(depthFormat_, "unorm24"))
        d.format = GL_DEPTH24_STENCIL8;
    return d;
}

PassIO LightingPass::inputs(const KnobRegistry& knobs) const {
    PassIO io{{std::begin(kGBufferInputs), std::end(kGBufferInputs)}, {"ao.filtered", "sky"}};
    if (knobs.get(directionalInGBuffer_)) io.inputs.push_back("gbuffer.directional");
    io.inputs.push_back("lights.table");
    io.inputs.push_back("gbuffer.occlusion");
    if (knobs.get(aaMethod_) == aaMsaa_) {  // MSAA's samples and edge mask
        io.optionalInputs.push_back("aa.edges");
        io.optionalInputs.insert(io.optionalInputs.end(), std::begin(kMsaaGBuffer), std::end(kMsaaGBuffer));
        io.optionalInputs.push_back(kMsaaDepth);
        if (knobs.get(directionalInGBuffer_)) io.optionalInputs.push_back(kMsaaDirectional);
    }
    return io;
}

void LightingPass::setup(gl::ShaderLibrary& shaders) {
    ambientProgram_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/ambient.frag"});
    shading_.setup(shaders);
    strategies_->setup(shaders);
    params_.create();
    shadowSumsProgram_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/shadow_sums.frag"});
    shadowResolveProgram_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/shadow_resolve.frag"});
    white_ = gl::Texture::create2D(GL_R8, 1, 1);
    const std::uint8_t one = 255;
    white_.upload(0, 1, 1, GL_RED, GL_UNSIGNED_BYTE, &one);
    msaaCopy_.setup(shaders);
    msaaResolve_.setup(shaders);
}

void LightingPass::writeShadowFactor(FrameContext& ctx, const LightTable& table, const std::function<void()>& bindInputs) {
    if (!shadowSums_ || shadowSumsWidth_ != ctx.width || shadowSumsHeight_ != ctx.height) {
        shadowSums_ = gl::Texture::create2D(GL_RG32F, ctx.width, ctx.height);
        shadowSumsTarget_ = gl::Framebuffer::forColor(shadowSums_, "lighting.shadow sums");
        shadowSumsWidth_ = ctx.width;
        shadowSumsHeight_ = ctx.height;
    }
    gl::resetPipelineState(ctx.width, ctx.height);
    shadowSumsTarget_.bind();
    shadowSumsTarget_.clearColor(0, 0, 0, 0, 0);
    if (ctx.shadows) {
        for (const LightTableEntry& e : table.entries) {
            if (!e.shadowed) continue;
            if (ctx.shadows->prepare(ctx, e)) bindInputs();
            gl::resetPipelineState(ctx.width, ctx.height);
            ctx.shadows->bind();
            shadowSumsTarget_.bind();
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFunc(GL_ONE, GL_ONE);
            shadowSumsProgram_->use();
            shadowSumsProgram_->set(0, e.row);
            triangle_.draw();
        }
    }
    gl::resetPipelineState(ctx.width, ctx.height);
    shadowTarget_.get(ctx, {"lighting.shadow"}, {}, "lighting.shadow").bind();
    shadowSums_.bind(binding::SHADOW_SUMS_TEXTURE);
    shadowResolveProgram_->use();
    triangle_.draw();
    bindInputs();  // GBUFFER_ALBEDO_TEXTURE again (SHADOW_SUMS_TEXTURE's unit)
}

LightingStrategy& LightingPass::pickStrategy(const FrameContext& ctx, const std::vector<const LightTableEntry*>& lights) {
    autoWhy_.clear();
    if (LightingStrategy* chosen = strategies_->picked(ctx.knobs)) return *chosen;  // not auto
    AutoStrategyInputs in;
    const glm::dmat4 worldToClip = ctx.camera.worldToClip();
    for (const LightTableEntry* e : lights) {
        if (!e->inFrustum) continue;
        ++in.lights;
        const auto [lo, hi] = shading_.localBox(e->volume.shape);
        const PixelRect r = screenRect(worldToClip * glm::dmat4(e->volume.transform), lo, hi, ctx.width, ctx.height);
        if (!r.empty()) in.coverage += double(r.x1 - r.x0) * (r.y1 - r.y0) / (double(ctx.width) * ctx.height);
    }
    const AutoStrategyChoice c = chooseLightingStrategy(
        in, {ctx.knobs.get(autoCoverage_), ctx.knobs.get(autoClusterCoverage_)});
    autoWhy_ = "auto picked " + std::string(c.strategy) + ": " + c.why;
    if (LightingStrategy* picked = strategies_->named(c.strategy)) return *picked;
    throw Error(std::string("lighting.strategy=auto picked '") + c.strategy + "', which is not registered");
}

void LightingPass::execute(FrameContext& ctx) {
    const LightingStrategy& strategy = shadeGBuffer(ctx);
    msaaLine_.clear();
    msaaWarning_.clear();
    if (ctx.produced("aa.edges")) shadeEdgeSamples(ctx, strategy);
    describe(ctx, strategy);
}

void LightingPass::shadeEdgeSamples(FrameContext& ctx, const LightingStrategy& strategy) {
    const int n = ctx.output(kMsaaDepth).desc.samples;
    const long long pixels = static_cast<long long>(ctx.width) * ctx.height;
    const long long edges = MsaaPass::countEdges(ctx.texture("aa.edges"), ctx.width, ctx.height);
    const std::string edgeCount = std::to_string(edges) + " edge pixels of " + std::to_string(pixels);
    if (!strategy.shadesFromGBuffer()) {
        msaaLine_ = "MSAA: " + edgeCount + " shaded per pixel only (" + strategy.name() +
                    " draws the scene itself at the pixel centres, not from the G-buffer); shaded samples " +
                    std::to_string(pixels) + ", 1 a pixel";
        msaaWarning_ = std::string("msaa: lighting.strategy=") + strategy.name() +
                       " shades per pixel only (it draws the scene itself at the pixel centres, not from the "
                       "G-buffer): the image is aa.method=none's and the multisampled G-buffer is drawn for nothing; "
                       "a deferred strategy shades the edge samples";
        return;
    }
    const bool directional = ctx.produced(kMsaaDirectional) && ctx.produced("gbuffer.directional");
    // The samples write none of the optional outputs (overlap, shadow
    // factor, the strategies' lists): those stay the pixel centres', as the counts do.
    FrameContext edgeFrame = ctx;
    for (const OutputDecl& o : outputs())
        if (o.name != "lbuffer" && o.name != "lbuffer.depth") edgeFrame.wanted.erase(o.name);
    const Counts centres = counts_;
    msaaResolve_.begin(ctx, n);
    msaaCopy_.save(ctx, directional);
    for (int s = 0; s < n; ++s) {
        msaaCopy_.copy(ctx, s, directional);
        shadeGBuffer(edgeFrame);
        msaaResolve_.add(ctx, n);
    }
    msaaCopy_.restore(ctx, directional);
    msaaResolve_.finish(ctx);
    const gl::Texture& gdepth = ctx.texture("gbuffer.depth");
    const gl::Texture& ldepth = ctx.texture("lbuffer.depth");
    glCopyImageSubData(gdepth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ldepth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ctx.width, ctx.height, 1);
    counts_ = centres;
    const long long shaded = pixels + edges * n;
    char perPixel[32];
    std::snprintf(perPixel, sizeof perPixel, "%.3f", pixels > 0 ? double(shaded) / double(pixels) : 0.0);
    msaaLine_ = "MSAA " + std::to_string(n) + "x: " + edgeCount + " shaded again per sample; shaded samples " +
                std::to_string(pixels) + " + " + std::to_string(edges) + " x " + std::to_string(n) + " = " +
                std::to_string(shaded) + ", " + perPixel + " a pixel";
}

std::vector<int> LightingPass::uploadParams(const FrameContext& ctx, const LightTable& table) {
    const KnobRegistry& k = ctx.knobs;
    const bool occlusion = ctx.produced("ao.filtered");
    const bool sky = ctx.produced("sky");
    gpu::LightingParams params{};
    params.windowed = k.get(attenuation_) == windowed_ ? 1 : 0;
    const int aoMode = k.get(ambientOcclusion_);
    params.occlusion = occlusion && aoMode != aoBaked_ ? 1 : 0;
    params.bakedOcclusion = aoMode != aoScreen_ ? 1 : 0;
    // GTAO's multi-bounce fit, on whatever accessibility the ambient term uses.
    params.multiBounce = params.occlusion && k.get(aoMethod_) == aoGtao_ && k.get(gtaoMultibounce_) ? 1 : 0;
    params.ambientSpecular = k.get(ambientSpecular_) ? 1 : 0;
    params.sky = sky ? 1 : 0;
    params.windowExponent = k.get(windowExponent_);
    // The directional lights the G-buffer pass shaded (lighting.directional_in_gbuffer).
    std::vector<int> shadedInGBuffer;
    if (k.get(directionalInGBuffer_) && ctx.produced("gbuffer.directional"))
        shadedInGBuffer = gbufferDirectionalRows(table, ctx.shadows != nullptr);
    params.gbufferDirectional = shadedInGBuffer.empty() ? 0 : 1;
    params.ambient = glm::vec4(ctx.scene.ambient, 0.0f);
    params.background = glm::vec4(ctx.scene.background, 0.0f);
    params_.upload(params, binding::PASS_UBO);
    return shadedInGBuffer;
}

// The table's lights by how they are shaded: bounded ones into `bounded`
// (the strategy's), directional ones the G-buffer pass shaded counted, and
// the rest (directional, unbounded) returned, drawn as full-screen passes.
std::vector<const LightTableEntry*> LightingPass::sortLights(const LightTable& table,
                                                              const std::vector<int>& shadedInGBuffer,
                                                              std::vector<const LightTableEntry*>& bounded) {
    std::vector<const LightTableEntry*> screenLights;
    for (const LightTableEntry& e : table.entries) {
        if (e.light->type != LightType::Directional && e.volume.shape != VolumeShape::FullScreen)
            bounded.push_back(&e);
        else if (std::find(shadedInGBuffer.begin(), shadedInGBuffer.end(), e.row) != shadedInGBuffer.end())
            ++counts_.directionalInGBuffer;
        else
            screenLights.push_back(&e);
    }
    return screenLights;
}

// What the strategy drew, into the frame's counts (full-screen lights add to
// the screen lights already counted).
void LightingPass::addStrategyCounts(const StrategyCounts& sc) {
    counts_.volumes = sc.volumes;
    counts_.batches = sc.batches;
    counts_.grid = sc.grid;
    counts_.gridWhere = sc.gridWhere;
    counts_.fullscreen += sc.fullscreen;
    counts_.frustumCulled = sc.culled;
}

LightingStrategy& LightingPass::shadeGBuffer(FrameContext& ctx) {
    if (!ctx.lightTable) throw Error("the lighting pass ran without a light table (the lights pass did not run)");
    const LightTable& table = *ctx.lightTable;

    const bool occlusion = ctx.produced("ao.filtered");
    const bool sky = ctx.produced("sky");
    const std::vector<int> shadedInGBuffer = uploadParams(ctx, table);

    // The L-buffer gets its own copy of the G-buffer depth: the stencil test
    // writes stencil there while the shader samples gbuffer.depth.
    const gl::Texture& gdepth = ctx.texture("gbuffer.depth");
    const gl::Texture& ldepth = ctx.texture("lbuffer.depth");
    glCopyImageSubData(gdepth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ldepth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ctx.width, ctx.height, 1);

    const bool counting = ctx.wants("lighting.overlap");
    gl::Framebuffer& fbo = counting ? countingTarget_.get(ctx, {"lbuffer", "lighting.overlap"}, "lbuffer.depth", "L-buffer")
                                          : target_.get(ctx, {"lbuffer"}, "lbuffer.depth", "L-buffer");

    // Looked up once: with reused shadow maps the inputs are re-bound after every map.
    const gl::Texture* inputTextures[std::size(kGBufferInputs)];
    for (std::size_t i = 0; i < std::size(kGBufferInputs); ++i) inputTextures[i] = &ctx.texture(kGBufferInputs[i]);
    const gl::Texture* occlusionTexture = occlusion ? &ctx.texture("ao.filtered") : &white_;
    const gl::Texture* skyTexture = sky ? &ctx.texture("sky") : nullptr;
    const gl::Texture& bakedOcclusion = ctx.texture("gbuffer.occlusion");
    const gl::Texture* gbufferDirectional = shadedInGBuffer.empty() ? nullptr : &ctx.texture("gbuffer.directional");
    auto bindInputs = [&] {
        for (std::size_t unit = 0; unit < std::size(kGBufferInputs); ++unit) inputTextures[unit]->bind(binding::GBUFFER_ALBEDO_TEXTURE + static_cast<GLuint>(unit));
        occlusionTexture->bind(binding::LIGHTING_OCCLUSION_TEXTURE);
        if (skyTexture) skyTexture->bind(binding::AMBIENT_SKY_TEXTURE);
        bakedOcclusion.bind(binding::AMBIENT_BAKED_OCCLUSION_TEXTURE);
        if (gbufferDirectional) gbufferDirectional->bind(binding::AMBIENT_GBUFFER_DIRECTIONAL_TEXTURE);
        table.buffer->bindBase(GL_SHADER_STORAGE_BUFFER, binding::LIGHT_SSBO);
        params_.bind(binding::PASS_UBO);
    };
    bindInputs();

    // The bounded lights go to the strategy; directional and unbounded
    // lights cover the screen whatever the strategy.
    counts_ = {};
    shading_.setSphereSubdivisions(ctx.knobs.get(volumeSubdivisions_));
    counts_.belowThreshold = table.belowThreshold;
    // Every light: its shadow map first when maps are reused, then the
    // L-buffer target with additive blending.
    auto beginLight = [&](const LightTableEntry& e) {
        if (ctx.shadows && ctx.shadows->prepare(ctx, e)) bindInputs();
        gl::resetPipelineState(ctx.width, ctx.height);
        if (ctx.shadows) ctx.shadows->bind();  // the comparison samplers, which the reset unbinds
        fbo.bind();
        if (counting) fbo.setDrawBuffers({0, 1});
        else fbo.setDrawBuffers({0});
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
    };
    LightingFrame frame{ctx, table, {}, counting, shading_, beginLight};
    const std::vector<const LightTableEntry*> screenLights = sortLights(table, shadedInGBuffer, frame.lights);
    LightingStrategy& strategy = pickStrategy(ctx, frame.lights);
    const bool strategyWritesFirst = strategy.writesFirstRadiance(ctx);

    gl::resetPipelineState(ctx.width, ctx.height);
    fbo.bind();
    if (counting) {
        fbo.setDrawBuffers({0, 1});  // clearing draw buffer 1 needs it enabled
        fbo.clearColor(1, 0, 0, 0, 0);
    }
    fbo.setDrawBuffers({0});
    // Ambient + emission + background: the first write, no blending (unless
    // the strategy's own pass makes it).
    if (!strategyWritesFirst) {
        ambientProgram_->use();
        triangle_.draw();
    }
    const gl::Program& fullscreen = shading_.fullscreen(counting);
    auto drawScreenLights = [&] {
        for (const LightTableEntry* e : screenLights) {
            beginLight(*e);
            fullscreen.use();
            fullscreen.set(0, e->row);
            triangle_.draw();
            if (e->light->type == LightType::Directional) ++counts_.directional;
            else ++counts_.fullscreen;
        }
    };
    if (!strategyWritesFirst) drawScreenLights();
    // Spheres before cones (fewer state changes), otherwise in scene order.
    std::stable_sort(frame.lights.begin(), frame.lights.end(), [](const LightTableEntry* a, const LightTableEntry* b) {
        return (a->volume.shape == VolumeShape::Cone) < (b->volume.shape == VolumeShape::Cone);
    });
    addStrategyCounts(strategy.shade(frame));
    if (strategyWritesFirst) drawScreenLights();
    for (auto& other : strategies_->all())
        if (other.get() != &strategy) other->writeOutputs(frame);  // their lists, when asked for
    if (ctx.wants("lighting.shadow")) writeShadowFactor(ctx, table, bindInputs);
    gl::resetPipelineState(ctx.width, ctx.height);
    fbo.bind();
    fbo.setDrawBuffers({0});
    for (const LightTableEntry& e : table.entries) counts_.shadowed += (ctx.shadows && e.shadowed) ? 1 : 0;
    lastStrategy_ = strategy.name();
    return strategy;
}

void LightingPass::describe(const FrameContext& ctx, const LightingStrategy& strategy) {
    const bool strategyWritesFirst = strategy.writesFirstRadiance(ctx);
    const int total = counts_.directional + counts_.directionalInGBuffer + counts_.fullscreen + counts_.volumes + counts_.grid + counts_.frustumCulled +
                      counts_.belowThreshold;
    stats_ = std::string(strategy.name()) + ", " + std::to_string(total) + " lights: " + std::to_string(counts_.directional) +
             " directional, " +
             (counts_.directionalInGBuffer > 0
                  ? std::to_string(counts_.directionalInGBuffer) + " directional shaded in the G-buffer pass, "
                  : std::string()) + (counts_.grid > 0 ? std::to_string(counts_.grid) + " " + counts_.gridWhere + ", " : "") +
             std::to_string(counts_.volumes) + " volumes" +
             (counts_.batches > 0 ? " in " + std::to_string(counts_.batches) + " batches" : std::string()) + ", " + std::to_string(counts_.fullscreen) +
             " full-screen, " + std::to_string(counts_.frustumCulled) + " outside the frustum, " +
             std::to_string(counts_.belowThreshold) + " below threshold";
    if (counts_.shadowed > 0) stats_ += "; " + std::to_string(counts_.shadowed) + " with shadow maps";
    if (strategyWritesFirst) stats_ += std::string("; ambient, emission and sky in the ") + strategy.name() + " pass";
    if (!autoWhy_.empty()) stats_ += "; " + autoWhy_;
    if (!msaaLine_.empty()) stats_ += "; " + msaaLine_;
}

}  // namespace dw
