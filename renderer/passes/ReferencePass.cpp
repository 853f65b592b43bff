#include "renderer/passes/ReferencePass.h"
#include "renderer/gl/MemoryLedger.h"

#include <algorithm>
#include <cmath>

#include "renderer/knobs/KnobRegistry.h"

namespace dw {

namespace {

double luminance(const float* p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

// Rows top-down (files) to GL's bottom-up.
std::vector<float> flipped(const FloatImage& img) {
    std::vector<float> out(img.pixels.size());
    const size_t row = static_cast<size_t>(img.width) * img.channels;
    for (int y = 0; y < img.height; ++y)
        std::copy_n(&img.pixels[static_cast<size_t>(img.height - 1 - y) * row], row, &out[static_cast<size_t>(y) * row]);
    return out;
}

}  // namespace

ReferencePass::ReferencePass(KnobRegistry&) {}

std::vector<OutputDecl> ReferencePass::outputs() const {
    return {
        {"reference.lbuffer", OutputKind::HdrColor,
         "the CPU reference's L-buffer (renderer/reference: exact geometry, no light cut-off, shadows and AO by rays; "
         "RGBA32F)"},
        {"reference.final", OutputKind::Color,
         "the CPU reference's tone-mapped image (no bloom, depth of field or FXAA; sRGB-encoded values, RGBA32F)"},
        {"reference.ao", OutputKind::Scalar, "the CPU reference's ray-traced ambient accessibility (R32F)", {}, 1},
        {"reference.spp_error", OutputKind::Scalar,
         "the CPU reference's standard error of each pixel's luminance over its samples (reference --spp; 0 with one "
         "sample; R32F)",
         {}, 1},
        {"compare.error", OutputKind::Scalar,
         "this frame's lbuffer against reference.lbuffer: |L - L_ref| / (L_ref + 0.001) per pixel, L the luminance (R32F)",
         {}, 1},
    };
}

std::string ReferencePass::skipReason(const KnobRegistry&, const Scene&) const {
    if (!images_) return stale_;
    // A reference of another size than the frame (the window resized since)
    // has nothing to show: skipped, so a frame asking for its outputs says
    // why instead of failing on an output never allocated.
    if (frameWidth_ > 0 && (images_->lbuffer.width != frameWidth_ || images_->lbuffer.height != frameHeight_))
        return sizeMismatch(frameWidth_, frameHeight_);
    return {};
}

std::string ReferencePass::sizeMismatch(int width, int height) const {
    return "the reference is " + std::to_string(images_->lbuffer.width) + "x" + std::to_string(images_->lbuffer.height) +
           ", the frame " + std::to_string(width) + "x" + std::to_string(height) + ": render the reference again";
}

void ReferencePass::setReference(std::shared_ptr<const Images> images, std::string staleReason) {
    images_ = std::move(images);
    if (!staleReason.empty()) stale_ = std::move(staleReason);
    uploaded_ = false;
    measuredGeneration_ = ~0ull;
    if (!images_) stats_.clear();
}

float ReferencePass::relativeError(float l, float ref) {
    return static_cast<float>(std::abs(static_cast<double>(l) - ref) / (static_cast<double>(ref) + 1e-3));
}

void ReferencePass::resize(int width, int height, OutputRegistry& outputs) {
    frameWidth_ = width;
    frameHeight_ = height;
    if (uploaded_) bindAll(outputs);
}

void ReferencePass::bindAll(OutputRegistry& outputs) {
    outputs.bind("reference.lbuffer", &lbuffer_, 4);
    outputs.bind("reference.final", &final_, 4);
    outputs.bind("reference.ao", &ao_, 1);
    outputs.bind("reference.spp_error", &sppError_, 1);
    outputs.bind("compare.error", &error_, 1);
}

void ReferencePass::upload() {
    const Images& r = *images_;
    const int w = r.lbuffer.width, h = r.lbuffer.height;
    gl::MemoryOwner owner("reference images");
    auto make = [&](gl::Texture& t, GLenum format, const FloatImage& img, GLenum layout) {
        t = gl::Texture::create2D(format, w, h);
        if (img.width == w && img.height == h) t.upload(0, w, h, layout, GL_FLOAT, flipped(img).data());
    };
    make(lbuffer_, GL_RGBA32F, r.lbuffer, GL_RGBA);
    make(final_, GL_RGBA32F, r.final, GL_RGBA);
    make(ao_, GL_R32F, r.ao, GL_RED);
    make(sppError_, GL_R32F, r.sppError, GL_RED);
    error_ = gl::Texture::create2D(GL_R32F, w, h);
    uploaded_ = true;
}

void ReferencePass::execute(FrameContext& ctx) {
    if (!images_) return;
    const int w = ctx.camera.viewport.x, h = ctx.camera.viewport.y;
    if (images_->lbuffer.width != w || images_->lbuffer.height != h) {
        stats_ = sizeMismatch(w, h);
        return;
    }
    if (!uploaded_) {
        upload();
        bindAll(ctx.outputs);
    }
    // Measure again only when the frame can have changed (knobs or camera):
    // a read-back of the L-buffer per frame would cost a static view nothing.
    if (ctx.knobs.generation() != measuredGeneration_ || ctx.camera.view != measuredView_) {
        measuredGeneration_ = ctx.knobs.generation();
        measuredView_ = ctx.camera.view;
        const std::vector<float> frame = ctx.texture("lbuffer").readFloats(0, GL_RGBA, 4);  // bottom-up
        const FloatImage& ref = images_->lbuffer;
        std::vector<float> error(static_cast<size_t>(w) * h);
        double sumAbs = 0, sumSq = 0, sumRel = 0, maxAbs = 0;
        Errors e;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t gl = static_cast<size_t>(y) * w + x;
                const size_t top = static_cast<size_t>(h - 1 - y) * w + x;
                const double lf = luminance(&frame[gl * 4]), lr = luminance(&ref.pixels[top * ref.channels]);
                const double d = std::isfinite(lf) ? std::abs(lf - lr) : 0.0;
                sumAbs += d;
                sumSq += d * d;
                error[gl] = relativeError(static_cast<float>(lf), static_cast<float>(lr));
                sumRel += error[gl];
                if (d > maxAbs) {
                    maxAbs = d;
                    e.maxX = x;
                    e.maxY = h - 1 - y;
                }
            }
        const double n = static_cast<double>(w) * h;
        e.meanAbsolute = sumAbs / n;
        e.rms = std::sqrt(sumSq / n);
        e.max = maxAbs;
        e.meanRelative = sumRel / n;
        e.psnr = e.rms > 0 ? 20.0 * std::log10(1.0 / e.rms) : INFINITY;
        errors_ = e;
        error_.upload(0, w, h, GL_RED, GL_FLOAT, error.data());
        char line[320];
        std::snprintf(line, sizeof line,
                      "lbuffer vs %s: luminance mean |d| %.3g, RMS %.3g (PSNR %.1f dB at peak 1), max %.3g at (%d, %d), "
                      "mean relative %.3g (compare.error); FLIP and SSIM: deferred-workbench compare --against reference",
                      images_->describe.c_str(), e.meanAbsolute, e.rms, e.psnr, e.max, e.maxX, e.maxY, e.meanRelative);
        stats_ = line;
    }
}

}  // namespace dw
