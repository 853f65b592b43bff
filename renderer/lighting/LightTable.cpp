#include "renderer/lighting/LightTable.h"

namespace dw {

void LightTable::uploadRow(int row) const {
    buffer->update(static_cast<std::size_t>(row) * sizeof(LightGpu), sizeof(LightGpu), &rows[row]);
}

}  // namespace dw
