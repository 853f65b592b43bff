#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include "renderer/scene/CameraController.h"
#include "renderer/scene/LightAnimator.h"
#include "renderer/scene/Scene.h"

using namespace dw;

TEST(CameraController, OrbitKeepsDistanceAndTargetAndStopsAtThePoles) {
    Camera c;
    c.position = {0, 2, 8};
    c.target = {1, 0, 0};
    const float d = camera::distance(c);
    camera::orbit(c, 0.7f, 0.3f);
    EXPECT_NEAR(camera::distance(c), d, 1e-4f);
    EXPECT_EQ(c.target, glm::vec3(1, 0, 0));
    camera::orbit(c, 0.0f, 10.0f);  // far past the pole
    const glm::vec3 dir = glm::normalize(c.position - c.target);
    EXPECT_LT(dir.y, 1.0f);
    EXPECT_GT(dir.y, std::cos(glm::radians(1.5f)));
    // A full turn of yaw comes back to the start.
    Camera a = c;
    for (int i = 0; i < 8; ++i) camera::orbit(a, glm::two_pi<float>() / 8.0f, 0.0f);
    EXPECT_NEAR(glm::length(a.position - c.position), 0.0f, 1e-3f);
}

TEST(CameraController, ZoomPanFlyAndLook) {
    Camera c;
    c.position = {0, 0, 10};
    c.target = {0, 0, 0};
    camera::zoom(c, 0.5f);
    EXPECT_NEAR(camera::distance(c), 5.0f, 1e-5f);
    camera::zoom(c, 1e-9f);  // clamped in front of the near plane
    EXPECT_GE(camera::distance(c), c.nearPlane * 2.0f - 1e-6f);
    Camera p;
    p.position = {0, 0, 10};
    p.target = {0, 0, 0};
    camera::pan(p, 0.1f, 0.0f);
    EXPECT_NEAR(p.position.x, 1.0f, 1e-5f);  // right of a camera looking down -Z is +X
    EXPECT_NEAR(p.target.x, 1.0f, 1e-5f);
    camera::fly(p, {0, 0, 2});
    EXPECT_NEAR(p.position.z, 8.0f, 1e-5f);
    const glm::vec3 eye = p.position;
    camera::look(p, glm::half_pi<float>(), 0.0f);
    EXPECT_EQ(p.position, eye);
    EXPECT_GT(p.target.x - p.position.x, 9.9f);  // turned right, towards +X
}

TEST(LightAnimator, MovesLocalLightsDeterministicallyAndRestoresThem) {
    Scene s;
    Light sun;
    sun.type = LightType::Directional;
    Light lamp;
    lamp.position = {1, 2, 3};
    s.lights = {sun, lamp};
    LightAnimator a;
    a.start(s);
    a.update(s, 30);
    const glm::vec3 moved = s.lights[1].position;
    EXPECT_GT(glm::length(moved - glm::vec3(1, 2, 3)), 0.1f);
    EXPECT_LE(glm::length(moved - glm::vec3(1, 2, 3)), a.radius * 1.1f);
    a.update(s, 30);
    EXPECT_EQ(s.lights[1].position, moved);  // a frame number, not the clock
    a.stop(s);
    EXPECT_EQ(s.lights[1].position, glm::vec3(1, 2, 3));
}
