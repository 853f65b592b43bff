#include "renderer/lighting/LightingStrategy.h"

#include "renderer/lighting/LightVolume.h"

namespace dw {

void LightShading::setup(gl::ShaderLibrary& shaders, const std::vector<std::string>& defines) {
    std::vector<std::string> counting = defines;
    counting.push_back("COUNT_OVERLAP");
    fullscreen_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/light.frag", .defines = defines});
    volume_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag", .defines = defines});
    fullscreenCounting_ = shaders.get({.vertex = "fullscreen.vert", .fragment = "lighting/light.frag", .defines = counting});
    volumeCounting_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/light.frag", .defines = counting});
    stencil_ = shaders.get({.vertex = "lighting/volume.vert", .fragment = "lighting/stencil.frag"});
    sphere_.create(unitSphereVolume());
    cone_.create(unitConeVolume());
}

LightingStrategyCatalog& LightingStrategyCatalog::extra() {
    static LightingStrategyCatalog catalog;
    return catalog;
}

}  // namespace dw
