// The built-in passes, one line each, in seed 002 section 6's order within
// each stage: G-buffer (and MSAA's edge mask), ambient occlusion (ao: SSAO, GTAO, ...), L-buffer (the sky and the shadow maps feed
// it), transparency over the L-buffer (oit), the fire's flames added into it (flames), luminance statistics, bloom, tone mapping; then the
// post chain (depth of field, then the anti-aliasing method aa.method names:
// FXAA, SSAA's resolve or TAA, last) on the tone-mapped image.
#include "renderer/graph/PassCatalog.h"
#include "renderer/passes/AoFilterPass.h"
#include "renderer/passes/AoPass.h"
#include "renderer/passes/BloomPass.h"
#include "renderer/passes/DofPass.h"
#include "renderer/passes/FlamesPass.h"
#include "renderer/passes/FxaaPass.h"
#include "renderer/passes/GBufferDecodePass.h"
#include "renderer/passes/GeometryPass.h"
#include "renderer/passes/LightTablePass.h"
#include "renderer/passes/LightingPass.h"
#include "renderer/passes/ShadowPass.h"
#include "renderer/passes/LuminancePass.h"
#include "renderer/passes/MsaaPass.h"
#include "renderer/passes/OitPass.h"
#include "renderer/passes/ReferencePass.h"
#include "renderer/passes/SkyboxPass.h"
#include "renderer/passes/SsaaPass.h"
#include "renderer/passes/TaaPass.h"
#include "renderer/passes/TonemapPass.h"

namespace dw {

namespace {
template <typename T>
PassEntry entry(PassStage stage) {
    return {stage, [](KnobRegistry& knobs) { return std::make_unique<T>(knobs); }};
}
}  // namespace

std::vector<PassEntry> builtinPasses() {
    return {
        entry<GeometryPass>(PassStage::GBuffer),
        entry<GBufferDecodePass>(PassStage::GBuffer),
        entry<MsaaPass>(PassStage::GBuffer),
        entry<AoPass>(PassStage::Screen),
        entry<AoFilterPass>(PassStage::Screen),
        entry<SkyboxPass>(PassStage::Screen),
        entry<LightTablePass>(PassStage::Lights),
        entry<ShadowPass>(PassStage::Lights),
        entry<LightingPass>(PassStage::Lighting),
        entry<OitPass>(PassStage::Lighting),
        entry<FlamesPass>(PassStage::Lighting),
        entry<LuminancePass>(PassStage::Hdr),
        entry<BloomPass>(PassStage::Hdr),
        entry<ReferencePass>(PassStage::Hdr),
        entry<TonemapPass>(PassStage::Tonemap),
        entry<DofPass>(PassStage::Post),
        entry<FxaaPass>(PassStage::Post),
        entry<SsaaPass>(PassStage::Post),
        entry<TaaPass>(PassStage::Post),
    };
}

}  // namespace dw
