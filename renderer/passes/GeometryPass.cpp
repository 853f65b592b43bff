#include "renderer/passes/GeometryPass.h"

#include <cstdio>
#include <string>

#include "renderer/Error.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/lighting/LightTable.h"
#include "renderer/passes/AaMethod.h"
#include "renderer/scene/GpuScene.h"
#include "renderer/scene/Scene.h"

namespace dw {

GeometryPass::GeometryPass(KnobRegistry& knobs) {
    knobs.addEnum("depth.mode", {"reversed", "conventional"}, 0, "depth",
                  "depth mapping of every depth buffer (G-buffer, shadow maps): reversed (near 1, far 0, GL_GREATER; "
                  "float depth keeps about 1e-7 relative precision at every distance) or conventional (near 0, far 1, "
                  "GL_LESS; precision spent near the camera)");
    materialFormat_ = knobs.addEnum(
        "gbuffer.material_format", {"srgb8", "unorm16"}, "unorm16", "gbuffer",
        "the storage of gbuffer.albedo and gbuffer.specular: srgb8 (4 bytes each, the seeds' layout: colours rounded "
        "to 8-bit sRGB, up to about 0.55% of a mid-grey, and the exponent to 1/255 of its log2 range, which a forward "
        "strategy's unquantised material shows as a mean difference of about 0.6% on a 0.6 diffuse) or unorm16 (8 "
        "bytes each, rounding 256 times finer)",
        true);
    normalEncoding_ = knobs.addEnum(
        "gbuffer.normal_encoding", {"kl16", "oct16", "oct8"}, "kl16", "gbuffer",
        "the storage of gbuffer.normal, a view-space unit vector in two signed channels: kl16 (Kircher-Lawrance, "
        "RG16_SNORM, seed 000: its error grows towards normals facing straight away from the viewer), oct16 "
        "(octahedral, RG16_SNORM, Cigolle et al. 2014: about as fine everywhere) or oct8 (octahedral, RG8_SNORM: half "
        "the bytes, about a degree of error)",
        true);
    depthFormat_ = knobs.addEnum(
        "gbuffer.depth_format", {"float32", "unorm24"}, "float32", "gbuffer",
        "the storage of gbuffer.depth (and lbuffer.depth): float32 (DEPTH32F_STENCIL8: with depth.mode=reversed "
        "about 1e-7 relative precision at every distance) or unorm24 (DEPTH24_STENCIL8: 2^-24 steps of window depth, "
        "so with a far/near ratio of 1e4 or more distant surfaces share depth values and z-fight, more so with "
        "depth.mode=reversed, whose precision float needs)",
        true);
    textureFilter_ = knobs.addEnum(
        "gbuffer.texture_filter", {"mipmap", "base_level", "aniso2", "aniso4", "aniso8", "aniso16"}, "mipmap", "gbuffer",
        "how the materials' textures are filtered: mipmap (trilinear mip-mapping as each "
        "glTF sampler asks, no anisotropic filtering: the pixel's footprint as a square, so blurred where it is "
        "long), aniso2 .. aniso16 (trilinear plus GL_TEXTURE_MAX_ANISOTROPY 2 .. 16: up to N lookups along the "
        "footprint's long axis, sharper on oblique surfaces; capped by the device, and to 1x on llvmpipe, whose "
        "anisotropic lookups can spin for minutes, and said) or base_level (bilinear "
        "at the full-resolution level, as the CPU reference samples at each point: aliases where textures are "
        "minified); mipmap and base_level mean the same on every device");
    directional_ = knobs.addBool("lighting.directional_in_gbuffer", false, "lighting",
                                 "shade the directional lights without a shadow map in the G-buffer pass, from the "
                                 "unquantised material, into gbuffer.directional, instead of one full-screen pass each "
                                 "in the lighting pass (seed 000 section 3.2.1); at most 8, the rest as before");
}

PassIO GeometryPass::inputs(const KnobRegistry& knobs) const {
    PassIO io;
    if (knobs.get(directional_)) io.inputs.push_back("lights.table");
    return io;
}

std::vector<OutputDecl> GeometryPass::outputs() const {
    return {
        {"gbuffer.albedo", OutputKind::Color,
         "diffuse colour (RGBA16, or sRGB8 with gbuffer.material_format = srgb8); alpha holds the pixel type (0 "
         "background, 1 surface)",
         texture2D(GL_SRGB8_ALPHA8), 4},
        {"gbuffer.normal", OutputKind::NormalKL,
         "view-space normal, encoded as gbuffer.normal_encoding says (Kircher-Lawrance or octahedral in RG16_SNORM, "
         "octahedral in RG8_SNORM)",
         texture2D(GL_RG16_SNORM), 2},
        {"gbuffer.specular", OutputKind::Color,
         "specular colour (RGBA16, or sRGB8 with gbuffer.material_format = srgb8); alpha = log2(Blinn-Phong "
         "exponent)/11",
         texture2D(GL_SRGB8_ALPHA8), 4},
        {"gbuffer.emissive", OutputKind::HdrColor, "emitted radiance (R11G11B10F)", texture2D(GL_R11F_G11F_B10F), 3},
        {"gbuffer.occlusion", OutputKind::Scalar,
         "baked ambient accessibility from the material's occlusion texture, 1 without one (R8)", texture2D(GL_R8), 1},
        {"gbuffer.depth", OutputKind::Depth,
         "window-space depth (DEPTH32F_STENCIL8, or DEPTH24_STENCIL8 with gbuffer.depth_format=unorm24)", texture2D(GL_DEPTH32F_STENCIL8), 1},
        {"gbuffer.directional", OutputKind::HdrColor,
         "with lighting.directional_in_gbuffer: the directional lights without a shadow map, shaded in the G-buffer "
         "pass (RGBA32F)",
         texture2D(GL_RGBA32F), 3, true},
        {"gbuffer.ms.albedo", OutputKind::Color, "aa.method=msaa: gbuffer.albedo multisampled (aa.samples samples)",
         textureMultisample(GL_SRGB8_ALPHA8, 4), 4},
        {"gbuffer.ms.normal", OutputKind::NormalKL, "aa.method=msaa: gbuffer.normal multisampled",
         textureMultisample(GL_RG16_SNORM, 4), 2},
        {"gbuffer.ms.specular", OutputKind::Color, "aa.method=msaa: gbuffer.specular multisampled",
         textureMultisample(GL_SRGB8_ALPHA8, 4), 4},
        {"gbuffer.ms.emissive", OutputKind::HdrColor, "aa.method=msaa: gbuffer.emissive multisampled",
         textureMultisample(GL_R11F_G11F_B10F, 4), 3},
        {"gbuffer.ms.occlusion", OutputKind::Scalar, "aa.method=msaa: gbuffer.occlusion multisampled",
         textureMultisample(GL_R8, 4), 1},
        {"gbuffer.ms.depth", OutputKind::Depth, "aa.method=msaa: gbuffer.depth multisampled, each sample's own depth",
         textureMultisample(GL_DEPTH32F_STENCIL8, 4), 1},
        {"gbuffer.ms.directional", OutputKind::HdrColor,
         "aa.method=msaa with lighting.directional_in_gbuffer: gbuffer.directional multisampled",
         textureMultisample(GL_RGBA32F, 4), 3, true},
    };
}

void GeometryPass::connect(const KnobRegistry& knobs) {
    aaMethod_ = knobs.requireEnum(kAaMethodKnob);
    aaMsaa_ = knobs.choiceIndex(aaMethod_, "msaa");
}

bool GeometryPass::allocates(const OutputDecl& output, const KnobRegistry& knobs) const {
    if (output.name.rfind("gbuffer.ms.", 0) != 0) return true;
    return msaa(knobs) && (output.name != kMsaaDirectional || knobs.get(directional_));
}

ResourceDesc GeometryPass::resource(const OutputDecl& output, const KnobRegistry& knobs) const {
    ResourceDesc d = output.resource;
    std::string name = output.name;
    if (name.rfind("gbuffer.ms.", 0) == 0) {
        name = "gbuffer." + name.substr(std::string("gbuffer.ms.").size());  // the same format as the ordinary one
        d.samples = MsaaPass::samples(knobs);
    }
    if ((name == "gbuffer.albedo" || name == "gbuffer.specular") &&
        knobs.get(materialFormat_) == knobs.choiceIndex(materialFormat_, "unorm16"))
        d.format = GL_RGBA16;
    if (name == "gbuffer.normal" && knobs.get(normalEncoding_) == knobs.choiceIndex(normalEncoding_, "oct8"))
        d.format = GL_RG8_SNORM;
    if (name == "gbuffer.depth" && knobs.get(depthFormat_) == knobs.choiceIndex(depthFormat_, "unorm24"))
        d.format = GL_DEPTH24_STENCIL8;
    return d;
}

float GeometryPass::requestedAnisotropy(const std::string& textureFilter) {
    if (textureFilter.rfind("aniso", 0) != 0) return 1.0f;
    return std::stof(textureFilter.substr(5));
}

std::string GeometryPass::anisotropyCapLine(const std::string& textureFilter, float deviceMax, bool llvmpipe) {
    const float want = requestedAnisotropy(textureFilter);
    if (llvmpipe && want > 1.0f)
        return "gbuffer.texture_filter=" + textureFilter +
               " is capped to 1x (mipmap) on llvmpipe: its anisotropic lookups spin for minutes at a grazing angle over "
               "a texture repeated thousands of times (Mesa 22.3)";
    if (want <= deviceMax) return {};
    char line[200];
    std::snprintf(line, sizeof(line),
                  "gbuffer.texture_filter=%s is capped to %gx: the device's GL_MAX_TEXTURE_MAX_ANISOTROPY is %g",
                  textureFilter.c_str(), static_cast<double>(deviceMax), static_cast<double>(deviceMax));
    return line;
}

void GeometryPass::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "geometry.vert", .fragment = "geometry.frag"});
    directionalProgram_ = shaders.get({.vertex = "geometry.vert", .fragment = "geometry.frag", .defines = {"DIRECTIONAL_IN_GBUFFER"}});
}

const gl::Framebuffer& GeometryPass::target(FrameContext& ctx, bool directional, bool multisampled) {
    if (multisampled)
        return directional ? msDirectionalTarget_.get(ctx,
                                                      {"gbuffer.ms.albedo", "gbuffer.ms.normal", "gbuffer.ms.specular",
                                                       "gbuffer.ms.emissive", "gbuffer.ms.occlusion", kMsaaDirectional},
                                                      kMsaaDepth, "multisampled G-buffer")
                           : msTarget_.get(ctx,
                                           {"gbuffer.ms.albedo", "gbuffer.ms.normal", "gbuffer.ms.specular",
                                            "gbuffer.ms.emissive", "gbuffer.ms.occlusion"},
                                           kMsaaDepth, "multisampled G-buffer");
    return directional ? directionalTarget_.get(ctx,
                                                {"gbuffer.albedo", "gbuffer.normal", "gbuffer.specular", "gbuffer.emissive",
                                                 "gbuffer.occlusion", "gbuffer.directional"},
                                                "gbuffer.depth", "G-buffer")
                       : target_.get(ctx, {"gbuffer.albedo", "gbuffer.normal", "gbuffer.specular", "gbuffer.emissive", "gbuffer.occlusion"},
                                     "gbuffer.depth", "G-buffer");
}

void GeometryPass::execute(FrameContext& ctx) {
    if (ctx.wants("gbuffer.directional") && !ctx.knobs.get(directional_))
        throw Error("gbuffer.directional is written only with lighting.directional_in_gbuffer=true");
    const bool directional = ctx.knobs.get(directional_) && ctx.wants("gbuffer.directional") && ctx.lightTable;
    for (const OutputDecl& o : outputs())
        if (o.name.rfind("gbuffer.ms.", 0) == 0 && ctx.wants(o.name) && !msaa(ctx.knobs))
            throw Error(o.name + " is written only with aa.method=msaa");
    // For the whole frame: the forward strategies draw the materials with the same samplers.
    const std::string filter = ctx.knobs.choice(textureFilter_);
    const float anisotropy = ctx.gpu.setTextureFiltering(filter == "base_level", requestedAnisotropy(filter));
    capLine_ = anisotropyCapLine(filter, GpuScene::deviceMaxAnisotropy(), GpuScene::onLlvmpipe());
    // Outputs are nearest-filtered: a G-buffer value between pixels means
    // nothing (SSAO reads depth between pixel centres through its own sampler).
    drawScene(ctx, target(ctx, directional, false), directional, false);
    char textures[128];
    std::snprintf(textures, sizeof(textures), ", textures %s (anisotropy %gx; up to %gx here)", filter.c_str(),
                  static_cast<double>(anisotropy), static_cast<double>(GpuScene::maxAnisotropy()));
    stats_ += textures;
    // MSAA: the multisampled G-buffer too; every later pass but the
    // lighting pass's edge samples reads the pixel centres' one above.
    if (msaa(ctx.knobs)) {
        drawScene(ctx, target(ctx, directional, true), directional, true);
        stats_ += "; again into the multisampled G-buffer, " + std::to_string(ctx.output(kMsaaDepth).desc.samples) +
                  " samples";
    }
}

void GeometryPass::drawScene(FrameContext& ctx, const gl::Framebuffer& fbo, bool directional, bool multisampled) {
    fbo.bind();
    fbo.clearColor(0, 0, 0, 0, 0);
    fbo.clearColor(1, 0, 0, 0, 0);
    fbo.clearColor(2, 0, 0, 0, 0);
    fbo.clearColor(3, 0, 0, 0, 0);
    fbo.clearColor(4, 1, 1, 1, 1);
    if (directional) fbo.clearColor(5, 0, 0, 0, 0);
    const DepthConvention depth = ctx.depth();
    fbo.clearDepthStencil(depth.farDepth(), 0);
    if (multisampled) glEnable(GL_MULTISAMPLE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth.nearer());
    // Albedo and specular are sRGB targets: encode the shader's linear values
    // on write, so sampling them decodes back to linear.
    glEnable(GL_FRAMEBUFFER_SRGB);
    const gl::Program& program = directional ? *directionalProgram_ : *program_;
    program.use();
    std::vector<int> rows;
    if (directional) {
        rows = gbufferDirectionalRows(*ctx.lightTable, ctx.shadows != nullptr);
        program.set(2, static_cast<int>(rows.size()));
        for (std::size_t i = 0; i < rows.size(); ++i) program.set(3 + static_cast<GLint>(i), rows[i]);
        ctx.lightTable->buffer->bindBase(GL_SHADER_STORAGE_BUFFER, binding::LIGHT_SSBO);
    }
    // Blended materials stay out of the G-buffer (and so out of SSAO and the
    // deferred lighting): the oit pass draws them over the L-buffer.
    ctx.gpu.draw(program, GpuScene::Filter::Opaque);
    stats_ = std::to_string(ctx.gpu.draws().size()) + " draws, " + std::to_string(ctx.gpu.triangleCount()) + " triangles";
    if (directional) stats_ += ", " + std::to_string(rows.size()) + " directional lights shaded";
}

}  // namespace dw
