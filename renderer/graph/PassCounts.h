#pragma once
// A pass's deterministic cost counters in one frame (issue 34), in the
// column order of every table that shows them:
//   fragments   fragment shader invocations (GL_FRAGMENT_SHADER_INVOCATIONS_ARB)
//   samples     samples that passed the depth and stencil tests (GL_SAMPLES_PASSED)
//   primitives  primitives submitted (GL_PRIMITIVES_SUBMITTED_ARB, before clipping)
//   vertices    vertices submitted (GL_VERTICES_SUBMITTED_ARB)
//   compute     compute shader invocations (GL_COMPUTE_SHADER_INVOCATIONS_ARB)
//   bytes       the bytes of the resources the pass declares it reads and writes
//               (texel bytes x width x height x layers x samples, a mip chain +1/3;
//               buffers their size), from the frame graph's declarations
// gl/CounterQuery.h says which driver counts what. -1: not measured (no
// GL_ARB_pipeline_statistics_query, counting off, or a span inside a pass).
// The frame's counts are the sums over its passes. Needs no GL.
#include <array>
#include <cstdint>
#include <string>

namespace dw {

struct PassCounts {
    static constexpr int kCount = 6;
    enum Index { Fragments, Samples, Primitives, Vertices, Compute, Bytes };
    std::array<std::int64_t, kCount> v{-1, -1, -1, -1, -1, -1};

    // "fragments", "samples", "primitives", "vertices", "compute", "bytes".
    static const char* name(int i);
    // The index of a counter's name, or -1.
    static int index(const std::string& name);
    // Whether the counter needs GL_ARB_pipeline_statistics_query.
    static bool needsStatistics(int i) { return i == Fragments || i == Primitives || i == Vertices || i == Compute; }
    bool measured() const;  // any counter measured
    std::int64_t operator[](int i) const { return v[static_cast<size_t>(i)]; }
    // Adds `other`'s measured counters into this (a frame's sum over passes).
    void add(const PassCounts& other);
    bool operator==(const PassCounts&) const = default;
};

}  // namespace dw
