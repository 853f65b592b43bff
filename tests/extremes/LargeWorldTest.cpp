// Large world coordinates (issue 10, part 6): camera-relative rendering with
// view and shadow matrices built in double precision. A small scene with a
// shadowing spot and point light, translated by 1e5 or 1e6, renders like the
// same scene at the origin; a scene with a copy at the origin and one 1e5
// away renders each right when the camera is near it. Before, at 1e5 the
// spot's pool vanished (self-shadowed), point shadows formed a wrong wedge,
// and near 4e7 the spot's shadow view was NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

Scene smallScene() {
    Scene s = test::planeScene(30.0f);
    s.ambient = glm::vec3(0.05f);
    const int mat = test::addBlinnPhong(s, {0.8f, 0.5f, 0.4f}, glm::vec3(0.2f), 30.0f);
    Mesh box = shapes::box({1.0f, 1.5f, 1.0f});
    box.material = mat;
    const int mesh = s.addMesh(std::move(box));
    s.instances.push_back({mesh, glm::translate(glm::mat4(1.0f), {-1.5f, 0.75f, 0.5f})});
    s.instances.push_back({mesh, glm::translate(glm::mat4(1.0f), {2.0f, 0.75f, -1.0f})});
    test::addSpotLight(s, {-1.0f, 5.0f, 3.0f}, {0.0f, -1.0f, -0.6f}, 30.0f, 4.0f, glm::vec3(6.0f), {1.0f, 0.0f, 0.05f})
        .castShadows = true;
    test::addPointLight(s, {3.0f, 3.0f, 2.0f}, glm::vec3(3.0f), {1.0f, 0.0f, 0.1f}).castShadows = true;
    s.camera.position = {0.0f, 6.0f, 10.0f};
    s.camera.target = {0.0f, 0.0f, 0.0f};
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 100.0f;
    return s;
}

// Everything (instances, lights, camera) moved by `offset`.
void translate(Scene& s, const glm::vec3& offset, std::size_t firstInstance = 0, std::size_t firstLight = 0) {
    for (std::size_t i = firstInstance; i < s.instances.size(); ++i) s.instances[i].transform[3] += glm::vec4(offset, 0.0f);
    for (std::size_t i = firstLight; i < s.lights.size(); ++i) s.lights[i].position += offset;
}

FloatImage render(Scene s, const char* point) {
    auto session = test::makeSession(160, 90);
    session->setScene(std::move(s));
    session->knobs().setFromString("shadows.point_method", point);
    session->render({{"lbuffer"}});
    return session->readRaw("lbuffer");
}

struct Difference {
    double worstFraction = 0.0;  // pixels off by more than 2% (+ 0.002 absolute)
    long long nonFinite = 0;
};

Difference compare(const FloatImage& a, const FloatImage& b) {
    Difference d;
    long long off = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const float va = a.at(x, y, c), vb = b.at(x, y, c);
                if (!std::isfinite(vb)) ++d.nonFinite;
                if (std::fabs(va - vb) > 0.02f * std::fabs(va) + 0.002f) {
                    ++off;
                    break;
                }
            }
    d.worstFraction = static_cast<double>(off) / (a.width * a.height);
    return d;
}

}  // namespace

class LargeWorld : public ::testing::TestWithParam<std::tuple<double, const char*>> {};

TEST_P(LargeWorld, OffsetSceneRendersLikeTheOrigin) {
    const auto [offset, point] = GetParam();
    const glm::vec3 o(static_cast<float>(offset), 0.0f, static_cast<float>(-offset));
    const FloatImage origin = render(smallScene(), point);
    Scene moved = smallScene();
    translate(moved, o);
    moved.camera.position += o;
    moved.camera.target += o;
    const FloatImage far = render(std::move(moved), point);
    const Difference d = compare(origin, far);
    std::printf("offset %g (%s point shadows): %.4f%% of pixels off by > 2%%, %lld non-finite\n", offset, point,
                100.0 * d.worstFraction, d.nonFinite);
    EXPECT_EQ(d.nonFinite, 0);
    EXPECT_LT(d.worstFraction, 0.005);
}

// The comparison above means something: the shadows change the image.
TEST(LargeWorld, TheSmallSceneHasShadowsToCompare) {
    Scene s = smallScene();
    const FloatImage shadowed = render(s, "cube");
    auto session = test::makeSession(160, 90);
    session->setScene(std::move(s));
    session->knobs().setFromString("shadows.enabled", "false");
    session->render({{"lbuffer"}});
    const Difference d = compare(shadowed, session->readRaw("lbuffer"));
    std::printf("shadows on vs off: %.2f%% of pixels differ by > 2%%\n", 100.0 * d.worstFraction);
    EXPECT_GT(d.worstFraction, 0.015);  // measured 2%; three times the bound the offsets must meet
}

// Near 4e7, pos + dir == pos in float (a spot's shadow view was NaN: a black
// disc). Float positions there are 4 units apart, so only finiteness is asked.
TEST(LargeWorld, FourTimesTenToTheSevenStaysFinite) {
    Scene moved = smallScene();
    const glm::vec3 o(4e7f, 0.0f, 4e7f);
    translate(moved, o);
    moved.camera.position += o;
    moved.camera.target += o;
    const FloatImage img = render(std::move(moved), "cube");
    const test::ChannelStats st = test::stats(img, 0);
    EXPECT_EQ(st.nonFinite, 0);
    EXPECT_GT(st.max, 0.0);  // lit, not black
}

INSTANTIATE_TEST_SUITE_P(Offsets, LargeWorld,
                         ::testing::Combine(::testing::Values(1e5, 1e6), ::testing::Values("cube", "dual_paraboloid")));

TEST(LargeWorld, CopiesAtTheOriginAndFarAwayEachRenderRightNearTheCamera) {
    const FloatImage reference = render(smallScene(), "cube");
    // The same scene twice: at the origin and 1e5 away.
    Scene both = smallScene();
    const std::size_t instances = both.instances.size(), lights = both.lights.size();
    const Scene copy = smallScene();
    for (std::size_t i = 0; i < instances; ++i) both.instances.push_back(copy.instances[i]);
    for (std::size_t i = 0; i < lights; ++i) both.lights.push_back(copy.lights[i]);
    const glm::vec3 o(1e5f, 0.0f, 1e5f);
    translate(both, o, instances, lights);
    const Difference nearOrigin = compare(reference, render(both, "cube"));
    both.camera.position += o;
    both.camera.target += o;
    const Difference nearFar = compare(reference, render(both, "cube"));
    std::printf("two copies: camera at the origin %.4f%%, at 1e5 %.4f%% of pixels off by > 2%%\n",
                100.0 * nearOrigin.worstFraction, 100.0 * nearFar.worstFraction);
    EXPECT_EQ(nearOrigin.nonFinite + nearFar.nonFinite, 0);
    EXPECT_LT(nearOrigin.worstFraction, 0.005);
    EXPECT_LT(nearFar.worstFraction, 0.005);
}
