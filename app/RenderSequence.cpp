#include "app/RenderSequence.h"

#include "app/CompareSequence.h"
#include "renderer/Error.h"
#include "renderer/scene/CameraPath.h"

namespace dw {

RenderSequence RenderSequence::read(CommandLine& cl) {
    RenderSequence s;
    s.orbit = cl.whole("--orbit", 0);
    const auto degrees = cl.real("--orbit-degrees");
    s.orbitDegrees = degrees.value_or(360.0);
    s.walkthrough = cl.flag("--walkthrough");
    s.timeSteps = cl.whole("--time-steps", 0);
    const auto rate = cl.real("--frame-rate");
    s.frameRate = rate.value_or(30.0);
    s.pattern = cl.value("--out-sequence").value_or("");
    const bool path = s.orbit > 0 || s.walkthrough || s.timeSteps > 0;
    if ((s.orbit > 0) + s.walkthrough + (s.timeSteps > 0) > 1)
        throw UsageError("--orbit, --walkthrough and --time-steps are three sequences; pick one");
    if (rate && s.timeSteps == 0) throw UsageError("--frame-rate is --time-steps N's frames per second; give --time-steps");
    if (degrees && s.orbit == 0) throw UsageError("--orbit-degrees is the arc of --orbit N's cameras; give --orbit");
    if (path && !s.given())
        throw UsageError("a camera path (--orbit, --walkthrough) or --time-steps renders a sequence: give --out-sequence PATTERN");
    if (s.given() && !path)
        throw UsageError("--out-sequence writes a sequence's frames: give --orbit N, --walkthrough or --time-steps N");
    if (s.given()) sequenceFrameName(s.pattern, 0);  // one integer conversion, or a usage error
    return s;
}

std::vector<Camera> RenderSequence::cameras(const Camera& base, const Scene& scene) const {
    std::vector<Camera> cameras;
    if (timeSteps > 0) {
        cameras.assign(static_cast<size_t>(timeSteps), base);
    } else if (walkthrough) {
        if (scene.cameraPath.size() < 2)
            throw Error("--walkthrough: the scene '" + scene.name + "' has no camera.path (docs/scene-format.md)");
        const CameraPath path = CameraPath::keyframes(base, scene.cameraPath);
        for (const auto& k : scene.cameraPath) cameras.push_back(path.atTime(k.time));
    } else {
        const CameraPath path = CameraPath::orbit(base, orbit, orbitDegrees);
        for (int k = 0; k < orbit; ++k) cameras.push_back(path.at(k, orbit));
    }
    return cameras;
}

}  // namespace dw
