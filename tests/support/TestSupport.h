#pragma once
// Shared helpers for the test binaries: the headless GL context, small scenes
// built in code, image statistics, and paths to test data.
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "renderer/io/ImageIO.h"
#include "renderer/RenderSession.h"
#include "renderer/reference/ShadingReference.h"
#include "renderer/scene/Scene.h"

namespace dw::test {

// Creates the process-wide headless context (gl/main.cpp calls this once).
void initGl();
// A session with the project's shaders, at `width` x `height`.
std::unique_ptr<RenderSession> makeSession(int width, int height);
// Builds every variant of the buffer view's programs (BufferView compiles
// one per source kind and value type when first needed), so the tests that
// go through every program (ParamBlocks, Bindings) see them all.
void buildBufferViewVariants(gl::ShaderLibrary& shaders);
// A program's stages and defines, for a failure message: "a.vert  b.frag  -DX".
std::string describeProgram(const gl::ProgramDesc& d);
// Each line on its own indented line, for a failure message.
std::string indentedLines(const std::vector<std::string>& lines);

// A large matte plane at y = 0 seen from above and in front, no lights.
Scene planeScene(float size = 40.0f);
// Adds a light and returns it for further edits.
Light& addPointLight(Scene& s, glm::vec3 pos, glm::vec3 intensity, Attenuation att);
Light& addSpotLight(Scene& s, glm::vec3 pos, glm::vec3 dir, float cutoff, float exponent, glm::vec3 intensity,
                    Attenuation att);

// Boxes on a floor among 12 overlapping point lights and 4 spots (and a dim
// sun when `withSun`): the lighting tests' common scene.
// Adds an opaque Blinn-Phong material; returns its index.
int addBlinnPhong(Scene& s, glm::vec3 diffuse, glm::vec3 specular, float exponent);
Scene boxesScene(bool withSun);
// 200 small lights (radius 1 to 2, every 9th a spot) on a jittered grid over
// part of a floor with 6 boxes, straddling box edges, screen tiles and depth
// slices; the first `shadowed` of every 67th cast shadows.
Scene straddleScene(int shadowed);

std::filesystem::path dataDir();       // ../shared/data (may not exist)
std::filesystem::path goldenDir();
std::filesystem::path scenesDir();
std::filesystem::path tempDir();       // a fresh directory per test binary run

// Runs the deferred-workbench binary with `args` (a shell command line's
// arguments) and returns its exit code, standard output and standard error.
struct CommandResult {
    int code = -1;
    std::string out, err;
};
CommandResult runWorkbench(const std::string& args);
// Runs a shell command line the same way.
CommandResult runCommand(const std::string& command);

// A --dump-knobs file: knob name -> value text; the "# scene <source>" line
// as key "#scene". Empty when the file does not exist.
std::map<std::string, std::string> readKnobDump(const std::filesystem::path& path);

// The last frame's G-buffer as the CPU shading reference reads it: view
// position (w = 0 where no surface), view normal, albedo and specular (its
// alpha the encoded exponent). The frame must have produced
// gbuffer.view_position and gbuffer.view_normal.
struct GBufferImages {
    FloatImage position, normal, albedo, specular;
    bool surface(int x, int y) const { return position.at(x, y, 3) != 0.0f; }
    // The surface at a pixel, the exponent decoded as geometry.frag encodes it.
    reference::SurfacePoint at(int x, int y) const;
};
GBufferImages readGBuffer(const RenderSession& session);
// reference::shadeLight summed over `lights` that reach `threshold` (their
// volume radii), in the view of `worldToView` (the frame's matrix).
glm::dvec3 referenceRadiance(const std::vector<Light>& lights, const glm::dmat4& worldToView,
                             const reference::SurfacePoint& s, double threshold,
                             reference::AttenuationModel model = reference::AttenuationModel::Classic,
                             double windowExponent = 20.0);

struct ChannelStats {
    double mean = 0, max = 0, min = 0;
    long long nonFinite = 0;
};
ChannelStats stats(const FloatImage& img, int channel);
double maxAbsDifference(const FloatImage& a, const FloatImage& b, int channels, int* worstX = nullptr, int* worstY = nullptr);

// The fraction of pixels whose R, G or B in `b` is off from `a` by more than
// relative * |a| + absolute (the invariance bound of the extremes tests).
double fractionOff(const FloatImage& a, const FloatImage& b, float relative = 0.02f, float absolute = 0.002f);

// Why this test binary cannot run a RenderDoc capture, or "" when it can.
// Under AddressSanitizer (scripts/test.sh --sanitize) the workbench starts
// again with librenderdoc.so in LD_PRELOAD, ahead of ASan's runtime, and ASan
// stops the process at start-up ("ASan runtime does not come first in initial
// library list"): the capture cannot be tested there, only in the plain build.
inline std::string renderDocCaptureUnavailable() {
#if defined(__SANITIZE_ADDRESS__)
    return "AddressSanitizer build: librenderdoc.so, preloaded ahead of ASan's runtime, stops the process at start-up "
           "(the capture is tested in the plain build)";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return "AddressSanitizer build: librenderdoc.so, preloaded ahead of ASan's runtime, stops the process at start-up "
           "(the capture is tested in the plain build)";
#else
    return "";
#endif
#else
    return "";
#endif
}

}  // namespace dw::test
