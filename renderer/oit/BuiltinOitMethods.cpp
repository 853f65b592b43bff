// The built-in OIT methods, one line each; the first is the default of oit.method.
#include "renderer/oit/DepthPeelingOit.h"
#include "renderer/oit/DualDepthPeelingOit.h"
#include "renderer/oit/LinkedListOit.h"
#include "renderer/oit/OitMethod.h"
#include "renderer/oit/SortedForwardOit.h"
#include "renderer/oit/StencilRoutedOit.h"
#include "renderer/oit/WeightedOit.h"

namespace dw {

namespace {
template <typename T>
OitMethodFactory make() {
    return [](KnobRegistry& knobs) { return std::make_unique<T>(knobs); };
}
}  // namespace

std::vector<OitMethodFactory> builtinOitMethods() {
    return {
        make<LinkedListOit>(),
        make<StencilRoutedOit>(),
        make<DepthPeelingOit>(),
        make<DualDepthPeelingOit>(),
        make<WeightedOit>(),
        make<SortedForwardOit>(),
    };
}

}  // namespace dw
