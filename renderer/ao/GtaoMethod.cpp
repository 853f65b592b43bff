#include "renderer/ao/GtaoMethod.h"

#include <algorithm>
#include <cstdio>

#include "renderer/scene/GpuScene.h"
#include "renderer/scene/Mesh.h"

namespace dw {

GtaoMethod::GtaoMethod(KnobRegistry& knobs) {
    slices_ = knobs.addInt("gtao.slices", 3, 1, gpu::GTAO_MAX_SLICES, "gtao",
                           "screen-space slices (directions) per pixel, rotated per pixel in a 4x4 pattern "
                           "(XeGTAO: 1 low, 2 medium, 3 high, 9 ultra)", "", true);
    steps_ = knobs.addInt("gtao.steps", 3, 1, gpu::GTAO_MAX_STEPS, "gtao",
                          "depth samples per side of each slice (XeGTAO: 2 low and medium, 3 high and ultra)", "",
                          true);
    radius_ = knobs.addFloat("gtao.radius", 1.0, 0.01, 20.0, "gtao",
                             "the world-space radius the horizon search covers, in gtao.radius_unit", "units", false,
                             true);
    radiusUnit_ = knobs.addEnum("gtao.radius_unit", {"world", "scene_fraction"}, "scene_fraction", "gtao",
                                "world: gtao.radius in world units; scene_fraction: in the scene's power-of-ten "
                                "unit, as ssao.radius_unit");
    falloff_ = knobs.addFloat("gtao.falloff", 0.0, 0.0, 1.0, "gtao",
                              "share of the radius over which a sample's weight falls linearly to 0 at the radius "
                              "(XeGTAO uses 0.615); 0, the default: a hard cut at the radius, as the ray-traced AO has (closest to it, docs/ao.md)");
    thickness_ = knobs.addFloat("gtao.thickness", 0.0, 0.0, 1.0, "gtao",
                                "thickness heuristic (Jimenez et al. 2016 section 4.3): how far a horizon sinks "
                                "back towards a lower sample per step; 0 takes every occluder as infinitely thick");
    // 1: with 0.8 and 0.9 the least summed error against the ray-traced AO
    // over a thin pole before a wall, a crease and the floor under a raised
    // box, and the least over other poles (docs/ao.md, "Thin occluders").
    thinOccluders_ = knobs.addFloat("gtao.thin_occluders", 1.0, 0.0, 1.0, "gtao",
                                    "thin-occluder compensation: a sample beyond which, as far along the slice as it "
                                    "stands before the shaded point, the point's own surface is back (a pole before "
                                    "a wall; not a box, a crease or a sphere) loses this share of its rise of the "
                                    "horizon and shades that share of the angle it subtends instead (docs/ao.md); "
                                    "0: every occluder infinitely thick");
    resolution_ = knobs.addEnum("gtao.resolution", {"full", "half"}, "full", "gtao",
                                "ao.raw's size, w x h or w/2 x h/2 (upsampled by the shared filter)", true);
    denoise_ = knobs.addEnum("gtao.denoise", {"shared", "edge_aware", "off"}, "shared", "gtao",
                             "spatial denoise of the 4x4 rotation pattern: shared (the cross-bilateral filter "
                             "ssao_blur.*), edge_aware (GTAO's own 5x5 filter weighted by the distance from the "
                             "pixel's tangent plane and the normals, as XeGTAO's denoiser; gtao.noisy before it) "
                             "or off (ao.raw only upsampled)");
    multibounce_ = knobs.addBool("gtao.multibounce", false, "gtao",
                                 "the lighting pass lifts the ambient term's accessibility x per colour channel by "
                                 "Jimenez et al. 2016's fit of interreflections, max(x, ((a x + b) x + c) x) with "
                                 "a, b, c linear in the G-buffer albedo; off, the default: single bounce, as the "
                                 "ray-traced reference has (docs/ao.md)");
    bentNormals_ = knobs.addBool("gtao.bent_normals", false, "gtao",
                                 "also write gtao.bent_normal, the cosine-weighted mean unoccluded direction from "
                                 "the horizon search (view space); the ambient term here has no normal to replace, "
                                 "so the image does not change (docs/ao.md)");
    shared_ = knobs.choiceIndex(denoise_, "shared");
    edgeAware_ = knobs.choiceIndex(denoise_, "edge_aware");
}

std::string GtaoMethod::description() const {
    return "ground-truth AO (Jimenez et al. 2016, XeGTAO): horizons in gtao.slices screen-space slices, the "
           "closed-form cosine-weighted visibility";
}

std::vector<std::string> GtaoMethod::knobNames() const {
    return {"gtao.slices", "gtao.steps", "gtao.radius", "gtao.radius_unit", "gtao.falloff", "gtao.thickness",
            "gtao.thin_occluders", "gtao.resolution", "gtao.denoise", "gtao.multibounce", "gtao.bent_normals"};
}

std::vector<OutputDecl> GtaoMethod::outputs() const {
    return {{"gtao.noisy", OutputKind::Scalar,
             "GTAO's visibility before its edge-aware denoise (gtao.denoise = edge_aware; R16F, at gtao.resolution)",
             texture2D(GL_R16F), 1},
            {"gtao.bent_normal", OutputKind::Vector,
             "GTAO's bent normal (gtao.bent_normals on): the cosine-weighted mean unoccluded direction, a unit "
             "view-space vector in xyz, 0 on the sky (RGBA16F, at gtao.resolution, not denoised)",
             texture2D(GL_RGBA16F), 3}};
}

bool GtaoMethod::allocates(const OutputDecl& output, const KnobRegistry& knobs) const {
    if (output.name == "gtao.bent_normal") return knobs.get(bentNormals_);
    return knobs.get(denoise_) == edgeAware_;
}

ResourceDesc GtaoMethod::resource(const OutputDecl& output, const KnobRegistry& knobs) const {
    ResourceDesc d = output.resource;
    d.shift = resolutionShift(knobs);
    return d;
}

float GtaoMethod::worldRadius(const KnobRegistry& knobs, const Bounds& bounds) const {
    const float r = knobs.get(radius_);
    return knobs.choice(radiusUnit_) == "world" ? r : r * static_cast<float>(sceneLengthUnit(bounds));
}

void GtaoMethod::setup(gl::ShaderLibrary& shaders) {
    program_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "ao/gtao.frag"});
    denoiseProgram_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "ao/gtao_denoise.frag"});
    linearDepth_ = gl::Sampler::create(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, "gtao linear depth");
    params_.create();
}

void GtaoMethod::run(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    const gl::Texture& raw = ctx.texture("ao.raw");
    gpu::GtaoParams p{};
    p.aoSize = {raw.width(), raw.height()};
    p.shift = resolutionShift(k);
    p.slices = k.get(slices_);
    p.steps = k.get(steps_);
    p.radius = worldRadius(k, ctx.gpu.bounds());
    p.falloff = k.get(falloff_);
    p.thickness = k.get(thickness_);
    p.thinOccluders = k.get(thinOccluders_);
    // Full-resolution pixels per view-space unit at depth 1: half the
    // viewport's height times the projection's y scale.
    p.pixelScale = 0.5f * static_cast<float>(ctx.height) * ctx.camera.projection[1][1];
    p.minPixels = 1.3f;  // XeGTAO's "pixel too close" threshold: never the pixel itself
    // Edge-aware denoise: a neighbour 2% of the depth off the tangent plane weighs 1/e.
    p.denoisePlane = 0.02f;
    const bool bent = k.get(bentNormals_);
    p.bentNormals = bent ? 1 : 0;
    params_.upload(p, binding::PASS_UBO);
    ctx.texture("gbuffer.depth").bind(binding::GTAO_DEPTH_TEXTURE);
    linearDepth_.bind(binding::GTAO_DEPTH_TEXTURE);  // samples between pixel centres (see gtao.frag)
    ctx.texture("gbuffer.normal").bind(binding::GTAO_NORMAL_TEXTURE);
    glViewport(0, 0, p.aoSize.x, p.aoSize.y);
    const bool edgeAware = k.get(denoise_) == edgeAware_;
    // The bent normal, when asked for, is the first draw's second attachment.
    if (bent)
        (edgeAware ? bentNoisyTarget_.get(ctx, {"gtao.noisy", "gtao.bent_normal"}, {}, "GTAO noisy, bent normal")
                   : bentTarget_.get(ctx, {"ao.raw", "gtao.bent_normal"}, {}, "GTAO, bent normal"))
            .bind();
    else
        (edgeAware ? noisyTarget_.get(ctx, {"gtao.noisy"}, {}, "GTAO noisy") : target_.get(ctx, {"ao.raw"}, {}, "GTAO")).bind();
    program_->use();
    triangle_.draw();
    if (edgeAware) {
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        ctx.texture("gtao.noisy").bind(binding::GTAO_NOISY_TEXTURE);
        target_.get(ctx, {"ao.raw"}, {}, "GTAO").bind();
        denoiseProgram_->use();
        triangle_.draw();
    }
    char line[160];
    std::snprintf(line, sizeof line, "%d slices x %d steps per side at %dx%d, radius %.4g world units, %s denoise%s%s",
                  p.slices, p.steps, p.aoSize.x, p.aoSize.y, p.radius, k.choice(denoise_).c_str(),
                  bent ? ", bent normals" : "", k.get(multibounce_) ? ", multi-bounce in the lighting" : "");
    stats_ = line;
}

}  // namespace dw
