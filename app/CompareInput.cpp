#include "app/CompareInput.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "app/HeadlessGlContext.h"
#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/scene/SceneLoader.h"

namespace dw {

CompareInputs::CompareInputs() = default;
CompareInputs::~CompareInputs() = default;

bool CompareInputs::isHdrFile(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".exr" || ext == ".hdr" || ext == ".pfm";
}

CompareImage CompareInputs::produce(const CompareInput& input) {
    CompareImage out;
    out.label = input.label;
    if (input.kind == CompareInput::Kind::File) {
        out.image = loadImageFloat(input.path);  // FileError names the file and why
        out.hdr = isHdrFile(input.path);
        out.describe = "file " + input.path + (out.hdr ? " (HDR)" : " (LDR)");
        return out;
    }
    // A render: the same run configuration, session and frame loop as `render`.
    const std::string spec = input.run.sceneSpec();
    if (!loaded_ || loadedSpec_ != spec) {
        loaded_ = loadScene(spec);
        loadedSpec_ = spec;
    }
    if (!context_) context_ = HeadlessGlContext::create();
    // A fresh session per side: each starts at frame 0 with no state from the
    // other (flame particles move with the frame index).
    session_.reset();
    session_ = std::make_unique<RenderSession>();
    session_->setScene(*loaded_, input.run);
    session_->resize(input.run.width, input.run.height);
    FrameRequest request;
    request.outputs = {input.buffer};
    for (int i = 0; i < input.run.warmup + input.run.frames; ++i) session_->render(request);
    out.hdr = input.buffer != "final";
    out.image = out.hdr ? session_->readRaw(input.buffer) : session_->readDisplay(input.buffer);
    out.describe = "render of " + session_->scene().name + ", " + input.buffer + ", " + std::to_string(input.run.width) +
                   "x" + std::to_string(input.run.height) + (out.hdr ? " (HDR)" : " (LDR)");
    for (const std::string& s : input.run.sets) out.describe += ", --set " + s;
    return out;
}

}  // namespace dw
