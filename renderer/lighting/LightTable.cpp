#include "renderer/lighting/LightTable.h"

namespace dw {

void LightTable::uploadRow(int row) const {
    buffer->update(static_cast<std::size_t>(row) * sizeof(LightGpu), sizeof(LightGpu), &rows[row]);
}

std::vector<int> gbufferDirectionalRows(const LightTable& table, bool shadows) {
    std::vector<int> rows;
    for (const LightTableEntry& e : table.entries)
        if (e.light->type == LightType::Directional && !(shadows && e.shadowed) &&
            static_cast<int>(rows.size()) < kMaxGBufferDirectional)
            rows.push_back(e.row);
    return rows;
}

}  // namespace dw
