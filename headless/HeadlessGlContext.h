#pragma once
// An OpenGL 4.5 core context without a window, through EGL: the device
// platform (NVIDIA, or Mesa's software device) or Mesa's surfaceless platform.
// DW_EGL_PLATFORM=device|surfaceless|default forces one.
#include <memory>
#include <string>

namespace dw {

class HeadlessGlContext {
public:
    // Creates the context and makes it current. Throws GlUnsupportedError with
    // what was tried and why each failed.
    static std::unique_ptr<HeadlessGlContext> create();
    ~HeadlessGlContext();
    HeadlessGlContext(const HeadlessGlContext&) = delete;
    HeadlessGlContext& operator=(const HeadlessGlContext&) = delete;

    const std::string& platform() const { return platform_; }
    void makeCurrent();

private:
    HeadlessGlContext() = default;
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string platform_;
};

}  // namespace dw
