#pragma once
// Where the camera is on each measured frame of a benchmark: still, on an
// orbit, or along a scene's keyframed walk-through (seed 000 chapter 6 times
// its strategies "during a guided walk-through with a camera through the
// scenes" and reports the average). A pose is a function of the frame's
// number only, never of the clock, so every configuration of a run sees the
// same camera on its k-th frame.
#include <vector>

#include "renderer/scene/Camera.h"

namespace dw {

class CameraPath {
public:
    // The camera stays at `base`.
    static CameraPath still(const Camera& base);
    // `poses` positions on the circle about base.target through base.position
    // (the same height and horizontal distance), `degrees` / `poses` apart
    // (360: evenly all around; less: an arc of small steps); pose 0 is base.
    // Throws dw::Error for poses < 1 or degrees outside (0, 360].
    static CameraPath orbit(const Camera& base, int poses, double degrees = 360.0);
    // Linear in position and look-at between keyframes, by time; the rest of
    // the camera (fov, planes, up) from `base`. Throws dw::Error for fewer
    // than two keyframes or times that do not increase.
    static CameraPath keyframes(const Camera& base, std::vector<CameraKeyframe> keys);

    bool moving() const { return kind_ != Kind::Still; }
    // The number of distinct poses (orbit), 1 (still), 0 (keyframes: continuous).
    int poses() const;
    // The camera for measured frame k of `count` (0 <= k < count): orbit pose
    // k mod N; keyframes at time t0 + (t_end - t0) * k / (count - 1).
    Camera at(int k, int count) const;
    // The camera at keyframe time `t`, clamped to the path's span.
    Camera atTime(float t) const;
    const std::vector<CameraKeyframe>& keys() const { return keys_; }

private:
    enum class Kind { Still, Orbit, Keyframes };
    Kind kind_ = Kind::Still;
    Camera base_;
    int poses_ = 1;
    double arc_ = 360.0;  // orbit: the degrees the poses span
    std::vector<CameraKeyframe> keys_;
};

}  // namespace dw
