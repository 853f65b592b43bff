// Each tone mapper against its formula on known values (seed 000 eqs. 4.1, 4.3, 4.4).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "renderer/scene/GpuScene.h"
#include "renderer/passes/BloomPass.h"
#include "renderer/graph/ResourcePool.h"
#include "renderer/passes/TonemapPass.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

double srgb(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}
double lum(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// Runs TonemapPass alone on given HDR pixels and luminance statistics.
class TonemapHarness {
public:
    explicit TonemapHarness(std::vector<glm::vec4> hdr) : hdr_(std::move(hdr)), bloom_(knobs_), pass_(knobs_) {
        test::initGl();
        shaders_ = std::make_unique<gl::ShaderLibrary>(gl::ShaderLibrary::locateRoot());
        outputs_.declare("lighting", {"lbuffer", OutputKind::HdrColor, ""});
        outputs_.declare("luminance", {"luminance.stats", OutputKind::Scalar, ""});
        outputs_.declare("tonemap", {"tonemap.result", OutputKind::Color, ""});
        const int w = static_cast<int>(hdr_.size());
        input_ = gl::Texture::create2D(GL_RGBA32F, w, 1);
        input_.upload(0, w, 1, GL_RGBA, GL_FLOAT, hdr_.data());
        stats_ = gl::Texture::create2D(GL_RGBA32F, 1, 1);
        outputs_.bind("lbuffer", &input_, 4);
        outputs_.bind("luminance.stats", &stats_, 4);
        pass_.connect(knobs_);
        pass_.setup(*shaders_);
        pool_.acquireOutputs(pass_, knobs_, w, 1, outputs_);
    }
    std::vector<glm::dvec3> run(glm::vec4 stats) {
        stats_.upload(0, 1, 1, GL_RGBA, GL_FLOAT, &stats);
        outputs_.markFrameStart();
        outputs_.markProduced("lighting");
        outputs_.markProduced("luminance");
        Scene scene;
        GpuScene gpu;
        const int w = static_cast<int>(hdr_.size());
        FrameContext ctx{scene, gpu, knobs_, outputs_, *shaders_, {}, w, 1, 0};
        gl::resetPipelineState(w, 1);
        pass_.execute(ctx);
        const auto bytes = outputs_.find("tonemap.result")->texture->readBytes(0, GL_RGBA, 4);
        std::vector<glm::dvec3> out;
        for (int i = 0; i < w; ++i) out.emplace_back(bytes[4 * i] / 255.0, bytes[4 * i + 1] / 255.0, bytes[4 * i + 2] / 255.0);
        return out;
    }
    KnobRegistry& knobs() { return knobs_; }
    const std::vector<glm::vec4>& hdr() const { return hdr_; }

private:
    std::vector<glm::vec4> hdr_;
    KnobRegistry knobs_;
    BloomPass bloom_;  // declares the bloom knobs the tone mapper reads
    TonemapPass pass_;
    std::unique_ptr<gl::ShaderLibrary> shaders_;
    OutputRegistry outputs_;
    ResourcePool pool_;
    gl::Texture input_, stats_;
};

const std::vector<glm::vec4> kInputs = {{0.0f, 0.0f, 0.0f, 1}, {0.05f, 0.05f, 0.05f, 1}, {0.18f, 0.18f, 0.18f, 1},
                                        {1.0f, 0.5f, 0.25f, 1}, {4.0f, 4.0f, 4.0f, 1},    {0.2f, 1.5f, 0.1f, 1},
                                        {30.0f, 10.0f, 2.0f, 1}, {0.5f, 0.5f, 2.0f, 1}};

void expectClose(const std::vector<glm::dvec3>& got, const std::vector<glm::dvec3>& want, const char* what) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[i][c], want[i][c], 1.0 / 255.0) << what << " pixel " << i << " channel " << c;
}

// Reference: map luminance, scale RGB by Ld / Lw, clamp, sRGB-encode.
std::vector<glm::dvec3> expected(const std::vector<glm::vec4>& in, double exposure,
                                 const std::function<double(double)>& op) {
    std::vector<glm::dvec3> out;
    for (const auto& p : in) {
        const glm::dvec3 hdr = glm::dvec3(p) * std::exp2(exposure);
        const double Lw = lum(hdr);
        const glm::dvec3 rgb = Lw > 0 ? hdr * (op(Lw) / Lw) : glm::dvec3(0.0);
        out.emplace_back(srgb(rgb.r), srgb(rgb.g), srgb(rgb.b));
    }
    return out;
}

}  // namespace

TEST(Tonemap, SimpleOperatorIsLOverOnePlusL) {
    TonemapHarness h(kInputs);
    h.knobs().setFromString("tonemap.operator", "simple");
    expectClose(h.run({1, 1, 1, 1}), expected(kInputs, 0.0, [](double L) { return L / (1.0 + L); }), "simple");
    h.knobs().setFromString("tonemap.exposure", "1.5");
    expectClose(h.run({1, 1, 1, 1}), expected(kInputs, 1.5, [](double L) { return L / (1.0 + L); }), "simple +1.5 EV");
}

TEST(Tonemap, ReinhardWithLogAverageAndAutomaticWhite) {
    TonemapHarness h(kInputs);
    const double logAvg = 0.37, maxL = 18.0, key = 0.18;
    const double scale = key / logAvg, white = scale * maxL;
    auto op = [&](double Lw) {
        const double L = scale * Lw;
        return L * (1.0 + L / (white * white)) / (1.0 + L);
    };
    expectClose(h.run({static_cast<float>(logAvg), static_cast<float>(maxL), 1, 100}), expected(kInputs, 0.0, op), "reinhard");
}

TEST(Tonemap, ReinhardWithManualWhiteAndKey) {
    TonemapHarness h(kInputs);
    h.knobs().setFromString("tonemap.auto_white", "false");
    h.knobs().setFromString("tonemap.white", "2.5");
    h.knobs().setFromString("tonemap.key", "0.36");
    const double logAvg = 0.9, scale = 0.36 / logAvg, white = 2.5;
    auto op = [&](double Lw) {
        const double L = scale * Lw;
        return L * (1.0 + L / (white * white)) / (1.0 + L);
    };
    expectClose(h.run({static_cast<float>(logAvg), 50.0f, 1, 100}), expected(kInputs, 0.0, op), "reinhard manual");
    // With L_white -> infinity Reinhard reverts to the simple operator on scaled luminance (eq. 4.4 -> 4.1).
    h.knobs().setFromString("tonemap.white", "10000");
    expectClose(h.run({static_cast<float>(logAvg), 50.0f, 1, 100}),
                expected(kInputs, 0.0, [&](double Lw) { return scale * Lw / (1.0 + scale * Lw); }), "reinhard white=inf");
}

namespace {

// Reference formulas, in double precision.
glm::dvec3 acesFitted(glm::dvec3 c) {
    const double in[3][3] = {{0.59719, 0.35458, 0.04823}, {0.07600, 0.90834, 0.01566}, {0.02840, 0.13383, 0.83777}};
    const double out[3][3] = {{1.60475, -0.53108, -0.07367}, {-0.10208, 1.10813, -0.00605}, {-0.00327, -0.07276, 1.07602}};
    glm::dvec3 v(0.0), w(0.0);
    for (int r = 0; r < 3; ++r) v[r] = in[r][0] * c.r + in[r][1] * c.g + in[r][2] * c.b;
    for (int i = 0; i < 3; ++i) v[i] = (v[i] * (v[i] + 0.0245786) - 0.000090537) / (v[i] * (0.983729 * v[i] + 0.4329510) + 0.238081);
    for (int r = 0; r < 3; ++r) w[r] = out[r][0] * v.r + out[r][1] * v.g + out[r][2] * v.b;
    return glm::clamp(w, 0.0, 1.0);
}

glm::dvec3 pbrNeutral(glm::dvec3 c) {
    const double start = 0.8 - 0.04, desaturation = 0.15;
    const double x = std::min(c.r, std::min(c.g, c.b));
    const double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    c -= offset;
    const double peak = std::max(c.r, std::max(c.g, c.b));
    if (peak < start) return glm::clamp(c, 0.0, 1.0);
    const double d = 1.0 - start;
    const double newPeak = 1.0 - d * d / (peak + d - start);
    c *= newPeak / peak;
    const double g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return glm::clamp(glm::mix(c, glm::dvec3(newPeak), g), 0.0, 1.0);
}

std::vector<glm::dvec3> perChannel(const std::vector<glm::vec4>& in, double exposure, glm::dvec3 (*op)(glm::dvec3)) {
    std::vector<glm::dvec3> out;
    for (const auto& p : in) {
        const glm::dvec3 c = op(glm::dvec3(p) * std::exp2(exposure));
        out.emplace_back(srgb(c.r), srgb(c.g), srgb(c.b));
    }
    return out;
}

}  // namespace

TEST(Tonemap, AcesNeutralAndClampMatchTheirFormulas) {
    TonemapHarness h(kInputs);
    h.knobs().setFromString("tonemap.operator", "aces");
    expectClose(h.run({1, 1, 1, 1}), perChannel(kInputs, 0.0, acesFitted), "aces");
    h.knobs().setFromString("tonemap.exposure", "-1");
    expectClose(h.run({1, 1, 1, 1}), perChannel(kInputs, -1.0, acesFitted), "aces -1 EV");
    h.knobs().setFromString("tonemap.operator", "neutral");
    expectClose(h.run({1, 1, 1, 1}), perChannel(kInputs, -1.0, pbrNeutral), "neutral -1 EV");
    h.knobs().setFromString("tonemap.operator", "clamp");
    expectClose(h.run({1, 1, 1, 1}), perChannel(kInputs, -1.0, [](glm::dvec3 c) { return glm::clamp(c, 0.0, 1.0); }), "clamp");
    // Auto exposure scales by key / log-average for these operators too.
    h.knobs().setFromString("tonemap.exposure", "0");
    h.knobs().setFromString("tonemap.auto_exposure", "true");
    h.knobs().setFromString("tonemap.operator", "aces");
    expectClose(h.run({0.5f, 1, 1, 1}), perChannel(kInputs, std::log2(0.18 / 0.5), acesFitted), "aces auto exposure");
}

TEST(Tonemap, TheGuardTurnsNanAndInfinityIntoFiniteValues) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    TonemapHarness h({{nan, 0.5f, 0.5f, 1}, {inf, 0.0f, 0.0f, 1}, {-inf, 0.2f, 0.2f, 1}, {0.5f, 0.5f, 0.5f, 1}});
    h.knobs().setFromString("tonemap.operator", "clamp");
    const auto out = h.run({1, 1, 1, 1});
    EXPECT_NEAR(out[0].r, 0.0, 1e-6);   // NaN -> 0
    EXPECT_NEAR(out[0].g, srgb(0.5), 1.0 / 255.0);
    EXPECT_NEAR(out[1].r, 1.0, 1e-6);   // +inf -> the largest half, clamped to white
    EXPECT_NEAR(out[2].r, 0.0, 1e-6);   // -inf -> 0
    EXPECT_NEAR(out[3].r, srgb(0.5), 1.0 / 255.0);
}
