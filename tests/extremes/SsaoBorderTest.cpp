// SSAO at the image border (issue 10): at 320x180 with half-resolution AO an
// open floor's border rows darkened (0.81 raw, 0.88 blurred over the top 5
// rows; 1 at 1280x720). Every border row and column of an open floor must be
// unoccluded; a crease that runs out of the image must stay occluded there.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

Scene openFloor(bool wall) {
    Scene s = test::planeScene(200.0f);
    s.ambient = glm::vec3(0.3f);  // AO only runs with an ambient term
    s.camera.position = {0.0f, 3.0f, 4.0f};
    s.camera.target = {0.0f, 0.0f, 0.0f};
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 400.0f;
    if (wall) {
        // A long wall along z whose crease with the floor leaves the image
        // through its left edge.
        Mesh box = shapes::box({0.5f, 1.5f, 40.0f});
        box.material = 0;  // the floor's material
        const int mesh = s.addMesh(std::move(box));
        s.instances.push_back({mesh, glm::translate(glm::mat4(1.0f), {-3.0f, 0.75f, -10.0f})});
    }
    return s;
}

struct BorderAo {
    float minBorder = 1.0f;      // over every border row and column
    float minLeftColumn = 1.0f;  // the leftmost column
};

BorderAo borderAo(const FloatImage& ao) {
    BorderAo b;
    for (int y = 0; y < ao.height; ++y)
        for (int x = 0; x < ao.width; ++x) {
            const bool border = x == 0 || y == 0 || x == ao.width - 1 || y == ao.height - 1;
            if (border) b.minBorder = std::min(b.minBorder, ao.at(x, y, 0));
            if (x == 0) b.minLeftColumn = std::min(b.minLeftColumn, ao.at(x, y, 0));
        }
    return b;
}

}  // namespace

TEST(SsaoBorder, OpenFloorIsUnoccludedOnEveryBorderRowAtHalfResolution) {
    auto session = test::makeSession(320, 180);
    session->setScene(openFloor(false));
    session->knobs().setFromString("ssao.resolution", "half");
    session->render({{"ao.raw", "ao.filtered"}});
    const BorderAo raw = borderAo(session->readRaw("ao.raw"));
    const BorderAo blurred = borderAo(session->readRaw("ao.filtered"));
    std::printf("open floor at 320x180, half-res AO: border minimum raw %.4f, blurred %.4f\n", raw.minBorder,
                blurred.minBorder);
    EXPECT_GE(raw.minBorder, 0.99f);
    EXPECT_GE(blurred.minBorder, 0.99f);
}

TEST(SsaoBorder, ACreaseThatLeavesTheImageStaysOccludedAtTheBorder) {
    auto session = test::makeSession(320, 180);
    session->setScene(openFloor(true));
    session->knobs().setFromString("ssao.resolution", "half");
    session->render({{"ao.raw"}});
    const BorderAo raw = borderAo(session->readRaw("ao.raw"));
    std::printf("wall crease at the left border: minimum raw AO in the left column %.4f\n", raw.minLeftColumn);
    EXPECT_LT(raw.minLeftColumn, 0.9f);  // measured 0.85 (the open floor: 1)
}
