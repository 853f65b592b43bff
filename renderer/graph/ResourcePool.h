#pragma once
// The GL objects behind managed outputs (ResourceDesc.h). The pipeline asks
// for a resource each frame its writer runs and releases it when none runs;
// the pool re-creates an object only when its resolved descriptor changes,
// and gives every allocation a new serial so passes can rebuild framebuffers.
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "renderer/graph/ResourceDesc.h"
#include "renderer/gl/Buffer.h"
#include "renderer/gl/Texture.h"

namespace dw {

class KnobRegistry;
class OutputRegistry;
class RenderPass;

// One allocated resource, as `Pipeline::resources()` lists it.
struct ResourceRecord {
    std::string name;
    ResourceDesc desc;  // resolved: size Fixed, width and height set
    std::size_t bytes = 0;
};

class ResourcePool {
public:
    struct Entry {
        ResourceDesc desc;  // resolved
        gl::Texture texture;
        gl::Buffer buffer;
        std::uint64_t serial = 0;
    };
    // `desc` with a frame-relative size resolved against the frame.
    static ResourceDesc resolve(const ResourceDesc& desc, int frameWidth, int frameHeight);
    // The resource `name` as `desc` describes it at this frame size; (re)created
    // only if it is missing or its resolved descriptor differs. Throws dw::Error
    // for a descriptor GL cannot allocate (e.g. more samples than GL_MAX_SAMPLES).
    const Entry& acquire(const std::string& name, const ResourceDesc& desc, int frameWidth, int frameHeight);
    void release(const std::string& name);
    // Acquires every managed output of `pass` (and binds it, and its mip
    // views, in `outputs`) as the pipeline does before the pass runs; for
    // running one pass alone (tests, tools). On-demand outputs only if `wanted` lists them.
    void acquireOutputs(const RenderPass& pass, const KnobRegistry& knobs, int frameWidth, int frameHeight,
                        OutputRegistry& outputs, const std::set<std::string>* wanted = nullptr);
    const Entry* find(const std::string& name) const;
    std::vector<ResourceRecord> list() const;
    std::size_t totalBytes() const;

private:
    std::map<std::string, Entry> entries_;
    std::uint64_t nextSerial_ = 1;
};

}  // namespace dw
