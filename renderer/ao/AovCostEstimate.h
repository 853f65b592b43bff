#pragma once
// What an Ambient Occlusion Volumes frame (ao.method = aov, renderer/ao/
// AovMethod) will cost, estimated on the CPU from the scene's triangles and
// the camera before anything is drawn (issue 22: a 202k-triangle model at
// aov.radius 1 ran for minutes with no word).
//
// Every opaque or MASK triangle extrudes a prism of depth delta (McGuire 2010;
// seed 000 4.6.4, figure 4.9; the same corners as shaders/ao/aov_volume.geom),
// and the rasteriser draws one face layer of it (its front faces, or its back
// faces when it reaches the camera), i.e. its projected outline. So the
// volume fragments per pixel are the sum over volumes of the outline's area,
// clipped to the screen, over the screen's area: `meanOverdraw`. Volumes
// outside the view frustum add 0 (the geometry shader culls them); a volume
// with a corner behind the near plane counts as the whole screen (its back
// faces may cover it: an upper bound). It counts rasterised fragments before
// the depth and stencil tests, so it is an upper bound of aov.overdraw's mean
// (which counts the fragments that passed; docs/aov.md gives both on the
// dragon and the courtyard). Cost: O(triangles), about 0.2-0.5 us per volume.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>

#include <glm/glm.hpp>

namespace dw {

class KnobRegistry;
struct Scene;
struct Camera;

struct AovCostEstimate {
    // Mean volume fragments per pixel (dimensionless; the same at any size).
    double meanOverdraw = 0.0;
    std::size_t volumes = 0;     // volumes extruded (double-sided triangles count twice)
    std::size_t culled = 0;      // of them, wholly outside the view frustum
    std::size_t nearCamera = 0;  // of them, reaching the near plane (counted as the whole screen)
    float radius = 0.0f;         // delta in world units

    // Volume fragments per frame at an accessibility buffer of w x h pixels.
    double fragments(int aoWidth, int aoHeight) const {
        return meanOverdraw * static_cast<double>(aoWidth) * static_cast<double>(aoHeight);
    }

    // The estimate for `scene` seen with `view` and `projection` (any
    // perspective projection, OpenGL or [0, 1] depth) whose near plane is
    // `nearPlane` from the eye, volumes of depth `radius` (world units, > 0).
    // Blended triangles cast no volume.
    static AovCostEstimate compute(const Scene& scene, const glm::mat4& view, const glm::mat4& projection,
                                   float nearPlane, float radius);

    // The limits above which render, bench, tradeoff and the window warn (and
    // the window asks before it renders). Measured on llvmpipe, 2 threads
    // shared with other builds (docs/aov.md): 2.5 to 15 us per estimated
    // volume fragment, depending on the load, so 4 million fragments are 10 s
    // to a minute a frame; a mean of 1000 a pixel is the seed's "hundreds of
    // full-screen passes" whatever the size.
    static constexpr double kWarnOverdraw = 1000.0;
    static constexpr double kWarnFragments = 4e6;
    // The measured time per estimated volume fragment on llvmpipe (seconds),
    // lightly and heavily loaded: the warning's time range for a frame.
    static constexpr double kSecondsPerFragmentLow = 2.5e-6;
    static constexpr double kSecondsPerFragmentHigh = 15e-6;
    // "about 10 s to 1 minute": the frame's time range from its fragments
    // at the two rates above (seconds, minutes or hours, each rounded).
    static std::string timeRange(double fragments);
    // Whether `e` at an accessibility buffer of w x h pixels exceeds either limit.
    static bool exceeds(const AovCostEstimate& e, int aoWidth, int aoHeight) {
        return e.meanOverdraw > kWarnOverdraw || e.fragments(aoWidth, aoHeight) > kWarnFragments;
    }

    // The knobs' estimate for `scene` and `camera` at a w x h frame, when
    // they ask for AOV (ao.enabled and ao.method = aov); nothing otherwise.
    // Reads aov.radius, aov.radius_unit and aov.resolution.
    static std::optional<AovCostEstimate> forKnobs(const KnobRegistry& knobs, const Scene& scene,
                                                   const Camera& camera, int width, int height);
    // The accessibility buffer's size for a w x h frame under aov.resolution.
    static std::pair<int, int> aoSize(const KnobRegistry& knobs, int width, int height);
    // One line naming the estimate, this frame's time range on llvmpipe
    // (timeRange) and the knobs that lower it, when it
    // exceeds a limit at the frame's accessibility buffer (`width` x
    // `height` the frame); empty otherwise.
    static std::string warning(const AovCostEstimate& e, const KnobRegistry& knobs, int width, int height);
    // forKnobs and warning in one: the line to print, or empty.
    static std::string check(const KnobRegistry& knobs, const Scene& scene, const Camera& camera, int width,
                             int height);
};

}  // namespace dw
