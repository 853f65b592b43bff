#pragma once
// The CPU reference of the view as outputs the inspector, probe and viewer
// show like any other (issue "Ground truth and error metrics", in the
// workbench): reference.lbuffer, reference.final, reference.ao, and
// compare.error, the per-pixel error of this frame's lbuffer against the
// reference's. Reads lbuffer; writes those four (imported textures, uploaded
// when a reference arrives). The reference itself is rendered on the CPU in
// the background (renderer/reference/ReferenceJob) and handed over with
// setReference; this pass only shows it and measures the frame against it.
// Skipped while there is no reference of the current view, or while the
// reference's size is not the frame's (after a resize, until withdrawn).
#include <memory>

#include "renderer/graph/RenderPass.h"
#include "renderer/gl/Texture.h"
#include "renderer/io/ImageIO.h"

namespace dw {

class ReferencePass : public RenderPass {
public:
    // What the workbench hands over: W x H images, rows top-down (ReferenceImages' buffers).
    struct Images {
        FloatImage lbuffer, final, ao;
        FloatImage sppError;  // 1 channel: the standard error of each pixel's luminance over its samples (0: one sample)
        std::string describe;  // "CPU reference, 64 AO rays (standard error 0.009)"
    };
    explicit ReferencePass(KnobRegistry& knobs);
    const char* name() const override { return "reference"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry&) const override { return {{"lbuffer"}, {}, {}}; }
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary&) override {}
    void resize(int width, int height, OutputRegistry& outputs) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

    // nullptr clears it (the view changed); `staleReason` is then the skip reason shown.
    void setReference(std::shared_ptr<const Images> images, std::string staleReason = {});
    bool hasReference() const { return images_ != nullptr; }
    // The images handed over (nullptr when none): what the outputs show, on the CPU.
    const Images* reference() const { return images_.get(); }

    // The frame's error against the reference (L-buffer luminance), as the statistics line states it.
    struct Errors {
        double meanAbsolute = 0, rms = 0, max = 0, meanRelative = 0, psnr = 0;
        int maxX = 0, maxY = 0;
    };
    const Errors& errors() const { return errors_; }
    // The per-pixel error of compare.error: |L - L_ref| / (L_ref + 0.001), L the luminance.
    static float relativeError(float luminance, float referenceLuminance);

private:
    void upload();
    // "the reference is WxH, the frame wxh: render the reference again"
    std::string sizeMismatch(int width, int height) const;
    void bindAll(OutputRegistry& outputs);
    std::shared_ptr<const Images> images_;
    std::string stale_ = "no CPU reference of this view yet (Render > CPU reference of this view)";
    bool uploaded_ = false;
    gl::Texture lbuffer_, final_, ao_, sppError_, error_;
    Errors errors_;
    std::uint64_t measuredGeneration_ = ~0ull;
    glm::mat4 measuredView_{0.0f};
    std::string stats_;
    int frameWidth_ = 0, frameHeight_ = 0;  // the pipeline's size (resize), 0 before the first
};

}  // namespace dw
