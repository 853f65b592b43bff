#include "renderer/passes/AoPass.h"

#include <set>

#include "renderer/Error.h"
#include "renderer/scene/Scene.h"

namespace dw {

AoPass::AoPass(KnobRegistry& knobs) {
    enabled_ = knobs.addBool("ao.enabled", true, "ao",
                             "ambient occlusion on the ambient term, by the method ao.method names (was ssao.enabled)");
    knobs.addAlias("ssao.enabled", "ao.enabled", "AO has several methods now, chosen by ao.method");
    methods_.emplace(knobs, builtinAoMethods(),
                     MethodKnob{"ao.method", "ao", "how the ambient occlusion ao.raw is computed:", {}, true});
}

AoPass::~AoPass() = default;

std::vector<OutputDecl> AoPass::outputs() const {
    std::vector<OutputDecl> out = {
        {"ao.raw", OutputKind::Scalar,
         "ambient accessibility before filtering, 1 = open (R16F, at the method's resolution)", texture2D(GL_R16F), 1},
    };
    methods_->appendOutputs(out);
    return out;
}

const AoMethod& AoPass::method(const KnobRegistry& knobs) const {
    return *methods_->picked(knobs);
}

ResourceDesc AoPass::resource(const OutputDecl& output, const KnobRegistry& knobs) const {
    if (const AoMethod* m = methods_->ownerOf(output.name)) return m->resource(output, knobs);
    ResourceDesc d = output.resource;
    d.shift = method(knobs).resolutionShift(knobs);
    return d;
}

bool AoPass::allocates(const OutputDecl& output, const KnobRegistry& knobs) const {
    const AoMethod* m = methods_->ownerOf(output.name);
    return !m || (m == &method(knobs) && m->allocates(output, knobs));
}

PassIO AoPass::inputs(const KnobRegistry& knobs) const {
    PassIO io;
    io.inputs = method(knobs).inputs(knobs);
    return io;
}

std::string AoPass::skipReason(const KnobRegistry& knobs, const Scene& scene) const {
    if (!knobs.get(enabled_)) return "switched off (ao.enabled = false)";
    if (scene.ambient == glm::vec3(0.0f)) return "the scene has no ambient light (AO only scales the ambient term)";
    return {};
}

void AoPass::setup(gl::ShaderLibrary& shaders) {
    methods_->setup(shaders);
}

void AoPass::execute(FrameContext& ctx) {
    AoMethod& chosen = *methods_->picked(ctx.knobs);
    methods_->refuseOthersOutputs(chosen, ctx.wanted);
    for (const auto& o : chosen.outputs())
        if (ctx.wants(o.name) && !chosen.allocates(o, ctx.knobs))
            throw Error(o.name + " is not written under the current knobs: " + o.description);
    chosen.run(ctx);
    ctx.aoMethod = &chosen;
    std::set<std::string> written{"ao.raw"};
    for (const auto& o : chosen.outputs())
        if (chosen.allocates(o, ctx.knobs)) written.insert(o.name);
    ctx.outputs.markProduced(name(), written);
    stats_ = std::string(chosen.name()) + ": " + chosen.stats();
}

}  // namespace dw
