#include "renderer/scene/CameraPath.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <string>

#include "renderer/Error.h"

namespace dw {

CameraPath CameraPath::still(const Camera& base) {
    CameraPath p;
    p.base_ = base;
    return p;
}

CameraPath CameraPath::orbit(const Camera& base, int poses, double degrees) {
    if (poses < 1) throw Error("an orbit needs at least one pose, got " + std::to_string(poses));
    if (!(degrees > 0.0 && degrees <= 360.0))
        throw Error("an orbit spans more than 0 and at most 360 degrees, got " + std::to_string(degrees));
    CameraPath p;
    p.kind_ = Kind::Orbit;
    p.base_ = base;
    p.poses_ = poses;
    p.arc_ = degrees;
    return p;
}

CameraPath CameraPath::keyframes(const Camera& base, std::vector<CameraKeyframe> keys) {
    if (keys.size() < 2) throw Error("a camera path needs at least two keyframes, got " + std::to_string(keys.size()));
    for (size_t i = 1; i < keys.size(); ++i)
        if (!(keys[i].time > keys[i - 1].time))
            throw Error("camera path times must increase: keyframe " + std::to_string(i) + " is at " +
                        std::to_string(keys[i].time) + ", keyframe " + std::to_string(i - 1) + " at " +
                        std::to_string(keys[i - 1].time));
    CameraPath p;
    p.kind_ = Kind::Keyframes;
    p.base_ = base;
    p.keys_ = std::move(keys);
    p.poses_ = 0;
    return p;
}

int CameraPath::poses() const { return poses_; }

Camera CameraPath::at(int k, int count) const {
    switch (kind_) {
        case Kind::Still: return base_;
        case Kind::Orbit: {
            Camera c = base_;
            const glm::vec3 offset = base_.position - base_.target;
            // A whole turn is 2 pi exactly, as it was before arcs.
            const float arc = arc_ == 360.0 ? glm::two_pi<float>() : static_cast<float>(glm::radians(arc_));
            const float angle = arc * static_cast<float>(k % poses_) / static_cast<float>(poses_);
            const float cs = std::cos(angle), sn = std::sin(angle);
            // About the vertical through the target: height and distance stay.
            c.position = base_.target + glm::vec3(cs * offset.x + sn * offset.z, offset.y, -sn * offset.x + cs * offset.z);
            return c;
        }
        case Kind::Keyframes: {
            const float t0 = keys_.front().time, t1 = keys_.back().time;
            const float u = count > 1 ? static_cast<float>(k) / static_cast<float>(count - 1) : 0.0f;
            return atTime(t0 + (t1 - t0) * u);
        }
    }
    return base_;
}

Camera CameraPath::atTime(float t) const {
    Camera c = base_;
    if (keys_.empty()) return c;
    t = std::clamp(t, keys_.front().time, keys_.back().time);
    size_t i = 1;
    while (i + 1 < keys_.size() && keys_[i].time < t) ++i;
    const CameraKeyframe& a = keys_[i - 1];
    const CameraKeyframe& b = keys_[i];
    const float w = (t - a.time) / (b.time - a.time);
    c.position = glm::mix(a.position, b.position, w);
    c.target = glm::mix(a.target, b.target, w);
    return c;
}

}  // namespace dw
