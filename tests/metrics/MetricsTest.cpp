// The image metrics (renderer/metrics/): OpenImageIO's statistics, SSIM
// against scikit-image, FLIP against values worked out by hand, the gates,
// the heat map and the refusal of non-finite pixels. CPU only.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>

#include "renderer/Error.h"
#include "renderer/io/ImageIO.h"
#include "renderer/metrics/ComparisonGates.h"
#include "renderer/metrics/DifferenceStatistics.h"
#include "renderer/metrics/FinitePixels.h"
#include "renderer/metrics/Flip.h"
#include "renderer/metrics/HeatMap.h"
#include "renderer/metrics/ImageComparison.h"
#include "renderer/metrics/Ssim.h"
#include "shaders/bufferview/turbo.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

FloatImage flat(int w, int h, int channels, float value) {
    FloatImage img;
    img.width = w;
    img.height = h;
    img.channels = channels;
    img.pixels.assign(static_cast<size_t>(w) * h * channels, value);
    return img;
}

FloatImage noise(int w, int h, int channels, unsigned seed) {
    FloatImage img = flat(w, h, channels, 0.0f);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (float& v : img.pixels) v = u(rng);
    return img;
}

fs::path tempDir() {
    const fs::path p = fs::temp_directory_path() / ("dw-metrics-tests-" + std::to_string(::getpid()));
    fs::create_directories(p);
    return p;
}

// The interpreter with Debian's python3-skimage (scripts/setup-deps.sh --tests).
std::string python() { return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3"; }

bool haveSkimage() {
    static const bool have =
        std::system((python() + " -c 'import skimage.metrics' >/dev/null 2>&1").c_str()) == 0;
    return have;
}

void writeRaw(const fs::path& path, const FloatImage& img) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(img.pixels.data()),
               static_cast<std::streamsize>(img.pixels.size() * sizeof(float)));
}

// scikit-image's structural_similarity on the same float32 values (as float64),
// Wang et al.'s settings; prints the mean, then the full map's values at `probes`.
struct SkimageSsim {
    double mean = 0;
    std::vector<double> probes;
};
SkimageSsim skimageSsim(const FloatImage& a, const FloatImage& b, const std::vector<size_t>& probes) {
    const fs::path dir = tempDir();
    writeRaw(dir / "a.raw", a);
    writeRaw(dir / "b.raw", b);
    std::ofstream script(dir / "ssim.py");
    script << "import numpy as np\n"
              "from skimage.metrics import structural_similarity\n"
              "shape = (" << a.height << ", " << a.width << ", " << a.channels << ")\n"
              "a = np.fromfile('" << (dir / "a.raw").string() << "', dtype=np.float32).astype(np.float64).reshape(shape)\n"
              "b = np.fromfile('" << (dir / "b.raw").string() << "', dtype=np.float32).astype(np.float64).reshape(shape)\n"
              "m, s = structural_similarity(a, b, gaussian_weights=True, sigma=1.5, use_sample_covariance=False,\n"
              "                             data_range=1.0, channel_axis=-1, full=True)\n"
              "print(repr(float(m)))\n"
              "flat = s.reshape(-1)\n";
    for (size_t p : probes) script << "print(repr(float(flat[" << p << "])))\n";
    script.close();
    const fs::path out = dir / "ssim.txt";
    const std::string cmd = python() + " " + (dir / "ssim.py").string() + " > " + out.string() + " 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream in(out);
    SkimageSsim r;
    in >> r.mean;
    for (size_t i = 0; i < probes.size(); ++i) {
        double v = 0;
        in >> v;
        r.probes.push_back(v);
    }
    return r;
}

void expectSsimMatchesSkimage(const FloatImage& a, const FloatImage& b) {
    const SsimResult ours = Ssim::compute(a, b);
    // Corners, edges and the interior of the full map.
    const size_t n = ours.map.pixels.size();
    const std::vector<size_t> probes = {0, 1, 7, n / 3, n / 2 + 5, n - 1, n - 40};
    const SkimageSsim theirs = skimageSsim(a, b, probes);
    EXPECT_NEAR(ours.mean, theirs.mean, 1e-4);
    EXPECT_NEAR(ours.mean, theirs.mean, 1e-9) << "(double precision on both sides: far closer than the 1e-4 asked)";
    for (size_t i = 0; i < probes.size(); ++i)
        EXPECT_NEAR(ours.map.pixels[probes[i]], theirs.probes[i], 1e-5) << "map value " << probes[i];
}

}  // namespace

// ---- OpenImageIO's statistics --------------------------------------------

TEST(DifferenceStatistics, OneChangedValue) {
    // 8 x 4 x 3 zeros; one value (pixel (5, 2), channel 1) 0.5.
    const FloatImage a = flat(8, 4, 3, 0.0f);
    FloatImage b = a;
    b.at(5, 2, 1) = 0.5f;
    const DifferenceStatistics s = DifferenceStatistics::measure(a, b, 0.1, 0.4);
    EXPECT_EQ(s.pixelCount, 32);
    EXPECT_NEAR(s.overall.mean, 0.5 / 96.0, 1e-9);               // over all 96 values
    EXPECT_NEAR(s.overall.rms, std::sqrt(0.25 / 96.0), 1e-7);
    EXPECT_NEAR(s.overall.psnr, 20.0 * std::log10(1.0 / std::sqrt(0.25 / 96.0)), 1e-4);
    EXPECT_DOUBLE_EQ(s.overall.max, 0.5);
    EXPECT_EQ(s.overall.maxX, 5);
    EXPECT_EQ(s.overall.maxY, 2);
    EXPECT_EQ(s.overall.maxChannel, 1);
    EXPECT_EQ(s.overall.failCount, 1);
    EXPECT_EQ(s.overall.warnCount, 1);
    ASSERT_EQ(s.perChannel.size(), 3u);
    EXPECT_DOUBLE_EQ(s.perChannel[0].max, 0.0);
    EXPECT_EQ(s.perChannel[0].failCount, 0);
    EXPECT_NEAR(s.perChannel[1].mean, 0.5 / 32.0, 1e-9);         // over that channel's 32 values
    EXPECT_EQ(s.perChannel[1].failCount, 1);
    EXPECT_EQ(s.perChannel[1].maxX, 5);
}

TEST(DifferenceStatistics, IdenticalImagesHaveInfinitePsnr) {
    const FloatImage a = noise(16, 16, 3, 1);
    const DifferenceStatistics s = DifferenceStatistics::measure(a, a, 1e-6, 1e-6);
    EXPECT_EQ(s.overall.max, 0.0);
    EXPECT_EQ(s.overall.failCount, 0);
    EXPECT_TRUE(std::isinf(s.overall.psnr));
}

TEST(DifferenceStatistics, ShapesMustMatch) {
    try {
        DifferenceStatistics::measure(flat(8, 4, 3, 0), flat(8, 5, 3, 0), 0, 0);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("8x4x3 vs 8x5x3"), std::string::npos) << e.what();
    }
}

// ---- non-finite input ----------------------------------------------------

TEST(FinitePixels, NamesTheImageAndTheFirstBadPixel) {
    FloatImage a = flat(6, 4, 3, 0.25f);
    a.at(3, 2, 1) = std::nanf("");
    a.at(4, 3, 0) = INFINITY;
    try {
        FinitePixels::require(a, "render.exr");
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "render.exr: pixel (3, 2) channel 1 is NaN (2 non-finite values in all); metrics need "
                               "finite pixels");
    }
    EXPECT_NO_THROW(FinitePixels::require(flat(2, 2, 1, 1.0f), "ok"));
    // ImageComparison refuses before measuring.
    EXPECT_THROW(ImageComparison::measure(flat(6, 4, 3, 0.25f), a, {}), Error);
}

// ---- SSIM ----------------------------------------------------------------

TEST(Ssim, IdenticalImagesScoreOne) {
    const FloatImage a = noise(20, 16, 3, 7);
    const SsimResult r = Ssim::compute(a, a);
    EXPECT_DOUBLE_EQ(r.mean, 1.0);
    for (float v : r.map.pixels) EXPECT_NEAR(v, 1.0, 1e-6);
    EXPECT_EQ(Ssim::windowRadius({}), 5);  // int(3.5 * 1.5 + 0.5): the 11 x 11 window
}

TEST(Ssim, RefusesImagesSmallerThanItsWindow) {
    EXPECT_THROW(Ssim::compute(flat(10, 30, 1, 0), flat(10, 30, 1, 0)), Error);
}

TEST(Ssim, MatchesScikitImageOnRandomImages) {
    if (!haveSkimage()) GTEST_SKIP() << "python3-skimage not installed (scripts/setup-deps.sh --tests)";
    // Independent noise (SSIM near 0), and a noisy copy (SSIM in between).
    expectSsimMatchesSkimage(noise(37, 23, 3, 1), noise(37, 23, 3, 2));
    FloatImage a = noise(40, 30, 3, 3), b = a;
    std::mt19937 rng(4);
    std::normal_distribution<float> n(0.0f, 0.05f);
    for (float& v : b.pixels) v += n(rng);
    expectSsimMatchesSkimage(a, b);
    // One channel; an image narrower than twice the window (reflection repeats).
    expectSsimMatchesSkimage(noise(12, 11, 1, 5), noise(12, 11, 1, 6));
}

TEST(Ssim, MatchesScikitImageOnANaturalImage) {
    if (!haveSkimage()) GTEST_SKIP() << "python3-skimage not installed (scripts/setup-deps.sh --tests)";
    // A rendered frame (the golden image of the default scene) against a
    // blurred and brightened copy: smooth regions, edges and texture.
    const FloatImage src = loadImageFloat(std::string(DW_TEST_GOLDEN_DIR) + "/default.png");
    FloatImage a;
    a.width = 160;
    a.height = 90;
    a.channels = 3;
    a.pixels.resize(160 * 90 * 3);
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 160; ++x)
            for (int c = 0; c < 3; ++c) a.at(x, y, c) = src.at(x * src.width / 160, y * src.height / 90, c);
    FloatImage b = a;
    for (int y = 0; y < 90; ++y)
        for (int x = 0; x < 160; ++x)
            for (int c = 0; c < 3; ++c)
                b.at(x, y, c) = 0.5f * a.at(x, y, c) + 0.25f * a.at(std::max(x - 1, 0), y, c) +
                                0.25f * a.at(std::min(x + 1, 159), y, c) + 0.03f;
    expectSsimMatchesSkimage(a, b);
}

TEST(Ssim, ReinhardEncodingForHdr) {
    FloatImage hdr = flat(1, 1, 3, 0.0f);
    hdr.pixels = {3.0f, -1.0f, 0.0f};
    const FloatImage e = Ssim::encode(hdr, SsimEncoding::Reinhard);
    EXPECT_FLOAT_EQ(e.pixels[0], 0.75f);  // 3 / (1 + 3)
    EXPECT_FLOAT_EQ(e.pixels[1], 0.0f);   // negative: clamped to 0 first
    EXPECT_FLOAT_EQ(e.pixels[2], 0.0f);
}

// ---- FLIP ----------------------------------------------------------------

TEST(Flip, DefaultPixelsPerDegree) {
    // 0.7 m * (3840 px / 0.7 m) * pi / 180 = 67.0206 pixels per degree.
    EXPECT_NEAR(Flip::defaultPixelsPerDegree(), 67.0206, 1e-4);
}

TEST(Flip, IdenticalImagesAreZero) {
    const FloatImage a = noise(32, 24, 3, 11);
    const FlipResult l = Flip::ldr(a, a);
    EXPECT_EQ(l.mean, 0.0);
    for (float v : l.map.pixels) EXPECT_EQ(v, 0.0f);
    FloatImage hdr = a;
    for (float& v : hdr.pixels) v *= 20.0f;
    const FlipResult h = Flip::hdr(hdr, hdr);
    EXPECT_EQ(h.mean, 0.0);
    EXPECT_TRUE(h.hdr);
    EXPECT_GE(h.exposureCount, 2);
}

// A flat colour difference, worked out by hand. On uniform images the CSF
// filters (normalised to sum 1) leave every value as it is, and the edge and
// point filters (weights summing to 0) give 0, so the feature difference is 0
// and FLIP = the mapped colour difference at every pixel.
//   Hunt-adjusted CIELAB (D65, white = XYZ of linear RGB (1,1,1)):
//     green (0,1,0): L 87.7355, a' -75.6114, b' 72.9842
//     blue  (0,0,1): L 32.3009, a' 25.5809, b' -34.8383
//     HyAB = |87.7355 - 32.3009| + hypot(101.1923, 107.8225) = 203.3047
//     cmax = 203.3047^0.7 = 41.27654, pc * cmax = 0.4 * 41.27654 = 16.51062
//   black vs white: L 0 vs 100, a = b = 0: HyAB 100, 100^0.7 = 25.11886 > 16.51062,
//     FLIP = 0.95 + (25.11886 - 16.51062) / (41.27654 - 16.51062) * 0.05 = 0.967379
//   black vs sRGB grey 0.5 (linear 0.214041, L 53.38896): 53.38896^0.7 = 16.18885 < 16.51062,
//     FLIP = 16.18885 * 0.95 / 16.51062 = 0.931486
TEST(Flip, FlatColourDifferenceByHand) {
    const FlipResult bw = Flip::ldr(flat(24, 16, 3, 0.0f), flat(24, 16, 3, 1.0f));
    EXPECT_NEAR(bw.mean, 0.967379, 1e-5);
    for (float v : bw.map.pixels) EXPECT_NEAR(v, 0.967379, 1e-5);
    const FlipResult grey = Flip::ldr(flat(24, 16, 3, 0.0f), flat(24, 16, 3, 0.5f));
    EXPECT_NEAR(grey.mean, 0.931486, 1e-5);
    // Grey images (1 channel) are RGB with R = G = B.
    EXPECT_NEAR(Flip::ldr(flat(24, 16, 1, 0.0f), flat(24, 16, 1, 0.5f)).mean, 0.931486, 1e-5);
}

// HDR-FLIP of flat grey radiance 1 (reference) against 2 (test), by hand.
//   ACES fit f(x) = (0.9036 x^2 + 0.018 x) / (0.8748 x^2 + 0.354 x + 0.14);
//   f(x_t) = 0.85 at x_t = 2.118872 (the positive root of
//   0.16002 x^2 - 0.2829 x - 0.119 = 0).
//   Y_max = Y_median = 1: start = stop = log2(2.118872) = 1.083289 stops, 2 exposures.
//   Reference: f(2.118872) = 0.85, L = 93.88312; test: f(4.237745) = 0.939674, L = 97.61883.
//   HyAB 3.73572, ^0.7 = 2.515718 < 16.51062: FLIP = 2.515718 * 0.95 / 16.51062 = 0.144751.
TEST(Flip, HdrFlatRadianceByHand) {
    const FlipResult r = Flip::hdr(flat(24, 16, 3, 1.0f), flat(24, 16, 3, 2.0f));
    EXPECT_NEAR(r.startExposure, 1.083289, 1e-5);
    EXPECT_NEAR(r.stopExposure, 1.083289, 1e-5);
    EXPECT_EQ(r.exposureCount, 2);
    EXPECT_NEAR(Flip::acesToneMap(2.118872), 0.85, 1e-6);
    EXPECT_NEAR(r.mean, 0.144751, 1e-5);
}

// HDR-FLIP's exposure range on a reference with a spread of luminance:
// start from its brightest pixel, stop from its median.
TEST(Flip, HdrExposureRangeFromTheReference) {
    FloatImage ref = flat(4, 4, 3, 0.0f);
    for (int i = 0; i < 16; ++i)
        for (int c = 0; c < 3; ++c) ref.pixels[static_cast<size_t>(i) * 3 + c] = static_cast<float>(i + 1);
    // Grey: luminance = value; max 16, median (element 8 of 16 sorted) 9.
    const FlipResult r = Flip::hdr(ref, ref);
    EXPECT_NEAR(r.startExposure, std::log2(2.118872 / 16.0), 1e-5);
    EXPECT_NEAR(r.stopExposure, std::log2(2.118872 / 9.0), 1e-5);
    EXPECT_EQ(r.exposureCount, 2);  // max(2, ceil(log2(16 / 9) = 0.83))
}

// A black reference, and one mostly black (median 0): finite exposures, a
// finite map (the authors' code would stop at log2(x_t / 0) = infinity).
TEST(Flip, HdrDarkReferencesStayFinite) {
    const FlipResult black = Flip::hdr(flat(16, 16, 3, 0.0f), flat(16, 16, 3, 0.5f));
    EXPECT_NEAR(black.startExposure, std::log2(2.118872), 1e-5);  // taken as luminance 1
    EXPECT_EQ(black.startExposure, black.stopExposure);
    EXPECT_GT(black.mean, 0.0);
    FloatImage sparse = flat(16, 16, 3, 0.0f);
    for (int c = 0; c < 3; ++c) {
        sparse.at(2, 2, c) = 4.0f;
        sparse.at(9, 9, c) = 0.25f;
    }
    const FlipResult r = Flip::hdr(sparse, flat(16, 16, 3, 0.0f));
    EXPECT_NEAR(r.startExposure, std::log2(2.118872 / 4.0), 1e-5);
    EXPECT_NEAR(r.stopExposure, std::log2(2.118872 / 0.25), 1e-5);  // the dimmest lit pixel
    EXPECT_EQ(r.exposureCount, 4);
    for (float v : r.map.pixels) EXPECT_TRUE(std::isfinite(v));
}

// An edge moved by one pixel: FLIP is high at the edge, 0 far from it (beyond
// the filters' reach), and a larger move is worse.
TEST(Flip, AShiftedEdgeIsSeenOnlyNearIt) {
    auto edge = [](int at) {
        FloatImage img = flat(64, 8, 3, 0.0f);
        for (int y = 0; y < 8; ++y)
            for (int x = at; x < 64; ++x)
                for (int c = 0; c < 3; ++c) img.at(x, y, c) = 1.0f;
        return img;
    };
    const FlipResult one = Flip::ldr(edge(32), edge(33));
    const FlipResult four = Flip::ldr(edge(32), edge(36));
    EXPECT_GT(one.map.pixels[(4 * 64 + 32) * 1], 0.3f);
    EXPECT_EQ(one.map.pixels[4 * 64 + 0], 0.0f);
    EXPECT_EQ(one.map.pixels[4 * 64 + 63], 0.0f);
    EXPECT_GT(four.mean, one.mean);
}

// ---- the comparison, its maps and its gates -------------------------------

TEST(ImageComparison, ErrorMapChannels) {
    const FloatImage a = noise(16, 12, 4, 21), b = noise(16, 12, 4, 22);
    const ImageComparison c = ImageComparison::measure(a, b, {});
    std::vector<std::string> names;
    const FloatImage map = c.errorMap(names);
    const std::vector<std::string> expected = {"absdiff.R", "absdiff.G", "absdiff.B", "absdiff.A", "ssim", "flip"};
    EXPECT_EQ(names, expected);
    EXPECT_EQ(map.channels, 6);
    EXPECT_FLOAT_EQ(map.at(3, 5, 3), std::fabs(a.at(3, 5, 3) - b.at(3, 5, 3)));
    EXPECT_FLOAT_EQ(map.at(3, 5, 5), c.flip->map.at(3, 5, 0));
    // SSIM and FLIP read RGB only: 3 SSIM channels.
    EXPECT_EQ(c.ssim->perChannel.size(), 3u);
    // Too small for SSIM: absent, and said.
    const ImageComparison tiny = ImageComparison::measure(flat(4, 4, 3, 0), flat(4, 4, 3, 1), {});
    EXPECT_FALSE(tiny.ssim);
    ASSERT_EQ(tiny.notes.size(), 1u);
}

TEST(ComparisonGates, IdiffRules) {
    // 20 x 20 pixels; 3 pixels differ by 0.2, 5 more by 0.02.
    const FloatImage a = flat(20, 20, 3, 0.5f);
    FloatImage b = a;
    for (int i = 0; i < 3; ++i) b.at(i, 0, 0) = 0.7f;
    for (int i = 0; i < 5; ++i) b.at(i, 5, 2) = 0.52f;
    ComparisonSettings s;
    s.warnThreshold = 0.01;
    s.failThreshold = 0.1;
    const ImageComparison c = ImageComparison::measure(a, b, s);
    EXPECT_EQ(c.difference.overall.failCount, 3);
    EXPECT_EQ(c.difference.overall.warnCount, 8);
    std::vector<std::string> why;
    ComparisonGates g;
    EXPECT_EQ(g.judge(c, why), Verdict::Fail);  // 3 > 0% of 400
    g.failPercent = 0.75;                        // 3 > 0.75% of 400 = 3 is false: not a failure
    EXPECT_EQ(g.judge(c, why), Verdict::Warn);   // 8 > 0%
    g.failPercent = 0.7;                         // 3 > 2.8: a failure again
    EXPECT_EQ(g.judge(c, why), Verdict::Fail);
    g.failPercent = 0.75;
    g.warnPercent = 2;                           // 8 > 8 is false
    EXPECT_EQ(g.judge(c, why), Verdict::Pass);
    g.hardFail = 0.15;                           // 0.2 > 0.15
    EXPECT_EQ(g.judge(c, why), Verdict::Fail);
    g.hardFail = INFINITY;
    g.failSsim = 0.9999;                         // SSIM below it
    EXPECT_EQ(g.judge(c, why), Verdict::Fail);
    ASSERT_EQ(why.size(), 1u);
    EXPECT_NE(why[0].find("is below 0.9999"), std::string::npos) << why[0];
    g.failSsim.reset();
    g.failFlip = 0.0;                            // any FLIP above 0
    EXPECT_EQ(g.judge(c, why), Verdict::Fail);
}

TEST(HeatMap, TurboOverTheStatedRange) {
    FloatImage m = flat(3, 1, 1, 0.0f);
    m.pixels = {0.0f, 0.5f, 2.0f};
    const FloatImage h = HeatMap::colour(m, 0, 0.0, 1.0);
    ASSERT_EQ(h.channels, 3);
    const glm::vec3 lo = gpu::turbo(0.0f), mid = gpu::turbo(0.5f), hi = gpu::turbo(1.0f);
    EXPECT_NEAR(h.pixels[0], lo.r, 1e-6);
    EXPECT_NEAR(h.pixels[4], mid.g, 1e-6);
    EXPECT_NEAR(h.pixels[6], std::fmin(hi.r, 1.0f), 1e-6);  // 2.0 is clamped to the top
    EXPECT_THROW(HeatMap::colour(m, 1, 0.0, 1.0), Error);
}
