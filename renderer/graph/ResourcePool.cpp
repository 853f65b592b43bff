#include "renderer/graph/ResourcePool.h"

#include <algorithm>

#include "renderer/Error.h"
#include "renderer/graph/OutputRegistry.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/gl/MemoryLedger.h"

namespace dw {

ResourceDesc ResourcePool::resolve(const ResourceDesc& desc, int fw, int fh) {
    ResourceDesc r = desc;
    if (desc.size == SizeMode::Frame) {
        r.size = SizeMode::Fixed;
        r.width = std::max(fw >> desc.shift, 1);
        r.height = std::max(fh >> desc.shift, 1);
        if (desc.kind == ResourceKind::Buffer) r.bytes = desc.bytes * static_cast<std::size_t>(r.width) * r.height;
    }
    r.shift = 0;
    if (r.kind != ResourceKind::Buffer && desc.levels == 0) {
        r.levels = gl::Texture::fullMipCount(r.width, r.height);
        if (desc.maxLevels > 0) r.levels = std::min(r.levels, desc.maxLevels);
        r.maxLevels = 0;
    }
    return r;
}

const ResourcePool::Entry& ResourcePool::acquire(const std::string& name, const ResourceDesc& desc, int fw, int fh) {
    const ResourceDesc r = resolve(desc, fw, fh);
    auto it = entries_.find(name);
    if (it != entries_.end() && it->second.desc == r) return it->second;
    Entry e;
    e.desc = r;
    gl::MemoryOwner owner("frame graph: " + name);
    e.serial = nextSerial_++;
    switch (r.kind) {
        case ResourceKind::Texture2D: e.texture = gl::Texture::create2D(r.format, r.width, r.height, r.levels); break;
        case ResourceKind::Texture2DMultisample: {
            GLint maxSamples = 0;
            glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
            if (r.samples > maxSamples)
                throw GlUnsupportedError("output '" + name + "' needs " + std::to_string(r.samples) +
                                         " samples; this GL allows at most " + std::to_string(maxSamples) + " (GL_MAX_SAMPLES)");
            e.texture = gl::Texture::create2DMultisample(r.format, r.width, r.height, r.samples);
            break;
        }
        case ResourceKind::Texture2DArray:
            e.texture = gl::Texture::create2DArray(r.format, r.width, r.height, r.layers, r.levels);
            break;
        case ResourceKind::TextureCube: e.texture = gl::Texture::createCube(r.format, r.width, r.levels); break;
        case ResourceKind::TextureCubeArray:
            e.texture = gl::Texture::createArray(GL_TEXTURE_CUBE_MAP_ARRAY, r.format, r.width, r.layers);
            break;
        case ResourceKind::Texture3D: e.texture = gl::Texture::create3D(r.format, r.width, r.height, r.layers); break;
        case ResourceKind::Buffer:
            e.buffer = gl::Buffer::create(std::max<std::size_t>(r.bytes, 16), nullptr, true, name.c_str());
            break;
    }
    if (e.texture) {
        // Outputs are read texel by texel; a pass that filters binds a sampler.
        e.texture.setFilter(GL_NEAREST, GL_NEAREST);
        e.texture.setLabel(name.c_str());
    }
    entries_[name] = std::move(e);
    return entries_[name];
}

void ResourcePool::acquireOutputs(const RenderPass& pass, const KnobRegistry& knobs, int fw, int fh,
                                  OutputRegistry& outputs, const std::set<std::string>* wanted) {
    const auto decls = pass.outputs();
    for (const auto& o : decls) {
        if (!o.viewOf.empty() || !o.resource.managed()) continue;
        if ((o.onDemand && (!wanted || !wanted->count(o.name))) || !pass.allocates(o, knobs)) {
            release(o.name);
            outputs.bindResource(o.name, nullptr, nullptr, {}, 0);
            continue;
        }
        const Entry& e = acquire(o.name, pass.resource(o, knobs), fw, fh);
        outputs.bindResource(o.name, e.texture ? &e.texture : nullptr, e.buffer ? &e.buffer : nullptr, e.desc, e.serial);
    }
    for (const auto& o : decls) {
        if (o.viewOf.empty()) continue;
        const Entry* parent = find(o.viewOf);
        outputs.bindResource(o.name, parent ? &parent->texture : nullptr, nullptr, parent ? parent->desc : ResourceDesc{},
                             parent ? parent->serial : 0);
    }
}

void ResourcePool::release(const std::string& name) { entries_.erase(name); }

const ResourcePool::Entry* ResourcePool::find(const std::string& name) const {
    auto it = entries_.find(name);
    return it == entries_.end() ? nullptr : &it->second;
}

std::vector<ResourceRecord> ResourcePool::list() const {
    std::vector<ResourceRecord> out;
    for (const auto& [name, e] : entries_) {
        // A buffer as created (at least 16 bytes); a texture by its descriptor.
        const std::size_t bytes = e.buffer ? e.buffer.size() : resourceBytes(e.desc, e.desc.width, e.desc.height);
        out.push_back({name, e.desc, bytes});
    }
    return out;
}

std::size_t ResourcePool::totalBytes() const {
    std::size_t b = 0;
    for (const auto& r : list()) b += r.bytes;
    return b;
}

}  // namespace dw
