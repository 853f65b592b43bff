#include "renderer/graph/PassCatalog.h"

namespace dw {

PassCatalog& PassCatalog::extra() {
    static PassCatalog catalog;
    return catalog;
}

const char* toString(PassStage stage) {
    switch (stage) {
        case PassStage::GBuffer: return "gbuffer";
        case PassStage::Screen: return "screen";
        case PassStage::Lights: return "lights";
        case PassStage::Lighting: return "lighting";
        case PassStage::Hdr: return "hdr";
        case PassStage::Tonemap: return "tonemap";
        case PassStage::Post: return "post";
    }
    return "?";
}

}  // namespace dw
