#pragma once
// Immutable-storage buffer object (vertex, index, uniform or storage data).
// Its bytes are counted in the MemoryLedger under the MemoryOwner in scope
// when it is created (ensureSize's re-creation: again, under today's owner).
#include <cstddef>
#include <vector>

#include "renderer/gl/GlObject.h"
#include "renderer/gl/MemoryLedger.h"

namespace dw::gl {

class Buffer {
public:
    Buffer() = default;
    // Dynamic buffers accept update(); static ones are written once.
    static Buffer create(std::size_t bytes, const void* data, bool dynamic, const char* label = nullptr);
    template <typename T>
    static Buffer fromVector(const std::vector<T>& v, bool dynamic = false, const char* label = nullptr) {
        return create(v.size() * sizeof(T), v.data(), dynamic, label);
    }

    GLuint id() const { return name_.id(); }
    explicit operator bool() const { return static_cast<bool>(name_); }
    std::size_t size() const { return size_; }
    void update(std::size_t offset, std::size_t bytes, const void* data);
    // Grows (re-creates) a dynamic buffer if it is smaller than bytes.
    void ensureSize(std::size_t bytes, const char* label = nullptr);
    void bindBase(GLenum target, GLuint index) const;
    void bindRange(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const;
    void read(std::size_t offset, std::size_t bytes, void* out) const;
    // Every 32-bit word to `value`.
    void clearUint(unsigned value) const;

private:
    GlObject<BufferTraits> name_;
    LedgerTicket ticket_;
    std::size_t size_ = 0;
    bool dynamic_ = false;
};

}  // namespace dw::gl
