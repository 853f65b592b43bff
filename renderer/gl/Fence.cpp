#include "renderer/gl/Fence.h"

#include <utility>

namespace dw::gl {

Fence Fence::insert() {
    Fence f;
    f.sync_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    return f;
}

Fence::~Fence() {
    if (sync_) glDeleteSync(sync_);
}

Fence& Fence::operator=(Fence&& other) noexcept {
    if (this != &other) {
        if (sync_) glDeleteSync(sync_);
        sync_ = std::exchange(other.sync_, nullptr);
    }
    return *this;
}

void Fence::wait() const {
    if (!sync_) return;
    // One second at a time: a slow software rasteriser may take longer than any single timeout.
    constexpr GLuint64 kTimeoutNs = 1'000'000'000;
    GLbitfield flags = GL_SYNC_FLUSH_COMMANDS_BIT;
    for (;;) {
        const GLenum r = glClientWaitSync(sync_, flags, kTimeoutNs);
        if (r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED || r == GL_WAIT_FAILED) return;
        flags = 0;
    }
}

void waitForGpu() { Fence::insert().wait(); }

}  // namespace dw::gl
