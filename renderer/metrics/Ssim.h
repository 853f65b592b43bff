#pragma once
// The structural similarity index (Wang, Bovik, Sheikh, Simoncelli, "Image
// Quality Assessment: From Error Visibility to Structural Similarity", IEEE
// TIP 13(4), 2004), written from the paper with the choices scikit-image's
// structural_similarity makes for gaussian_weights=True, sigma=1.5,
// use_sample_covariance=False, data_range given, channel_axis=-1:
//   - local statistics under a Gaussian window, sigma 1.5, truncated at 3.5
//     sigma (radius int(3.5 * 1.5 + 0.5) = 5: an 11 x 11 window, weights
//     normalised to sum 1), applied separably; outside the image the values
//     are mirrored about the edge (scipy.ndimage "reflect": d c b a | a b c d);
//   - population (co)variances: sigma_x^2 = G*(x^2) - (G*x)^2 and so on;
//   - C1 = (K1 L)^2, C2 = (K2 L)^2 with K1 = 0.01, K2 = 0.03, L = data range;
//   - SSIM(x, y) = (2 mu_x mu_y + C1)(2 sigma_xy + C2) /
//                  ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 + C2)) per pixel;
//   - each channel's index is the mean of its map over the interior, a border
//     of (window - 1) / 2 = 5 pixels left out on every side (as skimage crops);
//     the image's index is the mean of the channels' indices.
// Everything in double precision.
//
// Shapes: both images width x height x channels, interleaved, rows top-down,
// at least 11 x 11. The map has the same shape: one SSIM per pixel and
// channel, over the whole image (the border included, as skimage's full=True).
// Units: SSIM is dimensionless, 1 for identical images, at most 1.
// Errors: Error when the shapes differ or the image is smaller than the window.
//
// The values are compared as given: the caller chooses the encoding (8-bit
// files: their stored values / 255; an HDR buffer: see SsimEncoding).
#include <vector>

#include "renderer/io/ImageIO.h"

namespace dw {

// How an HDR (linear radiance) buffer is brought into [0, 1] for SSIM, whose
// constants C1, C2 assume a known data range.
enum class SsimEncoding {
    AsStored,  // the values as they are (8-bit files: stored value / 255), data range as given
    Reinhard,  // per channel max(v, 0) / (1 + max(v, 0)): monotone, [0, 1), data range 1
};
const char* ssimEncodingName(SsimEncoding e);

struct SsimParameters {
    double dataRange = 1.0;
    double sigma = 1.5;
    double truncate = 3.5;  // the window's radius in sigmas (skimage's value for gaussian_weights=True)
    double k1 = 0.01, k2 = 0.03;
};

struct SsimResult {
    double mean = 1.0;                // the mean of perChannel
    std::vector<double> perChannel;   // each channel's mean over the interior
    FloatImage map;                   // per pixel and channel, same shape as the inputs
};

class Ssim {
public:
    static SsimResult compute(const FloatImage& a, const FloatImage& b, const SsimParameters& parameters = {});
    // `image` encoded as `encoding` says (a copy).
    static FloatImage encode(const FloatImage& image, SsimEncoding encoding);
    // The window's radius: int(truncate * sigma + 0.5).
    static int windowRadius(const SsimParameters& parameters);
};

}  // namespace dw
