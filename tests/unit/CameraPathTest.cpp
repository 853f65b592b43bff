// Camera paths for bench: an orbit, keyframes, and the scene JSON's camera.path.
#include <gtest/gtest.h>

#include "renderer/Error.h"
#include "renderer/scene/CameraPath.h"
#include "renderer/scene/SceneJsonLoader.h"

using namespace dw;

TEST(CameraPath, OrbitKeepsHeightAndDistanceAndComesBack) {
    Camera base;
    base.position = {0.0f, 3.0f, 10.0f};
    base.target = {0.0f, 1.0f, 0.0f};
    const CameraPath orbit = CameraPath::orbit(base, 4);
    EXPECT_EQ(orbit.poses(), 4);
    const Camera quarter = orbit.at(1, 8);
    EXPECT_NEAR(quarter.position.y, 3.0f, 1e-5f);
    EXPECT_NEAR(glm::length(glm::vec2(quarter.position.x, quarter.position.z)), 10.0f, 1e-4f);
    EXPECT_NEAR(std::abs(quarter.position.x), 10.0f, 1e-4f);
    EXPECT_EQ(orbit.at(4, 8).position, orbit.at(0, 8).position);
    EXPECT_NEAR(glm::length(orbit.at(0, 8).position - base.position), 0.0f, 1e-5f);
}

TEST(CameraPath, KeyframesInterpolateAndSpanTheFrames) {
    Camera base;
    const CameraPath p = CameraPath::keyframes(base, {{0.0f, {0, 1, 0}, {0, 0, -1}}, {2.0f, {4, 1, 0}, {4, 0, -1}}});
    EXPECT_EQ(p.at(0, 5).position, glm::vec3(0, 1, 0));
    EXPECT_EQ(p.at(4, 5).position, glm::vec3(4, 1, 0));
    EXPECT_NEAR(p.at(2, 5).position.x, 2.0f, 1e-6f);
    EXPECT_NEAR(p.atTime(0.5f).target.x, 1.0f, 1e-6f);
    EXPECT_THROW(CameraPath::keyframes(base, {{0.0f, {}, {0, 0, 1}}}), Error);
    EXPECT_THROW(CameraPath::keyframes(base, {{1.0f, {}, {0, 0, 1}}, {1.0f, {}, {0, 0, 1}}}), Error);
}

TEST(CameraPath, SceneJsonCameraPathIsRead) {
    const Scene s = parseSceneJson(R"({"objects": [{"shape": "plane", "size": [10, 0, 10]}],
        "camera": {"pos": [0, 2, 8], "look-at": [0, 0, 0],
                   "path": [{"time": 0, "pos": [0, 2, 8], "look-at": [0, 0, 0]},
                            {"time": 4, "pos": [8, 2, 0], "look-at": [0, 1, 0]}]}})",
                                   "walk.json");
    ASSERT_EQ(s.cameraPath.size(), 2u);
    EXPECT_EQ(s.cameraPath[1].time, 4.0f);
    EXPECT_EQ(s.cameraPath[1].position, glm::vec3(8, 2, 0));
    EXPECT_EQ(s.cameraPath[1].target, glm::vec3(0, 1, 0));
    EXPECT_TRUE(s.warnings.empty());
    EXPECT_TRUE(parseSceneJson(R"({"camera": {"pos": [0, 2, 8]}})", "still.json").cameraPath.empty());

    auto error = [](const std::string& path) -> std::string {
        try {
            parseSceneJson(R"({"camera": {"pos": [0, 2, 8], "path": )" + path + "}}", "walk.json");
        } catch (const FileError& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_NE(error(R"([{"time": 0, "pos": [0, 1, 0], "look-at": [0, 0, 0]}])").find("at least two"), std::string::npos);
    // (Keyframes look at the origin from the side: straight down along up would be refused.)
    EXPECT_NE(error(R"([{"time": 1, "pos": [0, 1, 2], "look-at": [0, 0, 0]}, {"time": 1, "pos": [1, 1, 0], "look-at": [0, 0, 0]}])")
                  .find("walk.json: camera.path[1].time: must be greater"),
              std::string::npos);
    EXPECT_NE(error(R"([{"time": 0, "pos": [0, 1, 0]}, {"time": 1, "pos": [1, 1, 0], "look-at": [0, 0, 0]}])")
                  .find("camera.path[0]: a keyframe needs \"look-at\""),
              std::string::npos);
    EXPECT_NE(error(R"({"time": 0})").find("camera.path: expected an array"), std::string::npos);
}
