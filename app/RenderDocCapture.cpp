#include "app/RenderDocCapture.h"

#include <dlfcn.h>
#include <epoxy/egl.h>

#ifdef DW_HAVE_RENDERDOC
#include <renderdoc_app.h>
#endif

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace dw {

bool RenderDocCapture::injected() { return dlopen("librenderdoc.so", RTLD_NOW | RTLD_NOLOAD) != nullptr; }

std::string RenderDocCapture::relaunchUnderRenderDoc(char** argv) {
    if (injected()) return {};
    // Once only: a relaunched process that still has no RenderDoc says why.
    if (std::getenv("DW_RENDERDOC_RELAUNCHED"))
        return "librenderdoc.so was preloaded but is not in the process; install Debian's librenderdoc package";
    if (void* probe = dlopen("librenderdoc.so", RTLD_LAZY | RTLD_LOCAL)) {
        dlclose(probe);
    } else {
        return std::string("cannot find librenderdoc.so (") + dlerror() + "); install Debian's librenderdoc package";
    }
    const char* old = std::getenv("LD_PRELOAD");
    const std::string preload = old && *old ? std::string("librenderdoc.so:") + old : std::string("librenderdoc.so");
    setenv("LD_PRELOAD", preload.c_str(), 1);
    setenv("DW_RENDERDOC_RELAUNCHED", "1", 1);
    std::fflush(nullptr);
    execv("/proc/self/exe", argv);
    return std::string("cannot start again under RenderDoc: ") + std::strerror(errno);
}

#ifdef DW_HAVE_RENDERDOC

namespace {
RENDERDOC_API_1_4_1* rdoc(void* api) { return static_cast<RENDERDOC_API_1_4_1*>(api); }
}  // namespace

RenderDocCapture RenderDocCapture::attach(bool load) {
    RenderDocCapture c;
    // Already injected (launched from qrenderdoc / renderdoccmd capture)?
    void* lib = dlopen("librenderdoc.so", RTLD_NOW | RTLD_NOLOAD);
    if (!lib && load) lib = dlopen("librenderdoc.so", RTLD_NOW);
    if (!lib) {
        c.why_ = load ? std::string("cannot load librenderdoc.so (") + dlerror() +
                            "); install Debian's librenderdoc package (or renderdoc)"
                      : "not running under RenderDoc: start the workbench with --renderdoc (Debian package librenderdoc), "
                        "or launch it from qrenderdoc / 'renderdoccmd capture'";
        return c;
    }
    auto getApi = reinterpret_cast<pRENDERDOC_GetAPI>(dlsym(lib, "RENDERDOC_GetAPI"));
    void* api = nullptr;
    if (!getApi || getApi(eRENDERDOC_API_Version_1_4_1, &api) != 1 || !api) {
        c.why_ = "librenderdoc.so is loaded but offers no in-app API 1.4.1";
        return c;
    }
    c.api_ = api;
    // Our own UI shows what RenderDoc's overlay would.
    rdoc(api)->MaskOverlayBits(eRENDERDOC_Overlay_None, eRENDERDOC_Overlay_None);
    return c;
}

void RenderDocCapture::setPathTemplate(const std::string& pathTemplate) {
    if (api_) rdoc(api_)->SetCaptureFilePathTemplate(pathTemplate.c_str());
}

void RenderDocCapture::triggerCapture() {
    if (api_) rdoc(api_)->TriggerCapture();
}

// A headless context has no window for RenderDoc to pick: name the device,
// which for OpenGL is the context itself.
void RenderDocCapture::startFrameCapture() {
    if (api_) rdoc(api_)->StartFrameCapture(eglGetCurrentContext(), nullptr);
}

bool RenderDocCapture::endFrameCapture() { return api_ && rdoc(api_)->EndFrameCapture(eglGetCurrentContext(), nullptr) == 1; }

int RenderDocCapture::captureCount() const { return api_ ? static_cast<int>(rdoc(api_)->GetNumCaptures()) : 0; }

std::string RenderDocCapture::lastCapturePath() const {
    const int n = captureCount();
    if (n == 0) return {};
    std::uint32_t length = 0;
    if (rdoc(api_)->GetCapture(static_cast<std::uint32_t>(n - 1), nullptr, &length, nullptr) != 1 || length == 0) return {};
    std::vector<char> path(length + 1, '\0');
    rdoc(api_)->GetCapture(static_cast<std::uint32_t>(n - 1), path.data(), &length, nullptr);
    return path.data();
}

#else

RenderDocCapture RenderDocCapture::attach(bool) {
    RenderDocCapture c;
    c.why_ = "this build has no RenderDoc support: install Debian's librenderdoc-dev and rebuild "
             "(scripts/setup-deps.sh does), then run with --renderdoc";
    return c;
}
void RenderDocCapture::setPathTemplate(const std::string&) {}
void RenderDocCapture::triggerCapture() {}
void RenderDocCapture::startFrameCapture() {}
bool RenderDocCapture::endFrameCapture() { return false; }
int RenderDocCapture::captureCount() const { return 0; }
std::string RenderDocCapture::lastCapturePath() const { return {}; }

#endif

}  // namespace dw
