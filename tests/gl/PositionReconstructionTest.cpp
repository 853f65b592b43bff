// View-space position reconstructed from the G-buffer depth (seed 000 section
// 3.1) against the exact ray/plane intersection for every pixel.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

struct PlaneCase {
    glm::mat4 model;
    Camera camera;
};

struct ReconstructionError {
    double worst = 0.0, mean = 0.0;
};

ReconstructionError reconstructionError(const PlaneCase& c, const char* depthMode = "reversed",
                                        const char* depthFormat = "float32") {
    const int W = 160, H = 90;
    auto session = test::makeSession(W, H);
    Scene s = test::planeScene(200.0f);
    s.instances[0].transform = c.model;
    s.camera = c.camera;
    session->setScene(std::move(s));
    session->knobs().setFromString("depth.mode", depthMode);  // after setScene, which applies the run's knobs
    session->knobs().setFromString("gbuffer.depth_format", depthFormat);
    session->render({{"gbuffer.view_position"}});
    const FloatImage pos = session->readRaw("gbuffer.view_position");

    const glm::mat4 view = c.camera.view();
    const glm::vec3 p0 = glm::vec3(view * c.model * glm::vec4(0, 0, 0, 1));
    const glm::vec3 n = glm::normalize(glm::vec3(glm::transpose(glm::inverse(view * c.model)) * glm::vec4(0, 1, 0, 0)));
    const double tanHalf = std::tan(glm::radians(static_cast<double>(c.camera.fovYDegrees)) * 0.5);
    const double aspect = static_cast<double>(W) / H;
    double worst = 0.0, sum = 0.0;
    int covered = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (pos.at(x, y, 3) == 0.0f) continue;  // background
            ++covered;
            // Pixel centre ray; image rows are top-down.
            const double ndcX = (x + 0.5) / W * 2.0 - 1.0;
            const double ndcY = 1.0 - (y + 0.5) / H * 2.0;
            const glm::dvec3 dir(ndcX * tanHalf * aspect, ndcY * tanHalf, -1.0);
            const double t = glm::dot(glm::dvec3(n), glm::dvec3(p0)) / glm::dot(glm::dvec3(n), dir);
            const glm::dvec3 expected = dir * t;
            const glm::dvec3 got(pos.at(x, y, 0), pos.at(x, y, 1), pos.at(x, y, 2));
            const double e = glm::length(got - expected) / glm::length(expected);
            worst = std::max(worst, e);
            sum += e;
        }
    std::printf("position reconstruction (%s depth, %s, near %g, far %g): worst relative error %.3g, mean %.3g over %d pixels\n",
                depthMode, depthFormat, c.camera.nearPlane, c.camera.farPlane, worst, sum / std::max(covered, 1), covered);
    EXPECT_GT(covered, W * H / 4);
    return {worst, sum / std::max(covered, 1)};
}

void checkReconstruction(const PlaneCase& c, double tolerance) { EXPECT_LT(reconstructionError(c).worst, tolerance); }

// The case: near 1e-5, far 5000, a floor seen at a grazing angle.
PlaneCase tinyNearPlane() {
    PlaneCase c;
    c.model = glm::mat4(1.0f);
    c.camera.position = {0.0f, 2.0f, 10.0f};
    c.camera.target = {0.0f, 0.0f, -20.0f};
    c.camera.nearPlane = 1e-5f;
    c.camera.farPlane = 5000.0f;
    return c;
}

}  // namespace

TEST(PositionReconstruction, GroundPlaneAtAGrazingAngle) {
    PlaneCase c;
    c.model = glm::mat4(1.0f);
    c.camera.position = {0.0f, 2.0f, 10.0f};
    c.camera.target = {0.0f, 0.0f, -20.0f};
    c.camera.nearPlane = 0.1f;
    c.camera.farPlane = 100.0f;
    // DEPTH32F with reversed Z: the error is about constant in relative terms.
    checkReconstruction(c, 1e-4);
}

TEST(PositionReconstruction, TiltedPlaneFacingTheCamera) {
    PlaneCase c;
    c.model = glm::rotate(glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, -6.0f}), glm::radians(70.0f), glm::vec3(1, 0.3f, 0));
    c.camera.position = {0.5f, 0.5f, 4.0f};
    c.camera.target = {0.0f, 0.0f, -6.0f};
    c.camera.nearPlane = 0.5f;
    c.camera.farPlane = 50.0f;
    checkReconstruction(c, 2e-4);
}

// Reversed Z (the default) keeps positions exact to a few 1e-6 even with the
// near plane 5e8 times closer than the far one.
TEST(PositionReconstruction, ReversedDepthAtNear1e5Far5000) {
    const ReconstructionError e = reconstructionError(tinyNearPlane(), "reversed");
    EXPECT_LT(e.worst, 1e-4);
    EXPECT_LT(e.mean, 1e-5);
}

// The conventional mapping (depth.mode = conventional, kept for measuring)
// spends its precision at the near plane: the same view is off by percent.
TEST(PositionReconstruction, ConventionalDepthAtNear1e5Far5000LosesPrecision) {
    const ReconstructionError e = reconstructionError(tinyNearPlane(), "conventional");
    EXPECT_GT(e.mean, 1e-2);
}

// gbuffer.depth_format (issue 23) at near 1e-2, far 1e5 (ratio 1e7), the
// floor out to 100 units: 24-bit fixed-point depth with the conventional
// mapping has steps of 2^-24 in 1 - near/z, a relative step of z / near *
// 6e-8 = 6e-4 at z = 100: z-fighting level (two surfaces 0.06 apart there
// share a depth value). Float depth reversed keeps about 1e-7 everywhere.
TEST(PositionReconstruction, Unorm24ConventionalZFightsWhereFloat32ReversedDoesNot) {
    PlaneCase c = tinyNearPlane();
    c.camera.nearPlane = 1e-2f;
    c.camera.farPlane = 1e5f;
    const ReconstructionError floatReversed = reconstructionError(c, "reversed", "float32");
    const ReconstructionError unormConventional = reconstructionError(c, "conventional", "unorm24");
    const ReconstructionError unormReversed = reconstructionError(c, "reversed", "unorm24");
    RecordProperty("float32_reversed_worst", std::to_string(floatReversed.worst));
    RecordProperty("unorm24_conventional_worst", std::to_string(unormConventional.worst));
    EXPECT_LT(floatReversed.worst, 1e-5);
    EXPECT_GT(unormConventional.worst, 1e-4);
    EXPECT_GT(unormConventional.worst, 100.0 * floatReversed.worst);
    // Reversed mapping into fixed point gains nothing (its precision needs float's exponent).
    EXPECT_GT(unormReversed.worst, 10.0 * floatReversed.worst);
}
