#pragma once
// What the device offers, queried once per process and visible wherever a
// pass declares a resource (RenderPass::resource runs with a context
// current): a pass sizes its multisample targets by what the driver
// supports for the formats it uses, not by GL_MAX_SAMPLES alone.
#include <initializer_list>

#include "renderer/gl/GlObject.h"

namespace dw::gl {

// The largest sample count glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE,
// format, GL_SAMPLES) lists for every one of `formats` (the smallest of their
// maxima), at least 1. Cached per format.
int maxMultisampleSamples(std::initializer_list<GLenum> formats);

}  // namespace dw::gl
