#pragma once
// `render --orbit N [--orbit-degrees D] | --walkthrough --out-sequence PATTERN`:
// a camera path's frames, rendered in order by one session (a temporal
// method's history carried from frame to frame, after --warmup frames at the
// first camera), frame k written to PATTERN's file k (one integer conversion,
// as compare --sequence reads it: frames/f%03d.png). The path is tradeoff's:
// N cameras on an orbit about the run's camera, D / N degrees apart (default
// 360), or the scene's camera.path keyframes. A reference buffer
// (reference.final ...) is traced for each camera. `--time-steps N
// [--frame-rate F]` instead: N frames at the run's camera, frame k at scene
// time --scene-time + k / F seconds (an animated scene's frames; F default 30).
#include <string>
#include <vector>

#include "headless/CommandLine.h"
#include "renderer/scene/Camera.h"
#include "renderer/scene/Scene.h"

namespace dw {

struct RenderSequence {
    int orbit = 0;
    double orbitDegrees = 360.0;
    bool walkthrough = false;
    int timeSteps = 0;        // --time-steps N: frames over scene time at one camera
    double frameRate = 30.0;  // --frame-rate F (frames per second of scene time)
    std::string pattern;  // --out-sequence; empty: no sequence
    bool given() const { return !pattern.empty(); }

    // Reads --orbit, --orbit-degrees, --walkthrough, --time-steps,
    // --frame-rate and --out-sequence (before cl.finish()). UsageError for a
    // path without --out-sequence or the reverse, two paths, --orbit-degrees
    // without --orbit, --frame-rate without --time-steps, or a pattern without
    // one integer conversion.
    static RenderSequence read(CommandLine& cl);
    // The path's cameras about `base`; Error for --walkthrough on a scene
    // without a camera.path.
    // (--time-steps: N copies of `base`.)
    std::vector<Camera> cameras(const Camera& base, const Scene& scene) const;
    // Frame k's scene time (seconds): `start` + k / F with --time-steps, else `start`.
    double sceneTime(double start, size_t k) const {
        return timeSteps > 0 ? start + static_cast<double>(k) / frameRate : start;
    }
};

}  // namespace dw
