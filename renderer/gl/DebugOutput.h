#pragma once
// Routes KHR_debug messages to stderr (debug builds, or DW_GL_DEBUG=1), and
// requires the GL version and features the renderer uses.
#include <string>

namespace dw::gl {

struct GlInfo {
    std::string vendor, renderer, version;
    int major = 0, minor = 0;
    int maxSamples = 0;
    int maxDrawBuffers = 0;
    int maxTextureSize = 0;
    int timestampBits = 0;
};

// Whether the context rasterises on the CPU (Mesa's llvmpipe or softpipe,
// OpenSWR, or a renderer that calls itself a software rasterizer): frames
// there cost seconds at window sizes, and their time ratios are not a GPU's.
bool isCpuRasterizer(const GlInfo& info);

// Reads the context's capabilities; throws GlUnsupportedError naming what is
// missing when the context is older than 4.5 core or lacks a needed feature.
GlInfo requireGl45();
// Installs the debug callback when enabled (see above). Returns whether it did.
bool installDebugOutput(bool force = false);

}  // namespace dw::gl
