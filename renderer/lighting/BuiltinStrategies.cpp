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

namespace {
template <typename T>
LightingStrategyFactory make() {
    return [](KnobRegistry& knobs) { return std::make_unique<T>(knobs); };
}
}  // namespace

std::vector<LightingStrategyFactory> builtinLightingStrategies() {
    return {
        make<StencilVolumesStrategy>(),
        make<VolumesStrategy>(),
        make<FullscreenStrategy>(),
        make<TiledStrategy>(),
        make<ClusteredStrategy>(),
        make<ForwardStrategy>(),
        make<ForwardMultipassStrategy>(),
    };
}

}  // namespace dw
