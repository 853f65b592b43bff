// Depth of field's near field as its own layer (issue 25; case
// dof_blurred_foreground_over_sharp_background.json, pmndrs/postprocessing#176):
// an out-of-focus object in front of a sharp background spreads softly over
// it, about half covering the background at its silhouette and falling
// smoothly to nothing one blur radius out, rather than being dilated with a
// hard rim; and the far field still keeps a sharp foreground's edge sharp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/support/GltfBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

constexpr int W = 480, H = 270;
constexpr float kMaxRadius = 8.0f;

// The case's scene: a red box 0.4 wide at distance 2 in front of a blue wall
// at 12, lit by ambient light only; `focus` and `range` set the focus.
std::string caseScene(double focus, double range) {
    return R"({ "name": "dof near field",
  "camera": { "pos": [0, 0, 0.01], "look-at": [0, 0, -1], "fov": 40, "near": 0.1, "far": 100 },
  "ambient": [1, 1, 1], "sky": { "type": "color" },
  "settings": { "dof.enabled": true, "dof.near_blur": true, "dof.focus_distance": )" +
           std::to_string(focus) + R"(, "dof.focus_range": )" + std::to_string(range) +
           R"(, "dof.max_radius": 8, "ao.enabled": false, "bloom.enabled": false, "aa.method": "none",
                "tonemap.operator": "clamp" },
  "objects": [ { "shape": "box", "size": [80, 80, 0.2], "pos": [0, 0, -12], "material": { "diffuse": [0.1, 0.2, 0.9], "specular": [0, 0, 0] } },
               { "shape": "box", "size": [0.4, 0.4, 0.05], "pos": [0, 0, -2], "material": { "diffuse": [0.9, 0.1, 0.1], "specular": [0, 0, 0] } } ] })";
}

double linear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

// The foreground's share of each pixel on the line from the image's centre
// along (dx, dy) (the row H/2 to the right, or the column W/2 downwards): the
// linear red of `img` between the background's (the wall alone, at the
// line's end) and the foreground's (the box's centre in the sharp image),
// 0 to 1, indexed by the distance from the centre.
struct Profile {
    std::vector<double> share;
    int silhouette = 0;  // the first pixel outside the box in the sharp image
};

Profile measure(RenderSession& s, int dx = 1, int dy = 0) {
    s.knobs().setFromString("dof.enabled", "false");
    s.render({{"final"}});
    const FloatImage sharp = s.readRaw("final");
    s.knobs().setFromString("dof.enabled", "true");
    s.render({{"dof.result"}});
    const FloatImage img = s.readRaw("dof.result");
    const int n = dx ? W / 2 : H / 2;
    auto red = [&](const FloatImage& i, int k) { return linear(i.at(W / 2 + k * dx, H / 2 + k * dy, 0)); };
    const double fg = red(sharp, 0), bg = red(sharp, n - 1);
    Profile p;
    p.share.resize(n);
    for (int k = 0; k < n; ++k) p.share[k] = (red(img, k) - bg) / (fg - bg);
    for (int k = 0; k < n && !p.silhouette; ++k)
        if ((red(sharp, k) - bg) / (fg - bg) < 0.5) p.silhouette = k;
    return p;
}

void print(const Profile& p, int from, int to) {
    std::printf("foreground share from silhouette%+d:", from);
    for (int x = p.silhouette + from; x <= p.silhouette + to; ++x) std::printf(" %.2f", p.share[x]);
    std::printf("\n");
}

}  // namespace

// The case: the box is far in front of the focus (its circle of confusion
// is the whole 8 px), the wall in focus. A box wider than its blur covers
// each pixel by the share of the pixel's blur disc the box's discs reach: 1/2
// at the silhouette, the area of a disc segment beyond it, nothing one radius
// out. Before, near samples simply won the gather: 1.00 inside the edge, then
// 0.92, 0.83, 0.67, 0.50, and 0 seven pixels out.
TEST(DepthOfField, BlurredForegroundSpreadsSoftlyOverASharpBackground) {
    auto s = test::makeSession(W, H);
    s->loadScene(test::writeJson("dof_near.json", nlohmann::json::parse(caseScene(12.0, 2.0))).string());
    // The case's radius along the box's right edge, then its bottom edge and
    // other radii (4 and 16 px) along either.
    struct Variant {
        float radius;
        int dx, dy;
    };
    for (const Variant v : {Variant{kMaxRadius, 1, 0}, Variant{kMaxRadius, 0, 1}, Variant{4.0f, 1, 0}, Variant{16.0f, 0, 1}}) {
        SCOPED_TRACE("max_radius " + std::to_string(v.radius) + (v.dx ? ", right edge" : ", bottom edge"));
        s->knobs().setFromString("dof.max_radius", std::to_string(v.radius));
        const Profile p = measure(*s, v.dx, v.dy);
        const int R = static_cast<int>(v.radius);
        print(p, -R - 2, R + 4);
        const int xs = p.silhouette;
        ASSERT_GT(xs, R + 14);
        ASSERT_LT(xs + R + 12, static_cast<int>(p.share.size()));
        // About half at the silhouette (the pixels either side of it).
        EXPECT_NEAR(0.5 * (p.share[xs - 1] + p.share[xs]), 0.5, 0.1);
        // The background partly shows inside the edge; none of the box far inside.
        EXPECT_LT(p.share[xs - 1], 0.8);
        EXPECT_GT(p.share[xs - R - 3], 0.98);
        // No plateau outside the silhouette: below one half from the first pixel out.
        for (int x = xs; x <= xs + R; ++x) EXPECT_LT(p.share[x], 0.5) << "at silhouette+" << x - xs;
        // Still reaching out half the radius, and gone one radius (and a pixel) out.
        EXPECT_GT(p.share[xs + R / 2], 0.03);
        for (int x = xs + R + 1; x < xs + R + 12; ++x) EXPECT_LT(p.share[x], 0.01) << x - xs;
        // Monotonic and smooth: no step between neighbours much steeper than
        // the disc's own slope at the silhouette, 2 / (pi R) per pixel.
        const double steepest = 1.5 * 2.0 / (3.14159265 * v.radius) + 0.05;
        for (int x = xs - R - 4; x < xs + R + 6; ++x) {
            EXPECT_LE(p.share[x + 1], p.share[x] + 0.01) << "rising at silhouette+" << x + 1 - xs;
            EXPECT_LT(p.share[x] - p.share[x + 1], steepest) << "a hard step at silhouette+" << x + 1 - xs;
        }
    }
}

// The far field: the box in focus, the wall 8 px out of focus behind it. The
// box's edge stays sharp: the blurred wall does not bleed over it, nor does
// the sharp box smear over the wall.
TEST(DepthOfField, SharpForegroundKeepsItsEdgeOverABlurredBackground) {
    auto s = test::makeSession(W, H);
    s->loadScene(test::writeJson("dof_far.json", nlohmann::json::parse(caseScene(2.0, 0.5))).string());
    s->render({{"dof.coc"}});
    EXPECT_NEAR(s->readRaw("dof.coc").at(W - 10, H / 2, 0), kMaxRadius, 0.01);  // the wall is far-blurred
    EXPECT_NEAR(s->readRaw("dof.coc").at(W / 2, H / 2, 0), 0.0, 0.01);         // the box is in focus
    for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
        const Profile p = measure(*s, dx, dy);
        print(p, -4, 4);
        const int xs = p.silhouette;
        for (int x = xs - 12; x < xs; ++x) EXPECT_GT(p.share[x], 0.98) << "silhouette" << x - xs;
        for (int x = xs; x < xs + 12; ++x) EXPECT_LT(p.share[x], 0.02) << "silhouette+" << x - xs;
    }
}

// The near layer's alpha (dof.near_alpha) over the case's row: 1 well inside
// the box, about 1/2 at the silhouette, falling to 0 one radius out; none
// with dof.near_blur off, where the image is the far field's alone.
TEST(DepthOfField, NearAlphaIsTheForegroundsCoverage) {
    auto s = test::makeSession(W, H);
    s->loadScene(test::writeJson("dof_alpha.json", nlohmann::json::parse(caseScene(12.0, 2.0))).string());
    const int xs = W / 2 + measure(*s).silhouette, y = H / 2;
    s->render({{"dof.near_alpha"}});
    const FloatImage a = s->readRaw("dof.near_alpha");
    std::printf("near alpha from silhouette-2:");
    for (int x = xs - 2; x <= xs + 9; ++x) std::printf(" %.2f", a.at(x, y, 0));
    std::printf("\n");
    EXPECT_NEAR(a.at(xs - 12, y, 0), 1.0f, 0.01f);
    EXPECT_NEAR(0.5f * (a.at(xs - 1, y, 0) + a.at(xs, y, 0)), 0.5f, 0.1f);
    for (int x = xs + static_cast<int>(kMaxRadius) + 1; x < xs + 20; ++x) EXPECT_EQ(a.at(x, y, 0), 0.0f) << x - xs;
    EXPECT_EQ(a.at(W - 1, y, 0), 0.0f);
    s->knobs().setFromString("dof.near_blur", "false");
    s->render({{"dof.near_alpha"}});
    EXPECT_EQ(test::stats(s->readRaw("dof.near_alpha"), 0).max, 0.0);
}
