#pragma once
// Perspective look-at camera, as the scene files describe it.
#include <glm/glm.hpp>

namespace dw {

struct Bounds;

// A point of a camera walk-through (the scene JSON's camera.path): where the
// camera is and what it looks at, `time` seconds into the path.
struct CameraKeyframe {
    float time = 0.0f;
    glm::vec3 position{0.0f};
    glm::vec3 target{0.0f};
};

struct Camera {
    glm::vec3 position{0.0f, 2.0f, 8.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 60.0f;
    float nearPlane = 0.1f;
    float farPlane = 200.0f;

    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
    // Places the camera to see `bounds` from the front-right, above.
    static Camera framing(const Bounds& bounds, float fovYDegrees = 50.0f);
    // Near and far planes that hold `bounds` as seen from the current position.
    void fitClipPlanes(const Bounds& bounds);
};

}  // namespace dw
