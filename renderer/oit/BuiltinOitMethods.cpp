// The built-in OIT methods, one line each; the first is the default of oit.method.
#include "renderer/oit/DepthPeelingOit.h"
#include "renderer/oit/DualDepthPeelingOit.h"
#include "renderer/oit/LinkedListOit.h"
#include "renderer/oit/OitMethod.h"
#include "renderer/oit/SortedForwardOit.h"
#include "renderer/oit/StencilRoutedOit.h"
#include "renderer/oit/WeightedOit.h"

namespace dw {

std::vector<OitMethodFactory> builtinOitMethods() {
    return {
        makeMethod<OitMethod, LinkedListOit>(),
        makeMethod<OitMethod, StencilRoutedOit>(),
        makeMethod<OitMethod, DepthPeelingOit>(),
        makeMethod<OitMethod, DualDepthPeelingOit>(),
        makeMethod<OitMethod, WeightedOit>(),
        makeMethod<OitMethod, SortedForwardOit>(),
    };
}

}  // namespace dw
