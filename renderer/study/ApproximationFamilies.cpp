#include "renderer/study/ApproximationFamilies.h"

namespace dw {

const std::vector<ApproximationFamily>& approximationFamilies() {
    static const std::vector<ApproximationFamily> families = {
        {"shadows", "shadow maps: resolution, PCF, a point light's cube or paraboloids (the reference traces hard shadows)",
         {"shadows.map_size=2048", "shadows.pcf_radius=0", "shadows.point_method=cube"}},
        {"ao", "screen-space AO: the method's samples, slices, steps and buffer size (the reference traces AO rays)",
         {"ssao.samples=64", "ssao.resolution=full", "gtao.slices=16", "gtao.steps=32", "gtao.resolution=full",
          "aov.resolution=full"}},
        {"light_cutoff", "lights cut where their intensity falls under lighting.threshold, and the strategy that finds their pixels",
         {"lighting.threshold=1e-05", "lighting.strategy=fullscreen"}},
        {"gbuffer", "G-buffer encodings: material bytes, normal encoding, depth format",
         {"gbuffer.material_format=unorm16", "gbuffer.normal_encoding=oct16", "gbuffer.depth_format=float32"}},
        {"texture_filter", "texture filtering (mipmap, aniso2..aniso16) against the reference's base-level lookups at the pixel centre",
         {"gbuffer.texture_filter=base_level"}},
        {"transparency", "order-independent transparency: the method and its budget",
         {"oit.method=linked_list"}},
        {"bloom", "bloom (not in the reference's model)", {"bloom.enabled=false"}},
        {"dof", "depth of field (not in the reference's model)", {"dof.enabled=false"}},
        {"aa", "anti-aliasing, aa.method (FXAA by default; not in the reference's model)", {"aa.method=none"}},
    };
    return families;
}

}  // namespace dw
