#include "renderer/passes/OitPass.h"

#include <glm/glm.hpp>
#include <set>

#include "renderer/Error.h"
#include "renderer/graph/ViewFrustum.h"
#include "renderer/lighting/LightTable.h"
#include "renderer/lighting/ShadowService.h"
#include "renderer/scene/GpuScene.h"
#include "renderer/scene/Scene.h"

namespace dw {

namespace {

// Whether the instance's box can be seen: not wholly outside one of the
// side planes or behind the eye (a conservative test: it only saves draws).
bool boxInView(const Bounds& b, const glm::dmat4& worldToClip) {
    if (b.empty()) return false;
    int outside[5] = {0, 0, 0, 0, 0};
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 p((c & 1) ? b.max.x : b.min.x, (c & 2) ? b.max.y : b.min.y, (c & 4) ? b.max.z : b.min.z);
        const glm::dvec4 q = worldToClip * glm::dvec4(p, 1.0);
        outside[0] += q.x < -q.w;
        outside[1] += q.x > q.w;
        outside[2] += q.y < -q.w;
        outside[3] += q.y > q.w;
        outside[4] += q.w <= 0.0;
    }
    for (int k = 0; k < 5; ++k)
        if (outside[k] == 8) return false;
    return true;
}

}  // namespace

OitPass::OitPass(KnobRegistry& knobs) {
    enabled_ = knobs.addBool("oit.enabled", true, "oit",
                             "draw the blended materials (off: they are left out of the frame, seed 002 table 1's "
                             "presets without SR)");
    methods_.emplace(knobs, builtinOitMethods(),
                     MethodKnob{"oit.method", "oit", "how the blended materials are composited over the L-buffer:", {}, true});
}

OitPass::~OitPass() = default;

void OitPass::connect(const KnobRegistry& knobs) {
    attenuation_ = knobs.requireEnum("lighting.attenuation");
    windowed_ = knobs.choiceIndex(attenuation_, "windowed");
    windowExponent_ = knobs.requireFloat("lighting.window_exponent");
    ambientSpecular_ = knobs.requireBool("lighting.ambient_specular");
}

std::vector<OutputDecl> OitPass::outputs() const {
    std::vector<OutputDecl> out = {
        {"oit.sample_count", OutputKind::Count,
         "transparent fragments that reached the pixel in front of the opaque surface, stored or lost (= stored + "
         "oit.overflow; R32UI)",
         texture2D(GL_R32UI), 1},
        {"oit.overflow", OutputKind::Count,
         "transparent fragments lost per pixel: past the A-buffer's samples, past (or at exactly the depth of) the "
         "peeled layers, or past the list's budget, its 32 nearest or its walk's bound; the frame's total is warned "
         "about (R32UI)",
         texture2D(GL_R32UI), 1},
    };
    methods_->appendOutputs(out);
    return out;
}

ResourceDesc OitPass::resource(const OutputDecl& output, const KnobRegistry& knobs) const {
    const OitMethod* m = methods_->ownerOf(output.name);
    return m ? m->resource(output, knobs) : output.resource;
}

bool OitPass::allocates(const OutputDecl& output, const KnobRegistry& knobs) const {
    const OitMethod* m = methods_->ownerOf(output.name);
    return !m || m == methods_->picked(knobs);
}

PassIO OitPass::inputs(const KnobRegistry& knobs) const {
    (void)knobs;
    PassIO io;
    io.inputs = {"gbuffer.depth", "lights.table", "lbuffer.depth"};
    io.modifies = {"lbuffer"};
    return io;
}

std::string OitPass::skipReason(const KnobRegistry& knobs, const Scene& scene) const {
    if (!knobs.get(enabled_)) return "switched off (oit.enabled = false)";
    for (const auto& inst : scene.instances) {
        if (inst.mesh < 0 || static_cast<std::size_t>(inst.mesh) >= scene.meshes.size()) continue;
        const int mat = scene.meshes[static_cast<std::size_t>(inst.mesh)].material;
        if (mat >= 0 && static_cast<std::size_t>(mat) < scene.materials.size() &&
            scene.materials[static_cast<std::size_t>(mat)].alphaMode == AlphaMode::Blend)
            return {};
    }
    return "no blended material in the scene";
}

std::string OitPass::viewSkipReason(const KnobRegistry&, const Scene& scene, const CameraUniforms& camera) const {
    const ViewFrustum frustum(camera.worldToClip());
    for (const auto& inst : scene.instances) {
        if (inst.mesh < 0 || static_cast<std::size_t>(inst.mesh) >= scene.meshes.size()) continue;
        const Mesh& mesh = scene.meshes[static_cast<std::size_t>(inst.mesh)];
        if (mesh.material < 0 || static_cast<std::size_t>(mesh.material) >= scene.materials.size() ||
            scene.materials[static_cast<std::size_t>(mesh.material)].alphaMode != AlphaMode::Blend)
            continue;
        const Bounds b = mesh.bounds.transformed(inst.transform);
        if (b.empty() || !frustum.sphereOutside(glm::dvec3(b.center()), static_cast<double>(b.radius())))
            return {};
    }
    return "no blended material in view";
}

void OitPass::setup(gl::ShaderLibrary& shaders) {
    shaders_ = &shaders;
    methods_->setup(shaders);
    lighting_.create();
    params_.create();
    lostTotal_ = gl::Buffer::create(2 * sizeof(std::uint32_t), nullptr, true, "oit lost fragments");
}

const gl::Program& OitPass::transparentProgram(const std::string& method, bool shadowed) {
    std::vector<std::string> defines{method};
    if (shadowed) defines.emplace_back("OIT_SHADOWED");
    // The library caches programs by description.
    return *shaders_->get({.vertex = "geometry.vert", .fragment = "oit/transparent.frag", .defines = defines});
}

void OitPass::readLostTotal(const OitMethod& method) {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::uint32_t totals[2] = {0, 0};
    lostTotal_.read(0, sizeof totals, totals);
    lastLost_ = totals[0];
    lastArrived_ = totals[1];
    if (lastLost_ == 0) return;
    warning_ = "lost " + std::to_string(lastLost_) + " of " + std::to_string(lastArrived_) +
               " transparent fragments this frame (" + method.lossCause() + "); oit.overflow shows where";
}

void OitPass::execute(FrameContext& ctx) {
    const KnobRegistry& k = ctx.knobs;
    OitMethod& method = *methods_->picked(k);
    methods_->refuseOthersOutputs(method, ctx.wanted);
    if (!ctx.lightTable) throw Error("the oit pass ran without a light table (the lights pass did not run)");
    const LightTable& table = *ctx.lightTable;

    const gl::Texture& count = ctx.texture("oit.sample_count");
    const gl::Texture& overflow = ctx.texture("oit.overflow");
    count.clearUint(0);
    overflow.clearUint(0);
    warning_.clear();
    lastLost_ = lastArrived_ = 0;
    lostTotal_.clearUint(0);
    lostTotal_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::OIT_LOST_TOTAL_SSBO);

    OitFrame f{ctx};
    const glm::dmat4 worldToClip = ctx.camera.worldToClip();
    const auto& draws = ctx.gpu.draws();
    for (std::size_t i = 0; i < draws.size(); ++i)
        if (draws[i].alphaMode == AlphaMode::Blend && boxInView(draws[i].bounds, worldToClip)) f.draws.push_back(i);
    lastDraws_ = f.draws.size();
    if (f.draws.empty()) {
        stats_ = std::string(method.name()) + ": no blended material in view";
        return;
    }
    f.shadowed = ctx.shadows && ctx.shadows->everyMapKept();

    gpu::LightingParams lp{};
    lp.windowed = k.get(attenuation_) == windowed_ ? 1 : 0;
    lp.windowExponent = k.get(windowExponent_);
    lp.ambientSpecular = k.get(ambientSpecular_) ? 1 : 0;
    lp.ambient = glm::vec4(ctx.scene.ambient, 0.0f);
    lp.background = glm::vec4(ctx.scene.background, 0.0f);
    lighting_.upload(lp, binding::PASS_UBO);

    f.params.samples = 1;
    f.params.nodeBudget = 0;
    f.params.weightFunction = 7;
    f.params.countFragments = method.needsFragmentCount() || ctx.wants("oit.sample_count") ? 1 : 0;
    f.params.lightCount = static_cast<int>(table.rows.size());
    f.params.peelLayer = 0;
    f.uploadParams = [&] { params_.upload(f.params, binding::OIT_UBO); };
    f.uploadParams();

    ctx.texture("gbuffer.depth").bind(binding::GBUFFER_DEPTH_TEXTURE);
    table.buffer->bindBase(GL_SHADER_STORAGE_BUFFER, binding::LIGHT_SSBO);
    if (f.shadowed) ctx.shadows->bind();
    count.bindImage(binding::OIT_FRAGMENT_COUNT_IMAGE, GL_READ_WRITE);
    overflow.bindImage(binding::OIT_OVERFLOW_IMAGE, GL_READ_WRITE);

    f.transparentProgram = [&](const std::string& m) -> const gl::Program& { return transparentProgram(m, f.shadowed); };
    f.compositeOverLBuffer = [&](const gl::Program& program) {
        gl::Framebuffer& fbo = composite_.get(ctx, {"lbuffer"}, {}, "oit composite");
        fbo.bind();
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_ONE, GL_SRC_ALPHA, GL_ZERO, GL_ONE);
        params_.bind(binding::OIT_UBO);
        program.use();
        triangle_.draw();
        glDisable(GL_BLEND);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    };
    method.render(f);
    readLostTotal(method);
    // The method's own outputs and the overflow are written every frame, so
    // the probe and the inspector can read them although nothing asked for
    // them; the count only when it was counted.
    std::set<std::string> written{"oit.overflow"};
    if (f.params.countFragments != 0 || method.needsFragmentCount()) written.insert("oit.sample_count");
    for (const auto& o : method.outputs()) written.insert(o.name);
    ctx.outputs.markProduced(name(), written);
    stats_ = std::string(method.name()) + ": " + std::to_string(f.draws.size()) + " blended draws, " +
             (f.shadowed ? "shadowed" : ctx.shadows ? "unshadowed (shadow maps reused: shadows.reuse_map)" : "no shadow maps") +
             "; " + method.stats();
}

}  // namespace dw
