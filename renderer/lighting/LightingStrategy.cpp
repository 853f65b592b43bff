#include "renderer/lighting/LightingStrategy.h"

#include "renderer/lighting/LightVolume.h"

namespace dw {

void LightShading::setup(gl::ShaderLibrary& shaders) {
    fullscreen_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/light.frag"});
    volume_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag"});
    fullscreenCounting_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/light.frag", .defines = {"COUNT_OVERLAP"}});
    volumeCounting_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag", .defines = {"COUNT_OVERLAP"}});
    stencil_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/stencil.frag"});
    sphere_.create(unitSphereVolume());
    cone_.create(unitConeVolume());
}

LightingStrategyCatalog& LightingStrategyCatalog::extra() {
    static LightingStrategyCatalog catalog;
    return catalog;
}

}  // namespace dw
