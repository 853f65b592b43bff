#include "renderer/gl/Sampler.h"

#include "renderer/Error.h"

namespace dw::gl {

Sampler Sampler::create(GLenum minFilter, GLenum magFilter, GLenum wrap, const char* label) {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    if (id == 0) throw Error("glCreateSamplers failed");
    Sampler s;
    s.name_ = GlObject<SamplerTraits>(id);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
    for (GLenum p : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) glSamplerParameteri(id, p, static_cast<GLint>(wrap));
    if (label) glObjectLabel(GL_SAMPLER, id, -1, label);
    return s;
}

Sampler Sampler::create(GLenum minFilter, GLenum magFilter, GLenum wrapS, GLenum wrapT, const char* label) {
    Sampler s = create(minFilter, magFilter, wrapS, label);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrapT));
    return s;
}

Sampler Sampler::createDepthCompare(const char* label) {
    Sampler s = create(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_BORDER, label);
    const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glSamplerParameterfv(s.id(), GL_TEXTURE_BORDER_COLOR, border);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    return s;
}

void Sampler::bind(int unit) const { glBindSampler(static_cast<GLuint>(unit), id()); }
void Sampler::unbind(int unit) { glBindSampler(static_cast<GLuint>(unit), 0); }

}  // namespace dw::gl
