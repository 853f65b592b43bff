#include "renderer/inspect/FiniteCheck.h"

#include <cmath>

#include "renderer/inspect/OutputReadback.h"

namespace dw {

NonFiniteCount FiniteCheck::count(const FloatImage& image, const std::string& name) {
    NonFiniteCount c;
    c.buffer = name;
    c.values = static_cast<long long>(image.pixels.size());
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int ch = 0; ch < image.channels; ++ch) {
                const float v = image.at(x, y, ch);
                if (std::isfinite(v)) continue;
                if (std::isnan(v)) ++c.nan;
                else if (v > 0) ++c.positiveInf;
                else ++c.negativeInf;
                if (c.firstX < 0) {
                    c.firstX = x;
                    c.firstY = y;
                }
            }
    return c;
}

std::vector<NonFiniteCount> FiniteCheck::scan(const OutputRegistry& outputs) {
    std::vector<NonFiniteCount> out;
    for (const PublishedOutput& o : outputs.all()) {
        if (!o.producedThisFrame || !o.allocated()) continue;
        out.push_back(count(readOutputRaw(o), o.decl.name));
    }
    return out;
}

}  // namespace dw
