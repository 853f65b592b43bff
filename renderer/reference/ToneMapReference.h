#pragma once
// The tone mapping of shaders/tonemap/tonemap.frag in double precision, on a
// whole L-buffer, with its statistics (log-average and maximum luminance,
// seed 000 eq. 4.2 and section 5.3.1) computed exactly over the image rather
// than by the GPU's reduction. Bloom is not applied (the reference does not
// model it). The result has the GPU final image's encoding (sRGB when
// tonemap.srgb is on), unquantised: RGBA in [0, 1], alpha 1.
#include <cstdint>
#include <vector>

#include "renderer/io/ImageIO.h"
#include "renderer/reference/ReferenceModel.h"

namespace dw::reference {

// `background`: one byte per pixel, non-zero where no geometry is (left out
// of the statistics when the model says luminance.background = exclude);
// may be empty. Rows as in `lbuffer` (3 or 4 channels).
FloatImage toneMap(const FloatImage& lbuffer, const std::vector<std::uint8_t>& background, const ReferenceModel& model);

// One pixel, given the statistics: the operator's output before the sRGB curve.
struct ToneStatistics {
    double logAverage = 1.0;
    double maxLuminance = 0.0;
    bool measured = false;  // at least one finite pixel with luminance above 0
};
ToneStatistics toneStatistics(const FloatImage& lbuffer, const std::vector<std::uint8_t>& background,
                              const ReferenceModel& model);
glm::dvec3 toneMapPixel(glm::dvec3 hdr, const ToneStatistics& stats, const ReferenceModel& model);

}  // namespace dw::reference
