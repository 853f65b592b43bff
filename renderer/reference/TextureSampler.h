#pragma once
// Texture lookups of the CPU reference: bilinear filtering at the base level
// (the reference does not model mip-mapping or anisotropic filtering, which
// are approximations of the pixel's footprint), with the glTF sampler's wrap
// modes and KHR_texture_transform, sRGB textures decoded to linear per texel
// before filtering as the GPU's GL_SRGB8_ALPHA8 textures are.
// Image rows are top-down (dw::Image), and v = 0 is the first row, as glTF's
// texture coordinates and the GPU upload have it.
#include <glm/glm.hpp>

#include "renderer/io/Image.h"
#include "renderer/scene/Material.h"

namespace dw::reference {

// RGBA in [0, 1] (linear when `srgb`) at texture coordinate `uv` (after the
// mapping's transform has been applied: see transformUv).
glm::dvec4 sampleBilinear(const Image& image, const TextureMapping& mapping, const glm::dvec2& uv, bool srgb);
// The mapping's KHR_texture_transform applied to `uv`.
glm::dvec2 transformUv(const TextureMapping& mapping, const glm::dvec2& uv);
// The sRGB transfer curve's inverse (IEC 61966-2-1).
double srgbToLinear(double c);
double linearToSrgb(double c);

}  // namespace dw::reference
