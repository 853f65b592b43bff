#include "renderer/scene/LightAnimator.h"

#include <cmath>
#include <cstdint>
#include <glm/gtc/constants.hpp>

#include "renderer/scene/Scene.h"

namespace dw {

void LightAnimator::start(const Scene& scene) {
    base_.clear();
    for (const auto& l : scene.lights) base_.push_back(l.position);
    running_ = true;
}

void LightAnimator::stop(Scene& scene) {
    for (size_t i = 0; i < scene.lights.size() && i < base_.size(); ++i) scene.lights[i].position = base_[i];
    running_ = false;
}

void LightAnimator::update(Scene& scene, std::uint64_t frame) {
    if (!running_) return;
    // Lights added since start() join with their current position as centre.
    while (base_.size() < scene.lights.size()) base_.push_back(scene.lights[base_.size()].position);
    base_.resize(scene.lights.size());
    const float t = static_cast<float>(frame) / 60.0f * speed * glm::two_pi<float>() / 6.0f;
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        Light& l = scene.lights[i];
        if (l.type == LightType::Directional) continue;
        const float phase = static_cast<float>(i) * 2.399963f;  // golden angle: neighbours out of step
        l.position = base_[i] + glm::vec3(std::cos(t + phase), 0.25f * std::sin(2.0f * (t + phase)), std::sin(t + phase)) * radius;
    }
}

}  // namespace dw
