#pragma once
// A GL fence sync object (glFenceSync): placed in the command stream, it is
// signalled when the GPU has finished every command before it. Move-only.
#include <epoxy/gl.h>

namespace dw::gl {

class Fence {
public:
    Fence() = default;
    // A fence after every command issued so far.
    static Fence insert();
    ~Fence();
    Fence(Fence&& other) noexcept : sync_(other.sync_) { other.sync_ = nullptr; }
    Fence& operator=(Fence&& other) noexcept;
    Fence(const Fence&) = delete;
    Fence& operator=(const Fence&) = delete;

    // Blocks until the GPU has passed the fence (flushing first, so it gets there).
    void wait() const;

private:
    GLsync sync_ = nullptr;
};

// Waits until the GPU has finished everything issued so far.
void waitForGpu();

}  // namespace dw::gl
