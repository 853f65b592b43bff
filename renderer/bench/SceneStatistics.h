#pragma once
// Seed 000 table 6.1's statistics of a scene: objects (separate draws, the
// seed's "geometry batches": mesh instances), triangles (over every
// instance), lights (enabled, by type) and lights per pixel (LPP) over a
// walk-through of the camera: the scene's keyframed camera.path when it has
// one, else `poses` poses on the orbit through its camera (CameraPath).
// LPP is the mean of lighting.overlap (light-shader invocations per pixel,
// as bench's LPP column) over every pixel of every pose; "LPP lit" over the
// surface pixels at least one light reached; the poses' smallest and largest
// LPP are its range. `list scenes --stats` prints them (docs/bench.md).
#include <string>

#include "renderer/RunConfig.h"
#include "renderer/scene/Scene.h"

namespace dw {

class RenderSession;

struct SceneStatistics {
    std::string scene;  // the scene's name
    size_t objects = 0;
    size_t triangles = 0;
    int lights = 0, directional = 0, point = 0, spot = 0;
    int poses = 0;  // 0: LPP not measured
    double lpp = 0.0, lppMin = 0.0, lppMax = 0.0, lppLit = 0.0;
};

// Objects, triangles and lights: no GL.
SceneStatistics countScene(const Scene& scene);
// Adds LPP over the walk-through (`poses` >= 1 for an orbit; a camera.path
// takes `poses` evenly spaced times) at the session's render size, rendering
// with the session's knobs and scene; the camera is put back afterwards.
void measureLightsPerPixel(RenderSession& session, int poses, SceneStatistics& stats);

}  // namespace dw
