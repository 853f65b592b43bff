#pragma once
// Sampler object: sampling state for one texture unit that overrides the
// texture's own, so a pass can filter a shared texture (G-buffer depth, the
// tone-mapped image) linearly without changing how every other pass reads it.
// resetPipelineState unbinds samplers from the units passes use.
#include "renderer/gl/GlObject.h"

namespace dw::gl {

class Sampler {
public:
    Sampler() = default;
    static Sampler create(GLenum minFilter, GLenum magFilter, GLenum wrap, const char* label = nullptr);
    // Different wrap modes along S and T (glTF samplers).
    static Sampler create(GLenum minFilter, GLenum magFilter, GLenum wrapS, GLenum wrapT, const char* label);
    // Depth comparison (sampler*Shadow), bilinear over the comparisons, and
    // outside the map the border depth 1 (lit): how shadow maps are read, so
    // the maps themselves stay plain depth textures anyone can view.
    static Sampler createDepthCompare(const char* label = nullptr);

    GLuint id() const { return name_.id(); }
    explicit operator bool() const { return static_cast<bool>(name_); }
    void bind(int unit) const;
    static void unbind(int unit);
    // Units 0 .. kResetUnits-1 are unbound by resetPipelineState.
    static constexpr int kResetUnits = 16;

private:
    GlObject<SamplerTraits> name_;
};

}  // namespace dw::gl
