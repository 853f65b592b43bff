// The built-in AO methods, one line each; the first is the default of ao.method.
#include "renderer/ao/AoMethod.h"
#include "renderer/ao/AovMethod.h"
#include "renderer/ao/GtaoMethod.h"
#include "renderer/ao/SsaoMethod.h"

namespace dw {

std::vector<AoMethodFactory> builtinAoMethods() {
    return {
        makeMethod<AoMethod, SsaoMethod>(),
        makeMethod<AoMethod, GtaoMethod>(),
        makeMethod<AoMethod, AovMethod>(),
    };
}

}  // namespace dw
