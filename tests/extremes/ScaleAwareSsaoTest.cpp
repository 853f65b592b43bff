// Scale-aware SSAO (issue 10, part 8): with ssao.radius_unit = scene_fraction
// (the default) the same scene scaled by 1e-4, 1e-2 or 1e4 (positions,
// sizes, near/far together) gets the AO it gets at scale 1; in world units
// (seed 000's SSAO1-5 presets) a radius of 1 is far too large for a small
// model and far too small for a large one.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/ao/SsaoMethod.h"
#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

Scene creaseScene(float k) {
    Scene s = test::planeScene(20.0f * k);
    s.ambient = glm::vec3(0.3f);
    Mesh box = shapes::box(glm::vec3(2.0f, 2.0f, 2.0f) * k);
    box.material = 0;
    s.instances.push_back({s.addMesh(std::move(box)), glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.0f) * k)});
    s.camera.position = glm::vec3(3.0f, 4.0f, 6.0f) * k;
    s.camera.target = glm::vec3(0.0f, 0.5f, 0.0f) * k;
    s.camera.nearPlane = 0.1f * k;
    s.camera.farPlane = 100.0f * k;
    return s;
}

FloatImage rawAo(float k, const char* unit) {
    auto session = test::makeSession(160, 90);
    session->setScene(creaseScene(k));
    session->knobs().setFromString("ssao.radius_unit", unit);
    session->render({{"ao.raw"}});
    return session->readRaw("ao.raw");
}

// Mean |a - b| over the pixels either image occludes (AO < 0.98): the
// crease and whatever dark blobs a wrong radius makes.
double meanAbsDifference(const FloatImage& a, const FloatImage& b) {
    double sum = 0.0;
    int n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            if (a.at(x, y, 0) >= 0.98f && b.at(x, y, 0) >= 0.98f) continue;
            sum += std::fabs(a.at(x, y, 0) - b.at(x, y, 0));
            ++n;
        }
    return n > 0 ? sum / n : 0.0;
}

}  // namespace

TEST(ScaleAwareSsao, SceneFractionRadiusGivesTheSameAoAtEveryScale) {
    const FloatImage unit = rawAo(1.0f, "scene_fraction");
    const double minAo = test::stats(unit, 0).min;
    EXPECT_LT(minAo, 0.8);  // the crease is occluded
    for (float k : {1e-4f, 1e-2f, 1e4f}) {
        const double fraction = meanAbsDifference(unit, rawAo(k, "scene_fraction"));
        const double world = meanAbsDifference(unit, rawAo(k, "world"));
        std::printf("scale %g: mean |AO - AO at scale 1| where occluded %.4f with scene_fraction, %.4f with world units "
                    "(min AO at scale 1: %.3f)\n", k, fraction, world, minAo);
        EXPECT_LT(fraction, 0.01) << k;
        EXPECT_GT(world, 0.03) << k;  // world units do depend on the scale
    }
}

TEST(ScaleAwareSsao, TheSceneUnitIsAPowerOfTenOfTheScenesSize) {
    Bounds b;
    b.add(glm::vec3(-10.0f));
    b.add(glm::vec3(10.0f));  // radius 17.3
    EXPECT_FLOAT_EQ(SsaoMethod::sceneUnit(b), 1.0f);
    Bounds tiny;
    tiny.add(glm::vec3(-0.1f));
    tiny.add(glm::vec3(0.1f));  // a model 0.2 across: radius 0.17
    EXPECT_NEAR(SsaoMethod::sceneUnit(tiny), 0.01f, 1e-6f);
    EXPECT_FLOAT_EQ(SsaoMethod::sceneUnit(Bounds{}), 1.0f);
}
