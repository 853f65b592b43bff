// AovCostEstimate (issue 22): the projected area of each triangle's occlusion
// volume, summed over the screen, against the closed form for an equilateral
// triangle facing the camera and facing away; volumes outside the frustum
// add nothing; a volume reaching the near plane counts as the whole screen;
// the warning names the knob to lower.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/ao/AovCostEstimate.h"
#include "renderer/knobs/KnobRegistry.h"
#include "renderer/scene/Scene.h"

using namespace dw;

namespace {

// An equilateral triangle of inradius r about (cx, cy) in the plane z = z0,
// counter-clockwise seen from +z (its front side faces +z) or from -z.
Scene triangleScene(float r, float cx, float cy, float z0, bool facesPlusZ) {
    Scene s;
    s.addMaterial(Material{});
    Mesh m;
    for (int i = 0; i < 3; ++i) {
        const float a = glm::radians(90.0f + 120.0f * static_cast<float>(i));
        Vertex v;
        v.position = {cx + 2.0f * r * std::cos(a), cy + 2.0f * r * std::sin(a), z0};
        m.vertices.push_back(v);
    }
    m.indices = facesPlusZ ? std::vector<std::uint32_t>{0, 1, 2} : std::vector<std::uint32_t>{0, 2, 1};
    m.material = 0;
    m.computeBounds();
    s.instances.push_back({s.addMesh(std::move(m)), glm::mat4(1.0f)});
    return s;
}

// Camera at the origin looking down -z, 90 degrees, square: NDC = (x, y) / -z.
const glm::mat4 kView(1.0f);
const glm::mat4 kProjection = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);

}  // namespace

TEST(AovCostEstimate, AVolumeFacingTheCameraCoversItsNearCapsProjection) {
    // Inradius 0.5 at distance 10, delta 1: the volume's near cap is the
    // triangle grown to inradius 1.5 (its corners 2 delta out along the
    // bisectors), at distance 9. Area 3 sqrt(3) 1.5^2, over 9^2 in NDC,
    // over the NDC square's 4.
    const Scene s = triangleScene(0.5f, 0.0f, 0.0f, -10.0f, true);
    const AovCostEstimate e = AovCostEstimate::compute(s, kView, kProjection, 0.1f, 1.0f);
    const double expected = 3.0 * std::sqrt(3.0) * 2.25 / 81.0 / 4.0;  // 0.03608
    EXPECT_NEAR(e.meanOverdraw, expected, 1e-5);
    EXPECT_EQ(e.volumes, 1u);
    EXPECT_EQ(e.culled, 0u);
    EXPECT_EQ(e.nearCamera, 0u);
    EXPECT_DOUBLE_EQ(e.fragments(100, 100), e.meanOverdraw * 1e4);
}

TEST(AovCostEstimate, AVolumeFacingAwayCoversItsBasesProjection) {
    // The volume reaches away from the camera: the grown base at distance 10 is the outline.
    const Scene s = triangleScene(0.5f, 0.0f, 0.0f, -10.0f, false);
    const AovCostEstimate e = AovCostEstimate::compute(s, kView, kProjection, 0.1f, 1.0f);
    EXPECT_NEAR(e.meanOverdraw, 3.0 * std::sqrt(3.0) * 2.25 / 100.0 / 4.0, 1e-5);  // 0.02923
}

TEST(AovCostEstimate, TheOutlineIsClippedToTheScreen) {
    // A triangle far wider than the view: its outline covers the whole screen once.
    const Scene s = triangleScene(100.0f, 0.0f, 0.0f, -10.0f, false);
    const AovCostEstimate e = AovCostEstimate::compute(s, kView, kProjection, 0.1f, 1.0f);
    EXPECT_NEAR(e.meanOverdraw, 1.0, 1e-9);
    EXPECT_EQ(e.nearCamera, 0u);
}

TEST(AovCostEstimate, VolumesOutsideTheFrustumAddNothing) {
    for (const glm::vec3 at : {glm::vec3(40.0f, 0.0f, -10.0f), glm::vec3(0.0f, -40.0f, -10.0f),
                               glm::vec3(0.0f, 0.0f, 10.0f)}) {
        const Scene s = triangleScene(0.5f, at.x, at.y, at.z, true);
        const AovCostEstimate e = AovCostEstimate::compute(s, kView, kProjection, 0.1f, 1.0f);
        EXPECT_EQ(e.meanOverdraw, 0.0) << at.x << " " << at.y << " " << at.z;
        EXPECT_EQ(e.culled, 1u);
    }
}

TEST(AovCostEstimate, AVolumeReachingTheNearPlaneCountsAsTheWholeScreen) {
    // At distance 0.5 with delta 1, the volume facing the camera reaches past it.
    const Scene s = triangleScene(0.5f, 0.0f, 0.0f, -0.5f, true);
    const AovCostEstimate e = AovCostEstimate::compute(s, kView, kProjection, 0.1f, 1.0f);
    EXPECT_EQ(e.nearCamera, 1u);
    EXPECT_EQ(e.meanOverdraw, 1.0);
}

TEST(AovCostEstimate, BlendedAndDegenerateTrianglesCastNoVolume) {
    Scene s = triangleScene(0.5f, 0.0f, 0.0f, -10.0f, true);
    s.materials[0].alphaMode = AlphaMode::Blend;
    EXPECT_EQ(AovCostEstimate::compute(s, kView, kProjection, 0.1f, 1.0f).volumes, 0u);
    s.materials[0].alphaMode = AlphaMode::Opaque;
    s.materials[0].doubleSided = true;
    EXPECT_EQ(AovCostEstimate::compute(s, kView, kProjection, 0.1f, 1.0f).volumes, 2u);
    s.meshes[0].vertices[2].position = s.meshes[0].vertices[1].position;
    EXPECT_EQ(AovCostEstimate::compute(s, kView, kProjection, 0.1f, 1.0f).volumes, 0u);
}

TEST(AovCostEstimate, TheWarningNamesTheKnobAndTheLimits) {
    AovCostEstimate e;
    e.meanOverdraw = 2500.0;
    e.volumes = 1000;
    e.radius = 1.0f;
    KnobRegistry knobs;  // no aov.resolution: full size
    const std::string w = AovCostEstimate::warning(e, knobs, 160, 90);
    EXPECT_NE(w.find("about 2500 volume fragments per pixel"), std::string::npos) << w;
    EXPECT_NE(w.find("36 million at 160x90"), std::string::npos) << w;
    // This frame's time at 2.5-15 us a fragment: 90 to 540 s.
    EXPECT_NE(w.find("about 2 to 9 minutes a frame on llvmpipe"), std::string::npos) << w;
    e.meanOverdraw = 100.0;  // 1.44 million: two decimals below 10 million
    EXPECT_EQ(AovCostEstimate::warning(e, knobs, 160, 90), "");
    e.meanOverdraw = 1500.0;
    EXPECT_NE(AovCostEstimate::warning(e, knobs, 40, 30).find("1.80 million at 40x30"), std::string::npos);
    EXPECT_NE(w.find("lower aov.radius"), std::string::npos) << w;
    EXPECT_NE(w.find("limit of 1000 a pixel or 4 million a frame"), std::string::npos) << w;
    // Under 1000 a pixel: the fragments a frame decide (999 x 14400 = 14.4 million; at 80x45, 3.6).
    e.meanOverdraw = 999.0;
    EXPECT_NE(AovCostEstimate::warning(e, knobs, 160, 90), "");
    EXPECT_EQ(AovCostEstimate::warning(e, knobs, 80, 45), "");
    EXPECT_TRUE(AovCostEstimate::exceeds(e, 160, 90));
    EXPECT_FALSE(AovCostEstimate::exceeds(e, 80, 45));
}

// The warning's time range: the frame's fragments at 2.5 and 15 us each,
// each end in its own unit, the unit said once when they share it.
TEST(AovCostEstimate, TheTimeRangeIsTheFramesFragmentsAtTheMeasuredRates) {
    EXPECT_EQ(AovCostEstimate::timeRange(4e6), "about 10 to 60 s");
    EXPECT_EQ(AovCostEstimate::timeRange(36e6), "about 2 to 9 minutes");
    EXPECT_EQ(AovCostEstimate::timeRange(240e6), "about 10 to 60 minutes");
    EXPECT_EQ(AovCostEstimate::timeRange(933e6), "about 39 minutes to 3.9 hours");
    EXPECT_EQ(AovCostEstimate::timeRange(1e5), "about 0.25 to 1.5 s");
}
