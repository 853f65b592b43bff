// The built-in lighting strategies, one line each; the first is the default
// of lighting.strategy.
#include "renderer/lighting/ClusteredStrategy.h"
#include "renderer/lighting/ForwardStrategy.h"
#include "renderer/lighting/FullscreenStrategy.h"
#include "renderer/lighting/LightingStrategy.h"
#include "renderer/lighting/StencilVolumesStrategy.h"
#include "renderer/lighting/TiledStrategy.h"
#include "renderer/lighting/VolumesStrategy.h"

namespace dw {

std::vector<LightingStrategyFactory> builtinLightingStrategies() {
    return {
        makeMethod<LightingStrategy, StencilVolumesStrategy>(),
        makeMethod<LightingStrategy, VolumesStrategy>(),
        makeMethod<LightingStrategy, FullscreenStrategy>(),
        makeMethod<LightingStrategy, TiledStrategy>(),
        makeMethod<LightingStrategy, ClusteredStrategy>(),
        makeMethod<LightingStrategy, ForwardStrategy>(),
        makeMethod<LightingStrategy, ForwardMultipassStrategy>(),
    };
}

}  // namespace dw
