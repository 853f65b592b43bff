#include "renderer/OutputRegistry.h"

#include "renderer/Error.h"

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
    o->texture = texture;
    o->channels = channels;
    o->level = level;
}

void OutputRegistry::bindAlias(const std::string& alias, const std::string& target) {
    PublishedOutput* a = findMutable(alias);
    const PublishedOutput* t = find(target);
    if (!a || !t) throw Error("binding unknown alias '" + alias + "' to '" + target + "'");
    a->texture = t->texture;
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
