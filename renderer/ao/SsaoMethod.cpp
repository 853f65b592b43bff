#include "renderer/ao/SsaoMethod.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/scene/GpuScene.h"
#include "renderer/scene/IntegerHash.h"
#include "renderer/scene/Scene.h"
#include "shaders/params/ssao.h"

namespace dw {

namespace {

float hash01(std::uint32_t x) { return hashToUnit(x); }

}  // namespace

SsaoMethod::SsaoMethod(KnobRegistry& knobs) {
    samples_ = knobs.addInt("ssao.samples", 16, 4, gpu::SSAO_MAX_SAMPLES, "ssao",
                            "kernel samples per pixel (seed 000: 8 low, 16 average, 32 high)", "", true);
    radius_ = knobs.addFloat("ssao.radius", 1.0, 0.01, 20.0, "ssao",
                             "radius of the sampling hemisphere, in ssao.radius_unit (the inspector gives it in world units)",
                             "units", false, true);
    radiusUnit_ = knobs.addEnum("ssao.radius_unit", {"world", "scene_fraction"}, "scene_fraction", "ssao",
                                "world: ssao.radius in world units (seed 000's SSAO1-5 presets); scene_fraction: in "
                                "units of the scene's size, 10^round(log10(R / 10)) for a bounding radius R, so a model "
                                "authored in millimetres or kilometres gets the AO it would get in metres (1 for scenes of "
                                "radius 3.2 to 32)");
    intensity_ = knobs.addFloat("ssao.intensity", 1.0, 0.0, 4.0, "ssao", "scale of the occlusion: AO = 1 - intensity x mean occlusion");
    bias_ = knobs.addFloat("ssao.bias", 0.025, 0.0, 0.5, "ssao",
                           "depth tolerance before a sample counts as occluded, as a fraction of the radius");
    rangeCheck_ = knobs.addBool("ssao.range_check", true, "ssao",
                                "fade occluders much nearer the camera than the point (depth discontinuities)");
    // In the order of the shift to the AO size: the choice's index is the shift.
    resolution_ = knobs.addEnum("ssao.resolution", {"full", "half", "quarter"}, "half", "ssao",
                                "AO buffer size: w x h, w/2 x h/2 or w/4 x h/4 (seed 000 table 6.4)", true);
}

float SsaoMethod::sceneUnit(const Bounds& bounds) { return static_cast<float>(sceneLengthUnit(bounds)); }

float SsaoMethod::worldRadius(const KnobRegistry& knobs, const Bounds& bounds) const {
    const float r = knobs.get(radius_);
    return knobs.choice(radiusUnit_) == "world" ? r : r * sceneUnit(bounds);
}

std::string SsaoMethod::description() const {
    return "screen-space AO (seed 000 section 4.6.3): ssao.samples points of a kernel in the normal's hemisphere "
           "tested against the depth buffer, falloff 1 / (1 + d^2)";
}

std::vector<std::string> SsaoMethod::knobNames() const {
    return {"ssao.samples", "ssao.radius", "ssao.radius_unit", "ssao.intensity", "ssao.bias", "ssao.range_check",
            "ssao.resolution"};
}

glm::ivec2 SsaoMethod::aoSize(const KnobRegistry& knobs, int width, int height) const {
    const int shift = knobs.get(resolution_);  // full, half, quarter: 0, 1, 2
    return {std::max(width >> shift, 1), std::max(height >> shift, 1)};
}

std::vector<glm::vec4> SsaoMethod::kernel(int n) {
    std::vector<glm::vec4> k;
    for (int i = 0; i < n; ++i) {
        // A uniform direction, then a length that puts more samples near the
        // centre (nearby occluders matter most).
        const float z = 2.0f * hash01(static_cast<std::uint32_t>(3 * i + 1)) - 1.0f;
        const float phi = 6.28318531f * hash01(static_cast<std::uint32_t>(3 * i + 2));
        const float s = std::sqrt(std::max(1.0f - z * z, 0.0f));
        const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);
        const float len = 0.1f + 0.9f * t * t;
        k.emplace_back(glm::vec3(s * std::cos(phi), s * std::sin(phi), z) * len, 0.0f);
    }
    return k;
}

void SsaoMethod::setup(gl::ShaderLibrary& shaders) {
    linearDepth_ = gl::Sampler::create(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, "ssao linear depth");
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "ssao/ssao.frag"});
    params_.create();
    constexpr int n = gpu::SSAO_NOISE_SIZE;
    std::vector<glm::vec4> noise;
    for (std::uint32_t i = 0; i < n * n; ++i) {
        const float z = 2.0f * hash01(1000 + 2 * i) - 1.0f;
        const float phi = 6.28318531f * hash01(1001 + 2 * i);
        const float s = std::sqrt(std::max(1.0f - z * z, 0.0f));
        noise.emplace_back(s * std::cos(phi), s * std::sin(phi), z, 0.0f);
    }
    noise_ = gl::Texture::create2D(GL_RGBA16F, n, n);
    noise_.upload(0, n, n, GL_RGBA, GL_FLOAT, noise.data());
    noise_.setFilter(GL_NEAREST, GL_NEAREST);
}

void SsaoMethod::run(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    const glm::ivec2 size = aoSize(k, ctx.width, ctx.height);
    gpu::SsaoParams p{};
    const int n = k.get(samples_);
    if (static_cast<int>(kernel_.size()) != n) kernel_ = kernel(n);
    std::copy(kernel_.begin(), kernel_.end(), p.kernel);
    p.sampleCount = n;
    p.rangeCheck = k.get(rangeCheck_) ? 1 : 0;
    p.aoSize = size;
    const float radius = worldRadius(k, ctx.gpu.bounds());
    p.radius = radius;
    p.intensity = k.get(intensity_);
    p.bias = k.get(bias_);
    params_.upload(p, binding::PASS_UBO);
    ctx.texture("gbuffer.depth").bind(binding::SSAO_DEPTH_TEXTURE);
    linearDepth_.bind(binding::SSAO_DEPTH_TEXTURE);
    ctx.texture("gbuffer.normal").bind(binding::SSAO_NORMAL_TEXTURE);
    noise_.bind(binding::SSAO_NOISE_TEXTURE);
    glViewport(0, 0, size.x, size.y);
    target_.get(ctx, {"ao.raw"}, {}, "SSAO").bind();
    program_->use();
    triangle_.draw();
    char r[48];
    std::snprintf(r, sizeof(r), ", radius %.4g world units", radius);
    stats_ = std::to_string(n) + " samples at " + std::to_string(size.x) + "x" + std::to_string(size.y) + r;
}

}  // namespace dw
