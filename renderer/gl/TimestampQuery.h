#pragma once
// One GL_TIMESTAMP query object (glQueryCounter). GL_TIME_ELAPSED is broken on
// Mesa llvmpipe, so every GPU duration in the project is a pair of these.
#include <cstdint>

#include "renderer/gl/GlObject.h"

namespace dw::gl {

class TimestampQuery {
public:
    TimestampQuery() = default;
    static TimestampQuery create();

    GLuint id() const { return name_.id(); }
    explicit operator bool() const { return static_cast<bool>(name_); }
    void record() const;
    // Non-blocking: true when the result can be read without waiting.
    bool available() const;
    // Blocks until the GPU has passed the timestamp; nanoseconds.
    std::uint64_t result() const;

private:
    GlObject<QueryTraits> name_;
};

}  // namespace dw::gl
