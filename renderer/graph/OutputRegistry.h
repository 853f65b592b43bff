#pragma once
// Named outputs (DESIGN.md, "Named outputs"): every pass publishes what it
// writes under a name ("gbuffer.normal", "lbuffer", ...). The inspector, the
// CLI's --buffer and the pixel probe read this list; none needs per-pass code.
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "renderer/graph/ResourceDesc.h"

namespace dw {

namespace gl {
class Texture;
class Buffer;
}

// How a buffer's values are to be read; drives the default display mapping.
enum class OutputKind {
    Color,     // display-ready colour (8-bit, sRGB-encoded)
    HdrColor,  // linear radiance, unbounded
    Depth,     // window-space depth in [0, 1]
    NormalKL,  // view-space normal encoded in 2 SNORM channels (gbuffer.normal_encoding: Kircher-Lawrance or octahedral)
    Vector,    // signed vector data (decoded normals, positions)
    Scalar,    // one value per pixel (AO, luminance statistics)
    Count,     // small integer counts (light overlap, A-buffer samples)
};
const char* toString(OutputKind kind);

struct OutputDecl {
    std::string name;
    OutputKind kind = OutputKind::Color;
    std::string description;
    // Managed outputs are allocated by the pipeline from this (ResourceDesc.h);
    // the default, imported(), leaves the texture to the pass.
    ResourceDesc resource{};
    int channels = 4;        // channels that hold data (a view shows 1 as grey)
    bool onDemand = false;   // written (and allocated) only when something asks for it
    std::string viewOf;      // a mip level of another output of the same pass...
    int level = 0;           // ...this one
};

struct PublishedOutput {
    OutputDecl decl;
    std::string pass;
    const gl::Texture* texture = nullptr;  // null until allocated (or for a buffer)
    const gl::Buffer* buffer = nullptr;    // a buffer resource
    ResourceDesc desc{};                   // as allocated this frame (size resolved)
    std::uint64_t serial = 0;              // changes with every (re)allocation
    int level = 0;
    int channels = 4;
    bool producedThisFrame = false;
    bool allocated() const { return texture != nullptr || buffer != nullptr; }
};

class OutputRegistry {
public:
    void declare(const std::string& pass, const OutputDecl& decl);
    void bind(const std::string& name, const gl::Texture* texture, int channels, int level = 0);
    // A managed resource allocated by the pipeline (texture or buffer), or its release (both null).
    void bindResource(const std::string& name, const gl::Texture* texture, const gl::Buffer* buffer,
                      const ResourceDesc& desc, std::uint64_t serial);
    // Makes `alias` show `target` this frame (texture, pass, produced state).
    void bindAlias(const std::string& alias, const std::string& target);
    // A buffer the pass owns (sized by the scene, say): `count` elements of `stride` bytes.
    void bindBuffer(const std::string& name, const gl::Buffer* buffer, std::size_t stride, std::size_t count);
    void markFrameStart();
    // Marks the pass's outputs in `wanted` as written this frame (a pass skips
    // optional outputs nothing asked for, so those keep older contents).
    void markProduced(const std::string& pass, const std::set<std::string>& wanted);
    void markProduced(const std::string& pass);  // all of the pass's outputs
    const PublishedOutput* find(const std::string& name) const;
    const std::vector<PublishedOutput>& all() const { return outputs_; }
    std::vector<std::string> names() const;

private:
    PublishedOutput* findMutable(const std::string& name);
    std::vector<PublishedOutput> outputs_;
    std::uint64_t importSerial_ = 1ull << 62;  // imported textures count apart from the pool's serials
};

}  // namespace dw
