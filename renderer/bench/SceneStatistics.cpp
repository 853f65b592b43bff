#include "renderer/bench/SceneStatistics.h"

#include <algorithm>
#include <limits>

#include "renderer/RenderSession.h"
#include "renderer/scene/CameraPath.h"

namespace dw {

SceneStatistics countScene(const Scene& scene) {
    SceneStatistics s;
    s.scene = scene.name;
    s.objects = scene.instances.size();
    s.triangles = scene.triangleCount();
    s.directional = scene.countLights(LightType::Directional);
    s.point = scene.countLights(LightType::Point);
    s.spot = scene.countLights(LightType::Spot);
    s.lights = s.directional + s.point + s.spot;
    return s;
}

namespace {

struct PoseLpp {
    double sum = 0.0, pixels = 0.0, litSum = 0.0, lit = 0.0;
};

// One pose: lighting.overlap over every pixel, and over the lit surface pixels
// (gbuffer.view_position's alpha is 0 where no surface is).
PoseLpp poseLpp(RenderSession& session) {
    session.render({{"lighting.overlap", "gbuffer.view_position"}});
    const FloatImage overlap = session.readRaw("lighting.overlap");
    const FloatImage position = session.readRaw("gbuffer.view_position");
    PoseLpp p;
    for (int y = 0; y < overlap.height; ++y)
        for (int x = 0; x < overlap.width; ++x) {
            const float v = overlap.at(x, y, 0);
            p.sum += v;
            if (v > 0.0f && position.at(x, y, 3) != 0.0f) {
                p.lit += 1.0;
                p.litSum += v;
            }
        }
    p.pixels = static_cast<double>(overlap.width) * overlap.height;
    return p;
}

}  // namespace

void measureLightsPerPixel(RenderSession& session, int poses, SceneStatistics& stats) {
    const Camera base = session.camera();
    const Scene& scene = session.scene();
    const CameraPath path =
        scene.cameraPath.size() >= 2 ? CameraPath::keyframes(base, scene.cameraPath) : CameraPath::orbit(base, poses);
    PoseLpp all;
    stats.lppMin = std::numeric_limits<double>::infinity();
    stats.lppMax = 0.0;
    for (int k = 0; k < poses; ++k) {
        session.camera() = path.at(k, poses);
        const PoseLpp p = poseLpp(session);
        const double mean = p.pixels > 0.0 ? p.sum / p.pixels : 0.0;
        stats.lppMin = std::min(stats.lppMin, mean);
        stats.lppMax = std::max(stats.lppMax, mean);
        all.sum += p.sum;
        all.pixels += p.pixels;
        all.litSum += p.litSum;
        all.lit += p.lit;
    }
    session.camera() = base;
    stats.poses = poses;
    stats.lpp = all.pixels > 0.0 ? all.sum / all.pixels : 0.0;
    stats.lppLit = all.lit > 0.0 ? all.litSum / all.lit : 0.0;
}

}  // namespace dw
