// A shadowed scene scaled as a whole (objects, camera, lights) keeps its
// shadows: the shadow maps' depth ranges, box sizes, paddings and biases
// follow the scene's size, as the camera rule does. At 1e-8 the shadows were
// gone (finite and silent): absolute floors of 1e-3 units sized a
// directional map 100 000 times the scene.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <vector>

#include "renderer/scene/SceneJsonLoader.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.9g", v);
    return b;
}

std::string vec(double x, double y, double z, double k) { return "[" + num(x * k) + ", " + num(y * k) + ", " + num(z * k) + "]"; }

// A floor, a box and a sphere on it, lit by `light` (its positions scaled by k),
// seen by a camera scaled by k. No attenuation but the constant term, so the
// light's radiance does not depend on the scale.
Scene shadowScene(double k, const std::string& light, bool clipPlanes = true) {
    std::string l = light;
    for (std::size_t at; (at = l.find("@")) != std::string::npos;) {
        const std::size_t end = l.find(']', at);
        double x = 0, y = 0, z = 0;
        std::sscanf(l.c_str() + at + 1, "[%lf,%lf,%lf]", &x, &y, &z);
        l.replace(at, end + 1 - at, vec(x, y, z, k));
    }
    const std::string text = R"({"objects": [
        {"shape": "plane", "size": )" + vec(12, 0, 12, k) + R"(},
        {"shape": "box", "size": )" + vec(2, 2, 2, k) + R"(, "pos": )" + vec(0, 1, 0, k) + R"(},
        {"shape": "sphere", "radius": )" + num(0.8 * k) + R"(, "pos": )" + vec(2.5, 0.8, 1.5, k) + R"(}],
      "ambient": [0, 0, 0],
      "lights": [)" + l + R"(],
      "camera": {"pos": )" + vec(4, 5, 6, k) + R"(, "look-at": )" + vec(0, 0, 0, k) + (clipPlanes ? R"(, "near": )" + num(0.1 * k) +
                             R"(, "far": )" + num(50 * k) : std::string()) + R"(}})";
    return parseSceneJson(text, "scaled.json");
}

FloatImage lbuffer(double k, const std::string& light, const std::string& kind, bool shadows) {
    auto session = test::makeSession(160, 90);
    session->setScene(shadowScene(k, light));
    session->knobs().setFromString("ao.enabled", "false");
    if (!kind.empty()) session->knobs().setFromString("shadows.point_method", kind);
    if (!shadows) session->knobs().setFromString("shadows.enabled", "false");
    session->render({{"lbuffer"}});
    return session->readRaw("lbuffer");
}

// The pixels a shadow darkens: more than 10% of the brightest unshadowed
// pixel below the same render without shadows.
std::vector<bool> shadowMask(const FloatImage& lit, const FloatImage& shadowed) {
    double peak = 0;
    for (float v : lit.pixels) peak = std::max(peak, double(v));
    std::vector<bool> m(static_cast<std::size_t>(lit.width) * lit.height);
    for (int y = 0; y < lit.height; ++y)
        for (int x = 0; x < lit.width; ++x)
            m[static_cast<std::size_t>(y) * lit.width + x] = lit.at(x, y, 0) - shadowed.at(x, y, 0) > 0.1 * peak;
    return m;
}

}  // namespace

TEST(SceneScaleShadows, TheSameScaledSceneHasTheSameShadowsAtEveryScale) {
    const std::vector<std::pair<std::string, std::string>> lights = {
        {R"({"type": "directional", "direction": [-1, -2, -0.5], "intensity": [2, 2, 2], "shadow": true})", ""},
        {R"({"type": "spot", "pos": @[4, 9, 3], "direction": [-0.4, -0.9, -0.3], "cutoff": 40, "intensity": [2, 2, 2],
             "attenuation": {"constant": 1, "linear": 0, "quadratic": 0}, "shadow": true})", ""},
        {R"({"type": "point", "pos": @[3, 5, 2], "intensity": [2, 2, 2], "attenuation": {"constant": 1, "linear": 0, "quadratic": 0}, "shadow": true})", "cube"},
        {R"({"type": "point", "pos": @[3, 5, 2], "intensity": [2, 2, 2], "attenuation": {"constant": 1, "linear": 0, "quadratic": 0}, "shadow": true})", "dual_paraboloid"}};
    for (const auto& [light, kind] : lights) {
        const std::size_t at = light.find(": \"") + 3;
        const std::string name = light.substr(at, light.find('"', at) - at) + (kind.empty() ? "" : " (" + kind + ")");
        const std::vector<bool> unit = shadowMask(lbuffer(1.0, light, kind, false), lbuffer(1.0, light, kind, true));
        const long shadowed = std::count(unit.begin(), unit.end(), true);
        EXPECT_GT(shadowed, static_cast<long>(unit.size() / 200)) << name << " casts no shadow at scale 1";
        for (double k : {1e-8, 1e-4, 1e4, 1e6}) {
            const FloatImage lit = lbuffer(k, light, kind, false);
            const std::vector<bool> mask = shadowMask(lit, lbuffer(k, light, kind, true));
            long same = 0, count = 0;
            for (std::size_t i = 0; i < mask.size(); ++i) {
                count += mask[i];
                same += mask[i] && unit[i];
            }
            std::printf("%s at scale %g: %ld shadowed pixels (%ld at scale 1, %ld of them the same)\n", name.c_str(), k, count,
                        shadowed, same);
            EXPECT_NEAR(static_cast<double>(count), static_cast<double>(shadowed), 0.05 * shadowed) << name << " at scale " << k;
            EXPECT_GT(same, 0.95 * shadowed) << name << " at scale " << k;
            // Lit alike too (a light within 1e-6 of a surface was dark: L = toLight / max(d, 1e-6)).
            const FloatImage litUnit = lbuffer(1.0, light, kind, false);
            double diff = 0, sum = 0;
            for (std::size_t i = 0; i < lit.pixels.size(); ++i) {
                diff += std::fabs(lit.pixels[i] - litUnit.pixels[i]);
                sum += litUnit.pixels[i];
            }
            EXPECT_LT(diff, 0.01 * sum) << name << " at scale " << k;
        }
    }
}

// Without near and far the camera's planes come from the scene's bounds, in
// proportion at any scale (a 1e-3 floor on the radius put the near plane of
// a scene 1e-8 across beyond the whole scene: nothing was drawn).
TEST(SceneScaleShadows, FittedClipPlanesFollowTheScene) {
    const std::string light = R"({"type": "directional", "direction": [-1, -2, -0.5], "intensity": [2, 2, 2], "shadow": true})";
    const Scene unit = shadowScene(1.0, light, false);
    for (double k : {1e-8, 1e-4, 1e4}) {
        const Scene s = shadowScene(k, light, false);
        EXPECT_NEAR(s.camera.nearPlane / k, unit.camera.nearPlane, 1e-4 * unit.camera.nearPlane) << k;
        EXPECT_NEAR(s.camera.farPlane / k, unit.camera.farPlane, 1e-4 * unit.camera.farPlane) << k;
        auto render = [&](const Scene& scene) {
            auto session = test::makeSession(160, 90);
            session->setScene(scene);
            session->knobs().setFromString("ao.enabled", "false");
            session->render({{"lbuffer"}});
            return session->readRaw("lbuffer");
        };
        const FloatImage a = render(unit), b = render(s);
        double diff = 0, sum = 0;
        for (std::size_t i = 0; i < a.pixels.size(); ++i) {
            diff += std::fabs(a.pixels[i] - b.pixels[i]);
            sum += a.pixels[i];
        }
        EXPECT_GT(sum, 0.0);
        EXPECT_LT(diff, 0.01 * sum) << k;
    }
}
