#include "renderer/ao/AoMethod.h"

namespace dw {

AoMethodCatalog& AoMethodCatalog::extra() {
    static AoMethodCatalog catalog;
    return catalog;
}

}  // namespace dw
