#pragma once
// Moves point and spot lights on small loops around where they were placed,
// to see the deferred pipeline with moving lights. Driven by a frame count,
// not the wall clock, so scripted runs are deterministic.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace dw {

struct Scene;

class LightAnimator {
public:
    float radius = 0.75f;  // scene units
    float speed = 1.0f;    // loops per 6 seconds at 60 frames per second

    bool running() const { return running_; }
    // Remembers the current positions as the loops' centres.
    void start(const Scene& scene);
    // Puts every light back where it was when start() was called.
    void stop(Scene& scene);
    void update(Scene& scene, std::uint64_t frame);

private:
    bool running_ = false;
    std::vector<glm::vec3> base_;
};

}  // namespace dw
