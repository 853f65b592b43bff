#pragma once
// Frame captures with RenderDoc through its in-app API (renderdoc_app.h from
// Debian's librenderdoc-dev). When the process already runs under RenderDoc
// (qrenderdoc or renderdoccmd launched it, or LD_PRELOAD) the API is found.
// RenderDoc hooks GL only when it is preloaded (a dlopen at run time does not
// reach libEGL/libGL, which libepoxy opens itself), so gui --renderdoc and
// render --renderdoc-capture start the process again with
// LD_PRELOAD=librenderdoc.so (relaunchUnderRenderDoc) before any GL exists.
// Captures go to a path template RenderDoc completes ("_frameN.rdc" for the
// window's frames, "_capture.rdc" for a headless one). Without RenderDoc
// every call is harmless and `why()` says how to get it.
#include <string>

namespace dw {

class RenderDocCapture {
public:
    // Whether librenderdoc.so is in this process.
    static bool injected();
    // Not injected yet: exec this program again, same arguments, with
    // librenderdoc.so preloaded; returns only on failure, with the reason.
    // Injected already (or after the relaunch): returns "" at once.
    static std::string relaunchUnderRenderDoc(char** argv);
    // Finds RenderDoc's API in this process (loads the library when `load`,
    // which then can capture only what GL it can still hook).
    static RenderDocCapture attach(bool load);
    bool available() const { return api_ != nullptr; }
    // Why there is none: what to install or how to start the process.
    const std::string& why() const { return why_; }

    // Captures are written as <pathTemplate>_frameN.rdc (RenderDoc's rule).
    void setPathTemplate(const std::string& pathTemplate);
    // The window: capture the next frame presented (glfwSwapBuffers).
    void triggerCapture();
    // Headless: everything between start and end on the current context.
    void startFrameCapture();
    // Returns false when RenderDoc recorded nothing.
    bool endFrameCapture();
    int captureCount() const;
    // The newest capture's file, "" when none.
    std::string lastCapturePath() const;

private:
    void* api_ = nullptr;  // RENDERDOC_API_1_4_1*, kept opaque so the header stays free of renderdoc_app.h
    std::string why_;
};

}  // namespace dw
