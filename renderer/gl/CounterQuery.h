#pragma once
// The deterministic cost counters of a span of GL commands (issue 34): one
// query object per counter, begun and ended around a pass.
//   fragments   GL_FRAGMENT_SHADER_INVOCATIONS_ARB: fragment shader invocations
//   primitives  GL_PRIMITIVES_SUBMITTED_ARB: primitives submitted (before clipping)
//   vertices    GL_VERTICES_SUBMITTED_ARB: vertices submitted
//   compute     GL_COMPUTE_SHADER_INVOCATIONS_ARB: compute shader invocations
//   samples     GL_SAMPLES_PASSED: samples that pass the depth and stencil tests
// The first four need GL_ARB_pipeline_statistics_query (core in GL 4.6; Mesa
// llvmpipe offers it in a 4.5 context); GL_SAMPLES_PASSED is core. Mesa
// llvmpipe counts fragment invocations before the depth and stencil tests
// (early-z does not skip the shader on a CPU rasteriser), so early-depth and
// stencil light-volume savings show only in `samples`. Results are read
// frames later (available() first), as TimestampQuery's are.
#include <array>
#include <cstdint>

#include "renderer/gl/GlObject.h"

namespace dw::gl {

// Whether the current context lists GL_ARB_pipeline_statistics_query (or is
// GL 4.6, where it is core). Cached per process.
bool hasPipelineStatistics();

class CounterQueries {
public:
    // The counters in this order; kStatistics of them need the extension.
    static constexpr int kCount = 5;
    static constexpr int kStatistics = 4;
    static const std::array<GLenum, kCount>& targets();

    CounterQueries() = default;
    // Creates the queries: all five with `statistics`, else samples only.
    static CounterQueries create(bool statistics);
    explicit operator bool() const { return static_cast<bool>(names_[kCount - 1]); }
    bool statistics() const { return static_cast<bool>(names_[0]); }
    void begin() const;
    void end() const;
    bool available() const;
    // Blocks until done. Counters not created read -1, in targets() order.
    std::array<std::int64_t, kCount> results() const;

private:
    std::array<GlObject<QueryTraits>, kCount> names_;
};

}  // namespace dw::gl
