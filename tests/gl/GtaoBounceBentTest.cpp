// GTAO's multi-bounce fit and bent normals (issue 22; docs/ao.md):
// - an open plane: the bent normal is the surface normal, and multi-bounce
//   changes nothing where the accessibility is 1;
// - a right-angle crease (a wall on a floor): the bent normal tilts away
//   from the wall, within a stated angle of the analytic cosine-weighted
//   mean unoccluded direction (integrated here, with the same hard radius);
// - the ambient term with gtao.multibounce is, per pixel and channel, the
//   single-bounce one times f(x, albedo) / x, f Jimenez et al. 2016's fit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

constexpr int W = 160, H = 90;
constexpr double kPi = 3.14159265358979323846;

double degreesBetween(glm::dvec3 a, glm::dvec3 b) {
    const double c = glm::dot(glm::normalize(a), glm::normalize(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / kPi;
}

// The floor with a wall along x = 0 (a right-angle crease at its foot),
// seen from the side the wall faces; ambient only, no lights.
Scene crease() {
    Scene scene = test::planeScene(40.0f);
    scene.ambient = glm::vec3(0.2f);
    Mesh wall = shapes::box({0.4f, 4.0f, 20.0f});
    wall.material = 0;
    scene.instances.push_back({scene.addMesh(std::move(wall)), glm::translate(glm::mat4(1.0f), {-0.2f, 2.0f, 0.0f})});
    scene.camera.position = {6.0f, 3.0f, 7.0f};
    scene.camera.target = {1.5f, 0.0f, 0.0f};
    return scene;
}

void gtaoFull(RenderSession& s) {
    s.knobs().setFromString("ao.method", "gtao");
    s.knobs().setFromString("gtao.resolution", "full");
    s.knobs().setFromString("gtao.bent_normals", "true");
}

// The analytic bent normal (world space) of a floor point at distance x
// from a wall that is a half-space x < 0 for rays shorter than the radius R
// (the wall is 4 high and 20 wide, far beyond R = 1 here): the
// cosine-weighted mean of the directions that reach no wall within R, by
// midpoint quadrature over the hemisphere about +y.
glm::dvec3 analyticBentNormal(double x, double R) {
    glm::dvec3 b(0.0);
    const int nt = 200, np = 400;
    for (int i = 0; i < nt; ++i) {
        const double t = (i + 0.5) * (kPi / 2) / nt;
        for (int j = 0; j < np; ++j) {
            const double p = (j + 0.5) * 2 * kPi / np;
            const glm::dvec3 w(std::sin(t) * std::cos(p), std::cos(t), std::sin(t) * std::sin(p));
            if (w.x < 0.0 && x < -w.x * R) continue;  // the wall within R
            b += w * std::cos(t) * std::sin(t);
        }
    }
    return glm::normalize(b);
}

}  // namespace

TEST(GtaoBounceBent, OnAnOpenPlaneTheBentNormalIsTheNormal) {
    auto s = test::makeSession(W, H);
    Scene scene = test::planeScene(200.0f);
    scene.ambient = glm::vec3(0.2f);
    s->setScene(std::move(scene));
    gtaoFull(*s);
    s->render({{"gtao.bent_normal", "gbuffer.view_normal", "gbuffer.view_position"}});
    const FloatImage bent = s->readRaw("gtao.bent_normal");
    const FloatImage normal = s->readRaw("gbuffer.view_normal");
    const FloatImage P = s->readRaw("gbuffer.view_position");
    double worst = 0, sum = 0;
    int n = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (P.at(x, y, 3) == 0.0f) continue;
            const glm::dvec3 b(bent.at(x, y, 0), bent.at(x, y, 1), bent.at(x, y, 2));
            const glm::dvec3 N(normal.at(x, y, 0), normal.at(x, y, 1), normal.at(x, y, 2));
            EXPECT_NEAR(glm::length(b), 1.0, 0.002) << x << "," << y;
            const double d = degreesBetween(b, N);
            worst = std::max(worst, d);
            sum += d;
            ++n;
        }
    ASSERT_GT(n, W * H / 3);
    std::printf("open plane: bent normal to normal, mean %.3f deg, worst %.3f deg (%d px)\n", sum / n, worst, n);
    // The closed form gives N exactly for any slices (docs/ao.md); what is
    // left is the 16-bit storage and the depth's rounding. Measured on
    // llvmpipe at 160x90: mean 0.015 deg, worst 0.019 deg.
    EXPECT_LT(sum / n, 0.1);
    EXPECT_LT(worst, 0.5);
}

TEST(GtaoBounceBent, InACreaseTheBentNormalTiltsAwayFromTheWall) {
    // At the defaults (3 slices x 3 steps) the horizons come from 3 samples
    // per side, which miss part of the wall within the radius: measured tilt
    // 15.5 deg against the analytic 20.0, a mean 5.0 deg from it. With 9 x 12
    // the search converges (18.9 deg, 1.1 deg from it; 3 x 12 alone: 1.8):
    // the difference is the horizon sampling, not the bent normal's formula.
    struct Case {
        const char* setting;
        double tiltWithin, meanAngle;
    };
    for (const Case c : {Case{"", 6.0, 6.5}, Case{"gtao.slices=9 gtao.steps=12", 2.0, 2.0}}) {
        const char* setting = c.setting;
        auto s = test::makeSession(W, H);
        s->setScene(crease());
        gtaoFull(*s);
        std::string rest = setting;
        while (!rest.empty()) {
            const auto sp = rest.find(' ');
            s->knobs().applyAssignment(rest.substr(0, sp));
            rest = sp == std::string::npos ? "" : rest.substr(sp + 1);
        }
        s->render({{"gtao.bent_normal", "gbuffer.view_position"}});
        const FloatImage bent = s->readRaw("gtao.bent_normal");
        const FloatImage P = s->readRaw("gbuffer.view_position");
        const glm::dmat4 inverseView = glm::inverse(glm::dmat4(s->camera().view()));
        const glm::dmat3 toWorld(inverseView);
        const double R = 1.0;  // gtao.radius 1 in the scene's unit, 1 here
        double err = 0, tiltGpu = 0, tiltTrue = 0;
        int n = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                if (P.at(x, y, 3) == 0.0f) continue;
                const glm::dvec3 w(inverseView * glm::dvec4(P.at(x, y, 0), P.at(x, y, 1), P.at(x, y, 2), 1.0));
                if (w.y > 0.02 || std::abs(w.z) > 5.0 || w.x < 0.05 || w.x > 0.6) continue;  // the floor by the wall
                const glm::dvec3 b = glm::normalize(toWorld * glm::dvec3(bent.at(x, y, 0), bent.at(x, y, 1), bent.at(x, y, 2)));
                const glm::dvec3 truth = analyticBentNormal(w.x, R);
                err += degreesBetween(b, truth);
                tiltGpu += std::atan2(b.x, b.y) * 180.0 / kPi;
                tiltTrue += std::atan2(truth.x, truth.y) * 180.0 / kPi;
                ++n;
            }
        ASSERT_GT(n, 20);
        std::printf("crease [%s]: bent normal tilt from +y towards +x %.2f deg (analytic %.2f), mean angle to the analytic "
                    "%.2f deg (%d px)\n", setting, tiltGpu / n, tiltTrue / n, err / n, n);
        // Away from the wall (+x), by about the analytic tilt.
        EXPECT_GT(tiltGpu / n, 10.0) << setting;
        EXPECT_NEAR(tiltGpu / n, tiltTrue / n, c.tiltWithin) << setting;
        EXPECT_LT(err / n, c.meanAngle) << setting;
    }
}

TEST(GtaoBounceBent, MultiBounceScalesTheAmbientTermByTheFit) {
    auto s = test::makeSession(W, H);
    Scene scene = crease();
    scene.materials[0].baseColor = glm::vec4(0.8f, 0.5f, 0.2f, 1.0f);
    s->setScene(std::move(scene));
    gtaoFull(*s);
    s->knobs().setFromString("lighting.ambient_specular", "false");  // reflectance = the diffuse albedo
    s->render({{"lbuffer", "ao.filtered", "gbuffer.view_position"}});
    const FloatImage single = s->readRaw("lbuffer");
    const FloatImage ao = s->readRaw("ao.filtered");
    const FloatImage P = s->readRaw("gbuffer.view_position");
    s->knobs().setFromString("gtao.multibounce", "true");
    s->render({{"lbuffer"}});
    const FloatImage multi = s->readRaw("lbuffer");
    int checked = 0, lifted = 0, open = 0;
    double worst = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (P.at(x, y, 3) == 0.0f) continue;
            const double v = ao.at(x, y, 0);
            for (int c = 0; c < 3; ++c) {
                const double l1 = single.at(x, y, c);
                if (v < 0.02 || l1 <= 1e-4) continue;
                const double albedo = l1 / (0.2 * v);  // ambient 0.2 x albedo x accessibility
                const double a = 2.0404 * albedo - 0.3324, b = -4.7951 * albedo + 0.6417,
                             cc = 2.7552 * albedo + 0.6903;
                const double f = std::min(std::max(v, ((v * a + b) * v + cc) * v), 1.0);
                const double expected = 0.2 * albedo * f;
                worst = std::max(worst, std::abs(multi.at(x, y, c) - expected) / expected);
                ++checked;
                if (multi.at(x, y, c) > l1 * 1.02) ++lifted;
                if (v == 1.0 && c == 0) {
                    EXPECT_EQ(multi.at(x, y, c), single.at(x, y, c)) << x << "," << y;
                    ++open;
                }
            }
        }
    std::printf("multi-bounce: %d channel values checked, worst relative error %.2e, %d lifted by > 2%%, %d open "
                "pixels unchanged\n", checked, worst, lifted, open);
    ASSERT_GT(checked, 1000);
    EXPECT_GT(lifted, 100);  // the crease is lit by the bounce
    EXPECT_GT(open, 100);
    EXPECT_LT(worst, 1e-4);  // measured 4.2e-7 (float rounding)
}
