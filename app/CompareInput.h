#pragma once
// One side of `deferred-workbench compare`: what it is (a file, or a render of
// a run configuration) and how it becomes an image of known kind (HDR or LDR),
// so the command treats every side alike and a new kind of side (the Embree
// reference) is one more Kind and one more branch in CompareInputs::produce.
#include <memory>
#include <optional>
#include <string>

#include "renderer/RunConfig.h"
#include "renderer/io/ImageIO.h"
#include "renderer/metrics/Flip.h"
#include "renderer/scene/Scene.h"

namespace dw {

class HeadlessGlContext;
class RenderSession;

struct CompareInput {
    // Reference: the CPU ground truth (renderer/reference) of `run`, its
    // buffer matching `buffer` (final, lbuffer; ao.raw / ao.filtered ->
    // its ray-traced AO), through the reference cache.
    enum class Kind { File, Render, Reference };
    Kind kind = Kind::File;
    std::string path;             // File: the image file
    RunConfig run;                // Render: scene, preset, --set (base then this side's), size, frames
    std::string buffer = "final"; // Render: the output read back
    std::string label;            // how messages and the JSON name this side ("a.png", "--a")
    int aoRays = 64;              // Reference: AO rays per pixel
};

struct CompareImage {
    FloatImage image;
    // HDR: linear radiance (EXR/HDR/PFM files; a render's raw float buffer
    // other than `final`). LDR: display values in [0, 1] (8-bit files; the
    // final image as its .png would hold it).
    bool hdr = false;
    std::string label;
    std::string describe;  // one phrase: "file a.png (LDR)", "render of spheres, final, 160x90, --set x=1"
};

// Produces the sides; renders share one GL context and the loaded scene.
class CompareInputs {
public:
    CompareInputs();
    ~CompareInputs();
    // Throws FileError when a file (image, scene or preset) cannot be read,
    // Error for anything else (an unknown buffer, a knob value).
    CompareImage produce(const CompareInput& input);

    // Throws FileError naming `path` and its size when the image memory
    // budget does not hold comparing it (renderer/metrics/ComparisonMemory),
    // its shape read from the header: nothing is decoded.
    static void checkMemory(const std::string& path);

    // HDR by a file's extension: .exr, .hdr, .pfm.
    static bool isHdrFile(const std::string& path);
    // The reference buffer a render's buffer is compared with; throws Error when there is none.
    static std::string referenceBufferFor(const std::string& buffer);

private:
    CompareImage produceReference(const CompareInput& input);
    std::unique_ptr<HeadlessGlContext> context_;
    std::unique_ptr<RenderSession> session_;
    std::string loadedSpec_;
    std::optional<Scene> loaded_;
};

}  // namespace dw
