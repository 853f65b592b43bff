#include "renderer/graph/OutputRegistry.h"

#include <algorithm>

#include "renderer/Error.h"
#include "renderer/gl/Texture.h"

namespace dw {

const char* toString(OutputKind kind) {
    switch (kind) {
        case OutputKind::Color: return "color";
        case OutputKind::HdrColor: return "hdr";
        case OutputKind::Depth: return "depth";
        case OutputKind::NormalKL: return "normal-kl";
        case OutputKind::Vector: return "vector";
        case OutputKind::Scalar: return "scalar";
        case OutputKind::Count: return "count";
    }
    return "?";
}

void OutputRegistry::declare(const std::string& pass, const OutputDecl& decl) {
    if (findMutable(decl.name)) throw Error("output '" + decl.name + "' is declared twice");
    PublishedOutput o;
    o.decl = decl;
    o.pass = pass;
    outputs_.push_back(o);
}

void OutputRegistry::bind(const std::string& name, const gl::Texture* texture, int channels, int level) {
    PublishedOutput* o = findMutable(name);
    if (!o) throw Error("binding undeclared output '" + name + "'");
    if (texture && texture != o->texture) {
        // An imported texture: describe it from what GL has, so views treat it like a managed one.
        ResourceDesc d;
        switch (texture->target()) {
            case GL_TEXTURE_2D_MULTISAMPLE: d.kind = ResourceKind::Texture2DMultisample; break;
            case GL_TEXTURE_2D_ARRAY: d.kind = ResourceKind::Texture2DArray; break;
            case GL_TEXTURE_CUBE_MAP: d.kind = ResourceKind::TextureCube; break;
            case GL_TEXTURE_CUBE_MAP_ARRAY: d.kind = ResourceKind::TextureCubeArray; break;
            case GL_TEXTURE_3D: d.kind = ResourceKind::Texture3D; break;
            default: d.kind = ResourceKind::Texture2D; break;
        }
        d.format = texture->internalFormat();
        d.size = SizeMode::Fixed;
        d.width = texture->width();
        d.height = texture->height();
        d.layers = texture->layers();
        d.samples = std::max(texture->samples(), 1);
        d.levels = texture->levels();
        o->desc = d;
        o->serial = ++importSerial_;
    }
    o->buffer = nullptr;
    o->texture = texture;
    o->channels = channels;
    o->level = level;
}

void OutputRegistry::bindResource(const std::string& name, const gl::Texture* texture, const gl::Buffer* buffer,
                                  const ResourceDesc& desc, std::uint64_t serial) {
    PublishedOutput* o = findMutable(name);
    if (!o) throw Error("binding undeclared output '" + name + "'");
    o->texture = texture;
    o->buffer = buffer;
    o->desc = desc;
    o->serial = serial;
    o->channels = o->decl.channels;
    o->level = std::min(o->decl.level, std::max(desc.levels - 1, 0));
}

void OutputRegistry::bindBuffer(const std::string& name, const gl::Buffer* buffer, std::size_t stride, std::size_t count) {
    PublishedOutput* o = findMutable(name);
    if (!o) throw Error("binding undeclared output '" + name + "'");
    if (buffer != o->buffer || o->desc.bytes != stride * count) o->serial = ++importSerial_;
    o->texture = nullptr;
    o->buffer = buffer;
    o->desc = ResourceDesc{};
    o->desc.kind = ResourceKind::Buffer;
    o->desc.size = SizeMode::Fixed;
    o->desc.stride = stride;
    o->desc.bytes = stride * count;
    o->channels = o->decl.channels;
    o->level = 0;
}

void OutputRegistry::bindAlias(const std::string& alias, const std::string& target) {
    PublishedOutput* a = findMutable(alias);
    const PublishedOutput* t = find(target);
    if (!a || !t) throw Error("binding unknown alias '" + alias + "' to '" + target + "'");
    a->texture = t->texture;
    a->buffer = t->buffer;
    a->desc = t->desc;
    a->serial = t->serial;
    a->channels = t->channels;
    a->level = t->level;
    a->pass = t->pass;
    a->producedThisFrame = t->producedThisFrame;
}

void OutputRegistry::markFrameStart() {
    for (auto& o : outputs_) o.producedThisFrame = false;
}

void OutputRegistry::markProduced(const std::string& pass, const std::set<std::string>& wanted) {
    for (auto& o : outputs_)
        if (o.pass == pass && wanted.count(o.decl.name)) o.producedThisFrame = true;
}

void OutputRegistry::markProduced(const std::string& pass) {
    for (auto& o : outputs_)
        if (o.pass == pass) o.producedThisFrame = true;
}

const PublishedOutput* OutputRegistry::find(const std::string& name) const {
    for (const auto& o : outputs_)
        if (o.decl.name == name) return &o;
    return nullptr;
}

PublishedOutput* OutputRegistry::findMutable(const std::string& name) {
    for (auto& o : outputs_)
        if (o.decl.name == name) return &o;
    return nullptr;
}

std::vector<std::string> OutputRegistry::names() const {
    std::vector<std::string> n;
    for (const auto& o : outputs_) n.push_back(o.decl.name);
    return n;
}

}  // namespace dw
