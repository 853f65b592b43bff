#include "app/CompareInput.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "headless/HeadlessGlContext.h"
#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/ao/AovCostEstimate.h"
#include "renderer/io/ImageLimits.h"
#include "renderer/metrics/ComparisonMemory.h"
#include "renderer/reference/ReferenceCache.h"
#include "renderer/reference/ReferenceRenderer.h"
#include "renderer/scene/FlameParticles.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

CompareInputs::CompareInputs() = default;
CompareInputs::~CompareInputs() = default;

bool CompareInputs::isHdrFile(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".exr" || ext == ".hdr" || ext == ".pfm";
}

void CompareInputs::checkMemory(const std::string& path) {
    const ImageShape shape = readImageShape(path);  // the header only
    if (const std::string why = comparison_memory::refusal(shape.width, shape.height, shape.channels); !why.empty())
        throw FileError(path, "the image is " + why);
}

CompareImage CompareInputs::produce(const CompareInput& input) {
    CompareImage out;
    out.label = input.label;
    if (input.kind == CompareInput::Kind::File) {
        checkMemory(input.path);                 // before a pixel is decoded
        out.image = loadImageFloat(input.path);  // FileError names the file and why
        out.hdr = isHdrFile(input.path);
        out.describe = "file " + input.path + (out.hdr ? " (HDR)" : " (LDR)");
        return out;
    }
    const std::string spec = input.run.sceneSpec();
    if (!loaded_ || loadedSpec_ != spec) {
        loaded_ = loadScene(spec);
        loadedSpec_ = spec;
    }
    if (input.kind == CompareInput::Kind::Reference) return produceReference(input);
    // A render: the same run configuration, session and frame loop as `render`.
    if (!context_) context_ = HeadlessGlContext::create();
    // A fresh session per side: each starts at frame 0 with no state from the
    // other (flame particles move with the frame index).
    session_.reset();
    session_ = std::make_unique<RenderSession>();
    session_->setScene(*loaded_, input.run);
    session_->resize(input.run.width, input.run.height);
    // AOV's cost estimated from the triangles before the side's first frame, as render does (issue 22).
    if (const std::string w = AovCostEstimate::check(session_->knobs(), session_->scene(), session_->camera(),
                                                     input.run.width, input.run.height);
        !w.empty())
        std::fprintf(stderr, "compare: warning: side %s: %s\n", input.label.c_str(), w.c_str());
    FrameRequest request;
    request.outputs = {input.buffer};
    FrameReport last;
    for (int i = 0; i < input.run.warmup + input.run.frames; ++i) last = session_->render(request);
    // What a pass lost in the frame compared (the oit pass's fragments), as render says it.
    for (const std::string& w : last.warnings())
        std::fprintf(stderr, "compare: warning: side %s: %s\n", input.label.c_str(), w.c_str());
    out.hdr = input.buffer != "final";
    out.image = out.hdr ? session_->readRaw(input.buffer) : session_->readDisplay(input.buffer);
    out.describe = "render of " + session_->scene().name + ", " + input.buffer + ", " + std::to_string(input.run.width) +
                   "x" + std::to_string(input.run.height) + (out.hdr ? " (HDR)" : " (LDR)");
    for (const std::string& s : input.run.sets) out.describe += ", --set " + s;
    return out;
}

std::string CompareInputs::referenceBufferFor(const std::string& buffer) {
    if (buffer == "final" || buffer == "lbuffer") return buffer;
    if (buffer == "ao" || buffer == "ao.raw" || buffer == "ao.filtered") return "ao";
    if (buffer == "shadow" || buffer == "lighting.shadow") return "shadow";
    throw Error("--against reference: the reference has no counterpart of buffer '" + buffer +
                "' (final, lbuffer, ao (ao.filtered) / ao.raw against its ray-traced AO, or shadow "
                "(lighting.shadow) against its shadow rays)");
}

CompareImage CompareInputs::produceReference(const CompareInput& input) {
    const std::string name = referenceBufferFor(input.buffer);
    // The scene as the render's last frame has it: flame particles (fire) move with the frame index.
    Scene scene = *loaded_;
    animateFlameParticles(scene, static_cast<std::uint64_t>(input.run.warmup + input.run.frames - 1));
    for (const auto& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    KnobRegistry knobs = RunConfig::declaredKnobs();
    input.run.applyKnobs(knobs, scene);
    reference::ReferenceModel model = reference::ReferenceModel::fromKnobs(knobs, scene);
    model.aoRays = input.aoRays;
    reference::ReferenceRequest request;
    request.camera = input.run.camera(scene);
    request.width = input.run.width;
    request.height = input.run.height;
    const reference::ReferenceCache cache;
    const std::string key = reference::referenceKey(scene, model, request);
    std::optional<reference::ReferenceImages> images = cache.load(key);
    const bool cached = images.has_value();
    if (!cached) {
        std::fprintf(stderr, "rendering the CPU reference (%dx%d, %d AO rays; cached for the next run)...\n",
                     request.width, request.height, model.rayTracedAo ? model.aoRays : 0);
        images = reference::renderReference(scene, model, request);
        try {
            cache.store(key, *images);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "warning: the reference is not cached: %s\n", e.what());
        }
    }
    const reference::KnobReport report = reference::reportKnobs(knobs, model);
    if (!report.unmodelledOn.empty() && name == "final") {
        std::string on;
        for (const auto& k : report.unmodelledOn) on += " " + k;
        std::fprintf(stderr, "note: the reference's final image has no%s (set them false, aa.method none, on the render to compare "
                     "the shading alone)\n", on.c_str());
    }
    CompareImage out;
    out.label = input.label;
    out.image = *images->buffer(name);
    out.hdr = name != "final";
    out.describe = "CPU reference of " + scene.name + ", " + name + ", " + std::to_string(request.width) + "x" +
                   std::to_string(request.height) + (out.hdr ? " (HDR)" : " (LDR)") +
                   (model.rayTracedAo ? ", " + std::to_string(model.aoRays) + " AO rays" : std::string()) +
                   (cached ? ", from the cache" : "");
    return out;
}

}  // namespace dw
