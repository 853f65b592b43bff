#pragma once
// `render --orbit N [--orbit-degrees D] | --walkthrough --out-sequence PATTERN`:
// a camera path's frames, rendered in order by one session (a temporal
// method's history carried from frame to frame, after --warmup frames at the
// first camera), frame k written to PATTERN's file k (one integer conversion,
// as compare --sequence reads it: frames/f%03d.png). The path is tradeoff's:
// N cameras on an orbit about the run's camera, D / N degrees apart (default
// 360), or the scene's camera.path keyframes. A reference buffer
// (reference.final ...) is traced for each camera.
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
    std::string pattern;  // --out-sequence; empty: no sequence
    bool given() const { return !pattern.empty(); }

    // Reads --orbit, --orbit-degrees, --walkthrough and --out-sequence (before
    // cl.finish()). UsageError for a path without --out-sequence or the
    // reverse, both paths, --orbit-degrees without --orbit, or a pattern
    // without one integer conversion.
    static RenderSequence read(CommandLine& cl);
    // The path's cameras about `base`; Error for --walkthrough on a scene
    // without a camera.path.
    std::vector<Camera> cameras(const Camera& base, const Scene& scene) const;
};

}  // namespace dw
