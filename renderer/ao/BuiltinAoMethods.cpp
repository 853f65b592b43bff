// The built-in AO methods, one line each; the first is the default of ao.method.
#include "renderer/ao/AoMethod.h"
#include "renderer/ao/AovMethod.h"
#include "renderer/ao/GtaoMethod.h"
#include "renderer/ao/SsaoMethod.h"

namespace dw {

namespace {
template <typename T>
AoMethodFactory make() {
    return [](KnobRegistry& knobs) { return std::make_unique<T>(knobs); };
}
}  // namespace

std::vector<AoMethodFactory> builtinAoMethods() {
    return {
        make<SsaoMethod>(),
        make<GtaoMethod>(),
        make<AovMethod>(),
    };
}

}  // namespace dw
