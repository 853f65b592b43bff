#pragma once
// Ambient occlusion (issue 22; seed 000 sections 4.6.3-4.6.4 and 5.6-5.7):
// runs the method ao.method names (renderer/ao/AoMethod.h: ssao, gtao, ...)
// on the G-buffer. Reads what the method reads (gbuffer.depth and
// gbuffer.normal for the screen-space ones); writes ao.raw, the ambient
// accessibility (1 = open) at the method's resolution, and the method's own
// outputs. The shared filter (AoFilterPass) turns ao.raw into ao.filtered.
// Skipped when ao.enabled is off or the scene has no ambient light.
#include <memory>
#include <optional>
#include <vector>

#include "renderer/ao/AoMethod.h"
#include "renderer/graph/MethodSet.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/knobs/KnobRegistry.h"

namespace dw {

class AoPass : public RenderPass {
public:
    explicit AoPass(KnobRegistry& knobs);
    ~AoPass() override;
    const char* name() const override { return "ao"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry& knobs) const override;
    ResourceDesc resource(const OutputDecl& output, const KnobRegistry& knobs) const override;
    bool allocates(const OutputDecl& output, const KnobRegistry& knobs) const override;
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

    const std::vector<std::unique_ptr<AoMethod>>& methods() const { return methods_->all(); }
    // The method ao.method names under `knobs`.
    const AoMethod& method(const KnobRegistry& knobs) const;
    // Every method's, by name (null when none is called so).
    template <typename T>
    T* method() const {
        for (const auto& m : methods_->all())
            if (auto* t = dynamic_cast<T*>(m.get())) return t;
        return nullptr;
    }

private:
    std::optional<MethodSet<AoMethod>> methods_;  // ao.method's (made after ao.enabled: the knobs' order)
    BoolKnob enabled_;
    std::string stats_;
};

}  // namespace dw
