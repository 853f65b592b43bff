#pragma once
// Deferred MSAA (aa.method=msaa; Lauritzen 2010, "Deferred rendering for
// current and future rendering pipelines", SIGGRAPH course): the geometry
// pass draws the opaque scene into the ordinary G-buffer as under every
// other method (the pixel centres) and again into a multisampled one
// (gbuffer.ms.albedo, .normal, .specular, .emissive, .occlusion, .depth, and
// .directional with lighting.directional_in_gbuffer: the ordinary formats,
// aa.samples samples each). This pass writes the edge mask aa.edges (R8,
// the output size): 1 where a pixel's samples disagree by kEdgeRule, 0
// elsewhere. The lighting pass shades the ordinary G-buffer at every pixel,
// then each sample s = 0..N-1 of the edge pixels alone through the same
// lighting strategy (MsaaSampleCopy writes sample s into the G-buffer with
// every other pixel background, so light volumes, tiles and clusters pass
// them by), and box-resolves the HDR radiance (MsaaResolve): an edge
// pixel's L-buffer is the mean of its N samples' radiance, before tone
// mapping. A strategy that does not shade from the G-buffer (forward)
// shades per pixel only, said. aa.samples (2, 4, 8, 16; default 4) is
// capped by the device (deviceCap), said in stats() and frameWarning().
// docs/antialiasing.md.
#include <string>
#include <vector>

#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/knobs/KnobRegistry.h"

namespace dw {

inline constexpr const char* kAaSamplesKnob = "aa.samples";

// The edge rule, as the docs and `list buffers` give it.
inline constexpr const char* kEdgeRule =
    "a pixel is an edge when any sample differs from sample 0 in coverage (surface against background), in view-space "
    "depth by more than 1% of the nearer one's, in normal by more than 20 degrees, or in material (albedo, specular "
    "colour or exponent by more than 2/255, emission by more than 2%)";

class MsaaPass : public RenderPass {
public:
    // The edge rule's thresholds (shaders/gbuffer/msaa_edges.frag).
    static constexpr float kRelativeDepth = 0.01f;
    static constexpr float kNormalDegrees = 20.0f;
    // The largest sample count the device offers for every format the
    // multisampled G-buffer can take (glGetInternalformativ, DeviceLimits),
    // GL_MAX_SAMPLES, GL_MAX_COLOR_TEXTURE_SAMPLES and
    // GL_MAX_DEPTH_TEXTURE_SAMPLES (no attachment is an integer format, so
    // GL_MAX_INTEGER_SAMPLES does not bound it). Needs a current context.
    static int deviceCap();
    // aa.samples capped by deviceCap(); the requested value before the cap.
    static int samples(const KnobRegistry& knobs);
    static int requestedSamples(const KnobRegistry& knobs);
    // The pixels of an R8 edge mask that are 1 (a read-back).
    static long long countEdges(const gl::Texture& edges, int width, int height);

    explicit MsaaPass(KnobRegistry& knobs);
    const char* name() const override { return "msaa"; }
    std::vector<OutputDecl> outputs() const override;
    PassIO inputs(const KnobRegistry& knobs) const override;
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }
    std::string frameWarning() const override { return warning_; }

private:

    EnumKnob method_;
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    TargetFramebuffer target_;
    std::string stats_, warning_;
};

// The multisampled G-buffer's outputs (written by the geometry pass), in the
// order of MsaaSampleCopy's draw buffers.
inline const char* const kMsaaGBuffer[] = {"gbuffer.ms.albedo", "gbuffer.ms.normal", "gbuffer.ms.specular",
                                           "gbuffer.ms.emissive", "gbuffer.ms.occlusion"};
inline constexpr const char* kMsaaDepth = "gbuffer.ms.depth";
inline constexpr const char* kMsaaDirectional = "gbuffer.ms.directional";

// Writes sample `sample` of the multisampled G-buffer into the ordinary
// G-buffer (gbuffer.albedo ... gbuffer.depth, and gbuffer.directional when
// `directional`) on the pixels aa.edges marks, every other pixel background
// (albedo 0 with pixel type 0, far depth, stencil 0), which every lighting
// strategy passes by. save() keeps a copy of the ordinary G-buffer (pass-owned
// textures of its formats) and restore() puts it back.
class MsaaSampleCopy {
public:
    void setup(gl::ShaderLibrary& shaders);
    void copy(const FrameContext& ctx, int sample, bool directional);
    void save(const FrameContext& ctx, bool directional);
    void restore(const FrameContext& ctx, bool directional);

private:
    gl::ShaderLibrary::Handle program_, directionalProgram_;
    gl::FullscreenTriangle triangle_;
    TargetFramebuffer target_, directionalTarget_;
    std::vector<gl::Texture> saved_;
    std::vector<GLenum> savedFormats_;
    int savedWidth_ = 0, savedHeight_ = 0;
};

// The box resolve of the shaded radiance: begin() takes the L-buffer (the
// pixel centres' shading) on the pixels that are not edges and 0 on edge
// pixels, add() adds the L-buffer with weight 1/N on edge pixels, finish()
// writes the sum back to lbuffer. A pass-owned RGBA32F sum at the frame size.
class MsaaResolve {
public:
    void setup(gl::ShaderLibrary& shaders);
    void begin(const FrameContext& ctx, int samples) { accumulate(ctx, samples, true); }
    void add(const FrameContext& ctx, int samples) { accumulate(ctx, samples, false); }
    void finish(const FrameContext& ctx);

private:
    void accumulate(const FrameContext& ctx, int samples, bool first);
    gl::ShaderLibrary::Handle program_;
    gl::FullscreenTriangle triangle_;
    gl::Texture sum_;
    gl::Framebuffer sumTarget_;
    int width_ = 0, height_ = 0;
};

}  // namespace dw
