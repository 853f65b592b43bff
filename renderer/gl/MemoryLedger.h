#pragma once
// The process-wide count of GPU memory the GL wrapper allocated: every
// Buffer and Texture storage allocation (glNamedBufferStorage,
// glTextureStorage2D/3D/2DMultisample; a re-allocation is a delete and a new
// allocation) adds its bytes under an owner label and the object's deletion
// subtracts them. Texture views and buffer textures own no storage and are not
// counted. The owner is the innermost live MemoryOwner scope on the allocating
// thread ("unowned" when none: a test asserts there is none after a frame).
//
// Bytes are the LOGICAL size: texel bytes (the format table in
// texelBytes) x width x height x depth or layers x samples, summed over
// the mip levels (a level halves width, height and, for 3D, depth; each
// at least 1); a buffer's size as created. Not the driver's padded,
// compressed or aligned size, which GL does not report.
#include <epoxy/gl.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dw::gl {

// Bytes of one texel of a sized internal format; 0 for a format the table
// lacks (the ledger then counts 4 bytes a texel and names it in
// MemoryLedger::unknownFormats, which a test asserts empty).
std::size_t texelBytes(GLenum internalFormat);

// Logical bytes of a texture's storage. `depthOrLayers`: a 3D texture's depth
// (halved per level), an array's layers (a cube map array's 6 x cubes; not
// halved); a cube map counts 6 faces itself. `samples` 0 or 1: single-sampled.
std::size_t textureStorageBytes(GLenum target, GLenum internalFormat, int width, int height, int depthOrLayers,
                                int levels, int samples);

// One live allocation.
struct LedgerEntry {
    std::uint64_t ticket = 0;
    std::string owner;
    const char* kind = "";  // "buffer" or "texture"
    GLuint id = 0;          // the GL name (per context)
    std::size_t bytes = 0;
};

// Live bytes and objects of one owner label.
struct OwnerBytes {
    std::string owner;
    std::size_t bytes = 0;
    int objects = 0;
};

class MemoryLedger {
public:
    static MemoryLedger& instance();
    // Records an allocation under the current owner; returns its ticket.
    std::uint64_t add(const char* kind, GLuint id, std::size_t bytes);
    void remove(std::uint64_t ticket);
    std::size_t liveBytes() const;
    std::size_t liveObjects() const;
    // The largest liveBytes() since the last resetPeak() (or the start).
    std::size_t peakBytes() const;
    // Starts a new peak at today's live bytes (bench: between configurations).
    void resetPeak();
    std::vector<LedgerEntry> entries() const;
    // Live bytes per owner label, sorted by label.
    std::vector<OwnerBytes> byOwner() const;
    // Formats texelBytes lacked since the start (0x hex), for the test.
    std::vector<GLenum> unknownFormats() const;
    void noteUnknownFormat(GLenum format);
};

// While alive, allocations on this thread are owned by `owner` (the innermost
// scope wins), e.g. MemoryOwner scope("shadow maps").
class MemoryOwner {
public:
    explicit MemoryOwner(std::string owner);
    ~MemoryOwner();
    MemoryOwner(const MemoryOwner&) = delete;
    MemoryOwner& operator=(const MemoryOwner&) = delete;
    // The innermost owner now ("unowned" outside every scope).
    static std::string current();
};

// Move-only: the ledger entry of one allocation, removed when destroyed.
class LedgerTicket {
public:
    LedgerTicket() = default;
    explicit LedgerTicket(std::uint64_t ticket) : ticket_(ticket) {}
    ~LedgerTicket() { reset(); }
    LedgerTicket(const LedgerTicket&) = delete;
    LedgerTicket& operator=(const LedgerTicket&) = delete;
    LedgerTicket(LedgerTicket&& o) noexcept : ticket_(o.ticket_) { o.ticket_ = 0; }
    LedgerTicket& operator=(LedgerTicket&& o) noexcept {
        if (this != &o) {
            reset();
            ticket_ = o.ticket_;
            o.ticket_ = 0;
        }
        return *this;
    }
    void reset() {
        if (ticket_ != 0) MemoryLedger::instance().remove(ticket_);
        ticket_ = 0;
    }

private:
    std::uint64_t ticket_ = 0;
};

}  // namespace dw::gl
