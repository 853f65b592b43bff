#include "renderer/lighting/LightTable.h"

#include <algorithm>
#include <cmath>

namespace dw {

void LightTable::uploadRow(int row) const {
    buffer->update(static_cast<std::size_t>(row) * sizeof(LightGpu), sizeof(LightGpu), &rows[row]);
}

float coneRampScale(const Light& light) {
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    const double span = std::cos(light.innerConeDegrees * kDegree) - std::cos(light.cutoffDegrees * kDegree);
    return span > 1e-30 ? static_cast<float>(std::min(1.0 / span, 1e30)) : 1e30f;
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
