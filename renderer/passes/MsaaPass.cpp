#include "renderer/passes/MsaaPass.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "renderer/gl/DeviceLimits.h"
#include "renderer/passes/AaMethod.h"

namespace dw {

long long MsaaPass::countEdges(const gl::Texture& edges, int width, int height) {
    std::vector<unsigned char> mask(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(edges.id(), 0, GL_RED, GL_UNSIGNED_BYTE, static_cast<GLsizei>(mask.size()), mask.data());
    return std::count_if(mask.begin(), mask.end(), [](unsigned char v) { return v >= 128; });
}

int MsaaPass::deviceCap() {
    int cap = gl::maxMultisampleSamples({GL_RGBA16, GL_SRGB8_ALPHA8, GL_RG16_SNORM, GL_RG8_SNORM, GL_R11F_G11F_B10F,
                                         GL_R8, GL_RGBA32F, GL_DEPTH32F_STENCIL8, GL_DEPTH24_STENCIL8});
    for (GLenum limit : {GL_MAX_SAMPLES, GL_MAX_COLOR_TEXTURE_SAMPLES, GL_MAX_DEPTH_TEXTURE_SAMPLES}) {
        GLint v = 0;
        glGetIntegerv(limit, &v);
        if (v > 0) cap = std::min(cap, static_cast<int>(v));
    }
    return std::max(cap, 1);
}

int MsaaPass::requestedSamples(const KnobRegistry& knobs) {
    return std::stoi(knobs.choice(knobs.requireEnum(kAaSamplesKnob)));
}

int MsaaPass::samples(const KnobRegistry& knobs) {
    return std::min(requestedSamples(knobs), deviceCap());
}

MsaaPass::MsaaPass(KnobRegistry& knobs) {
    method_ = declareAaMethod(knobs, "msaa",
                              "deferred MSAA: a multisampled G-buffer, shaded per pixel where its samples agree and per "
                              "sample on edge pixels (aa.edges), the radiance box-resolved");
    knobs.addEnum(kAaSamplesKnob, {"2", "4", "8", "16"}, "4", kAaGroup,
                  "MSAA's samples per pixel in the multisampled G-buffer; capped by what the device offers for the "
                  "G-buffer's formats (4 on llvmpipe, 8 or more on GPUs), the cap said",
                  true);
}

std::vector<OutputDecl> MsaaPass::outputs() const {
    return {{"aa.edges", OutputKind::Scalar,
             std::string("MSAA's edge mask: 1 where the pixel's samples are shaded each, 0 where the pixel is shaded once, "
                         "at its centre (R8); ") +
                 kEdgeRule,
             texture2D(GL_R8), 1}};
}

PassIO MsaaPass::inputs(const KnobRegistry&) const {
    PassIO io;
    io.inputs.assign(std::begin(kMsaaGBuffer), std::end(kMsaaGBuffer));
    io.inputs.push_back(kMsaaDepth);
    return io;
}

std::string MsaaPass::skipReason(const KnobRegistry& knobs, const Scene&) const {
    return aaMethodSkipReason(knobs, method_, "msaa");
}

void MsaaPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "gbuffer/msaa_edges.frag"});
}

void MsaaPass::execute(FrameContext& ctx) {
    const int n = ctx.output(kMsaaDepth).desc.samples;
    const char* names[] = {"gbuffer.ms.albedo", "gbuffer.ms.normal", "gbuffer.ms.specular", "gbuffer.ms.emissive",
                           kMsaaDepth};
    const GLuint units[] = {binding::MSAA_ALBEDO_TEXTURE, binding::MSAA_NORMAL_TEXTURE, binding::MSAA_SPECULAR_TEXTURE,
                            binding::MSAA_EMISSIVE_TEXTURE, binding::MSAA_DEPTH_TEXTURE};
    for (std::size_t i = 0; i < std::size(names); ++i) ctx.texture(names[i]).bind(units[i]);
    target_.get(ctx, {"aa.edges"}, {}, "aa.edges").bind();
    program_->use();
    program_->set(0, n);
    program_->set(1, kRelativeDepth);
    program_->set(2, static_cast<float>(std::cos(kNormalDegrees * 3.14159265358979 / 180.0)));
    triangle_.draw();
    const int want = requestedSamples(ctx.knobs);
    stats_ = std::to_string(n) + " samples" +
             (want > n ? " (aa.samples = " + std::to_string(want) + " capped)" : std::string());
    warning_.clear();
    if (want > n)
        warning_ = "aa.samples " + std::to_string(want) + " is capped to " + std::to_string(n) + ": the device offers " +
                   std::to_string(n) + " samples for the G-buffer's formats (GL_MAX_SAMPLES, GL_MAX_COLOR_TEXTURE_SAMPLES, "
                   "GL_MAX_DEPTH_TEXTURE_SAMPLES, glGetInternalformativ)";
}

namespace {
// The ordinary G-buffer, as MsaaSampleCopy saves and restores it.
std::vector<std::string> gbufferNames(bool directional) {
    std::vector<std::string> names = {"gbuffer.albedo", "gbuffer.normal",   "gbuffer.specular",
                                      "gbuffer.emissive", "gbuffer.occlusion", "gbuffer.depth"};
    if (directional) names.push_back("gbuffer.directional");
    return names;
}

void copyImage(const gl::Texture& from, const gl::Texture& to, int width, int height) {
    glCopyImageSubData(from.id(), GL_TEXTURE_2D, 0, 0, 0, 0, to.id(), GL_TEXTURE_2D, 0, 0, 0, 0, width, height, 1);
}
}  // namespace

void MsaaSampleCopy::save(const FrameContext& ctx, bool directional) {
    const std::vector<std::string> names = gbufferNames(directional);
    std::vector<GLenum> formats;
    for (const std::string& n : names) formats.push_back(ctx.output(n).desc.format);
    if (formats != savedFormats_ || savedWidth_ != ctx.width || savedHeight_ != ctx.height) {
        saved_.clear();
        for (GLenum f : formats) saved_.push_back(gl::Texture::create2D(f, ctx.width, ctx.height));
        savedFormats_ = formats;
        savedWidth_ = ctx.width;
        savedHeight_ = ctx.height;
    }
    for (std::size_t i = 0; i < names.size(); ++i) copyImage(ctx.texture(names[i]), saved_[i], ctx.width, ctx.height);
}

void MsaaSampleCopy::restore(const FrameContext& ctx, bool directional) {
    const std::vector<std::string> names = gbufferNames(directional);
    for (std::size_t i = 0; i < names.size(); ++i) copyImage(saved_[i], ctx.texture(names[i]), ctx.width, ctx.height);
}

void MsaaSampleCopy::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "gbuffer/msaa_copy.frag"});
    directionalProgram_ =
        shaders.get({.vertex = "fullscreen.vert", .fragment = "gbuffer/msaa_copy.frag", .defines = {"DIRECTIONAL_IN_GBUFFER"}});
}

void MsaaSampleCopy::copy(const FrameContext& ctx, int sample, bool directional) {
    gl::resetPipelineState(ctx.width, ctx.height);
    const gl::Framebuffer& fbo =
        directional ? directionalTarget_.get(ctx,
                                             {"gbuffer.albedo", "gbuffer.normal", "gbuffer.specular", "gbuffer.emissive",
                                              "gbuffer.occlusion", "gbuffer.directional"},
                                             "gbuffer.depth", "MSAA sample copy")
                    : target_.get(ctx, {"gbuffer.albedo", "gbuffer.normal", "gbuffer.specular", "gbuffer.emissive", "gbuffer.occlusion"},
                                  "gbuffer.depth", "MSAA sample copy");
    fbo.bind();
    for (int i = 0; i < 4; ++i) fbo.clearColor(i, 0, 0, 0, 0);
    fbo.clearColor(4, 1, 1, 1, 1);
    if (directional) fbo.clearColor(5, 0, 0, 0, 0);
    fbo.clearDepthStencil(ctx.depth().farDepth(), 0);
    const GLuint units[] = {binding::MSAA_ALBEDO_TEXTURE, binding::MSAA_NORMAL_TEXTURE, binding::MSAA_SPECULAR_TEXTURE,
                            binding::MSAA_EMISSIVE_TEXTURE, binding::MSAA_OCCLUSION_TEXTURE};
    for (std::size_t i = 0; i < std::size(kMsaaGBuffer); ++i) ctx.texture(kMsaaGBuffer[i]).bind(units[i]);
    ctx.texture(kMsaaDepth).bind(binding::MSAA_DEPTH_TEXTURE);
    if (directional) ctx.texture(kMsaaDirectional).bind(binding::MSAA_DIRECTIONAL_TEXTURE);
    ctx.texture("aa.edges").bind(binding::MSAA_EDGES_TEXTURE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glEnable(GL_FRAMEBUFFER_SRGB);  // albedo and specular: linear values encoded on write, as the geometry pass does
    const gl::Program& program = directional ? *directionalProgram_ : *program_;
    program.use();
    program.set(0, sample);
    triangle_.draw();
    gl::resetPipelineState(ctx.width, ctx.height);
}

void MsaaResolve::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/msaa_accumulate.frag"});
}

void MsaaResolve::accumulate(const FrameContext& ctx, int samples, bool first) {
    if (!sum_ || width_ != ctx.width || height_ != ctx.height) {
        sum_ = gl::Texture::create2D(GL_RGBA32F, ctx.width, ctx.height);
        sumTarget_ = gl::Framebuffer::forColor(sum_, "MSAA radiance sum");
        width_ = ctx.width;
        height_ = ctx.height;
    }
    gl::resetPipelineState(ctx.width, ctx.height);
    sumTarget_.bind();
    if (!first) {
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
    }
    ctx.texture("lbuffer").bind(binding::MSAA_LBUFFER_TEXTURE);
    ctx.texture("aa.edges").bind(binding::MSAA_EDGES_TEXTURE);
    program_->use();
    program_->set(0, first ? 1 : 0);
    program_->set(1, 1.0f / static_cast<float>(samples));
    triangle_.draw();
    gl::resetPipelineState(ctx.width, ctx.height);
}

void MsaaResolve::finish(const FrameContext& ctx) {
    const gl::Texture& lbuffer = ctx.texture("lbuffer");
    glCopyImageSubData(sum_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, lbuffer.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ctx.width, ctx.height, 1);
}

}  // namespace dw
