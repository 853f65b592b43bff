// Google's Turbo colour map (Mikhailov 2019, the polynomial approximation),
// shared by the buffer view's heat map (GLSL) and the workbench's colour bar
// (C++), so the bar shows exactly the colours of the image.
#ifndef DW_BUFFERVIEW_TURBO_H
#define DW_BUFFERVIEW_TURBO_H

#ifdef __cplusplus
// Angle brackets: the GLSL include resolver takes only "quoted" includes.
#include <glm/glm.hpp>
namespace dw::gpu {
using glm::clamp;
using glm::dot;
using glm::vec2;
using glm::vec3;
using glm::vec4;
#define DW_SHARED_FN inline
#else
#define DW_SHARED_FN
#endif

// t in [0, 1] (clamped) -> linear RGB.
DW_SHARED_FN vec3 turbo(float t) {
    t = clamp(t, 0.0f, 1.0f);
    const vec4 kr = vec4(0.13572138f, 4.61539260f, -42.66032258f, 132.13108234f);
    const vec4 kg = vec4(0.09140261f, 2.19418839f, 4.84296658f, -14.18503333f);
    const vec4 kb = vec4(0.10667330f, 12.64194608f, -60.58204836f, 110.36276771f);
    const vec2 kr2 = vec2(-152.94239396f, 59.28637943f);
    const vec2 kg2 = vec2(4.27729857f, 2.82956604f);
    const vec2 kb2 = vec2(-89.90310912f, 27.34824973f);
    vec4 v4 = vec4(1.0f, t, t * t, t * t * t);
    vec2 v2 = vec2(v4.z, v4.w) * v4.z;
    return vec3(dot(v4, kr) + dot(v2, kr2), dot(v4, kg) + dot(v2, kg2), dot(v4, kb) + dot(v2, kb2));
}

#ifdef __cplusplus
}  // namespace dw::gpu
#endif
#undef DW_SHARED_FN

#endif
