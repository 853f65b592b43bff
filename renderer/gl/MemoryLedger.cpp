#include "renderer/gl/MemoryLedger.h"
#include "renderer/gl/MemoryDomain.h"

#include <algorithm>
#include <map>
#include <mutex>
#include <set>
#include <unordered_map>

namespace dw::gl {

std::size_t texelBytes(GLenum f) {
    switch (f) {
        case GL_R8: case GL_R8_SNORM: case GL_R8UI: case GL_R8I: case GL_STENCIL_INDEX8: return 1;
        case GL_R16F: case GL_R16: case GL_R16_SNORM: case GL_R16UI: case GL_R16I: case GL_RG8: case GL_RG8_SNORM:
        case GL_RG8UI: case GL_RG8I: case GL_DEPTH_COMPONENT16: return 2;
        case GL_RGB8: case GL_SRGB8: case GL_RGB8_SNORM: case GL_RGB8UI: case GL_RGB8I: return 3;
        case GL_RGBA8: case GL_SRGB8_ALPHA8: case GL_RGBA8_SNORM: case GL_RGBA8UI: case GL_RGBA8I: case GL_R32F:
        case GL_R32UI: case GL_R32I: case GL_RG16F: case GL_RG16: case GL_RG16_SNORM: case GL_RG16UI: case GL_RG16I:
        case GL_R11F_G11F_B10F: case GL_RGB9_E5: case GL_RGB10_A2: case GL_RGB10_A2UI: case GL_DEPTH_COMPONENT32F:
        case GL_DEPTH_COMPONENT32: case GL_DEPTH_COMPONENT24: case GL_DEPTH24_STENCIL8: return 4;
        case GL_DEPTH32F_STENCIL8: return 5;  // 32-bit depth + 8-bit stencil, logically
        case GL_RGB16F: case GL_RGB16: case GL_RGB16_SNORM: case GL_RGB16UI: case GL_RGB16I: return 6;
        case GL_RGBA16F: case GL_RGBA16: case GL_RGBA16_SNORM: case GL_RGBA16UI: case GL_RGBA16I: case GL_RG32F:
        case GL_RG32UI: case GL_RG32I: return 8;
        case GL_RGB32F: case GL_RGB32UI: case GL_RGB32I: return 12;
        case GL_RGBA32F: case GL_RGBA32UI: case GL_RGBA32I: return 16;
        default: return 0;
    }
}

std::size_t textureStorageBytes(GLenum target, GLenum format, int width, int height, int depthOrLayers, int levels,
                                int samples) {
    std::size_t texel = texelBytes(format);
    if (texel == 0) {
        MemoryLedger::instance().noteUnknownFormat(format);
        texel = 4;
    }
    const bool is3D = target == GL_TEXTURE_3D;
    std::size_t layers = static_cast<std::size_t>(std::max(depthOrLayers, 1));
    if (target == GL_TEXTURE_CUBE_MAP) layers = 6;
    std::size_t total = 0;
    for (int l = 0; l < std::max(levels, 1); ++l) {
        const std::size_t w = static_cast<std::size_t>(std::max(width >> l, 1));
        const std::size_t h = static_cast<std::size_t>(std::max(height >> l, 1));
        const std::size_t d = is3D ? static_cast<std::size_t>(std::max(depthOrLayers >> l, 1)) : layers;
        total += texel * w * h * d;
    }
    return total * static_cast<std::size_t>(std::max(samples, 1));
}

namespace {

thread_local std::vector<std::string> tOwners;
thread_local std::vector<const void*> tDomains;

struct DomainBytes {
    std::size_t live = 0, peak = 0;
};

struct LedgerState {
    std::mutex mutex;
    std::unordered_map<std::uint64_t, LedgerEntry> live;
    std::set<GLenum> unknown;
    std::uint64_t next = 1;
    std::size_t bytes = 0;
    std::size_t peak = 0;
    std::unordered_map<std::uint64_t, const void*> domainOf;  // tickets made inside a domain
    std::unordered_map<const void*, DomainBytes> domains;
};

LedgerState& state() {
    // Never destroyed: wrappers in static storage may release after main.
    static LedgerState* s = new LedgerState();
    return *s;
}

}  // namespace

MemoryLedger& MemoryLedger::instance() {
    static MemoryLedger ledger;
    return ledger;
}

std::uint64_t MemoryLedger::add(const char* kind, GLuint id, std::size_t bytes) {
    LedgerState& s = state();
    std::string owner = MemoryOwner::current();
    std::lock_guard<std::mutex> lock(s.mutex);
    const std::uint64_t ticket = s.next++;
    s.live[ticket] = LedgerEntry{ticket, std::move(owner), kind, id, bytes};
    s.bytes += bytes;
    s.peak = std::max(s.peak, s.bytes);
    if (!tDomains.empty()) {
        s.domainOf[ticket] = tDomains.back();
        DomainBytes& d = s.domains[tDomains.back()];
        d.live += bytes;
        d.peak = std::max(d.peak, d.live);
    }
    return ticket;
}

void MemoryLedger::remove(std::uint64_t ticket) {
    LedgerState& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    auto it = s.live.find(ticket);
    if (it == s.live.end()) return;
    s.bytes -= it->second.bytes;
    if (auto d = s.domainOf.find(ticket); d != s.domainOf.end()) {
        s.domains[d->second].live -= it->second.bytes;
        s.domainOf.erase(d);
    }
    s.live.erase(it);
}

std::size_t MemoryLedger::liveBytes() const {
    std::lock_guard<std::mutex> lock(state().mutex);
    return state().bytes;
}

std::size_t MemoryLedger::liveObjects() const {
    std::lock_guard<std::mutex> lock(state().mutex);
    return state().live.size();
}

std::size_t MemoryLedger::peakBytes() const {
    std::lock_guard<std::mutex> lock(state().mutex);
    return state().peak;
}

void MemoryLedger::resetPeak() {
    std::lock_guard<std::mutex> lock(state().mutex);
    state().peak = state().bytes;
}

std::vector<LedgerEntry> MemoryLedger::entries() const {
    std::lock_guard<std::mutex> lock(state().mutex);
    std::vector<LedgerEntry> out;
    out.reserve(state().live.size());
    for (const auto& [ticket, e] : state().live) out.push_back(e);
    std::sort(out.begin(), out.end(), [](const LedgerEntry& a, const LedgerEntry& b) { return a.ticket < b.ticket; });
    return out;
}

std::vector<OwnerBytes> MemoryLedger::byOwner() const {
    std::map<std::string, OwnerBytes> owners;
    for (const auto& e : entries()) {
        OwnerBytes& o = owners[e.owner];
        o.owner = e.owner;
        o.bytes += e.bytes;
        ++o.objects;
    }
    std::vector<OwnerBytes> out;
    for (auto& [name, o] : owners) out.push_back(std::move(o));
    return out;
}

std::vector<GLenum> MemoryLedger::unknownFormats() const {
    std::lock_guard<std::mutex> lock(state().mutex);
    return {state().unknown.begin(), state().unknown.end()};
}

void MemoryLedger::noteUnknownFormat(GLenum format) {
    std::lock_guard<std::mutex> lock(state().mutex);
    state().unknown.insert(format);
}

MemoryOwner::MemoryOwner(std::string owner) { tOwners.push_back(std::move(owner)); }

MemoryOwner::~MemoryOwner() { tOwners.pop_back(); }

std::string MemoryOwner::current() { return tOwners.empty() ? std::string("unowned") : tOwners.back(); }

MemoryDomain::MemoryDomain(const void* key) { tDomains.push_back(key); }

MemoryDomain::~MemoryDomain() { tDomains.pop_back(); }

std::size_t domainLiveBytes(const void* key) {
    LedgerState& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    auto it = s.domains.find(key);
    return it == s.domains.end() ? 0 : it->second.live;
}

std::size_t domainPeakBytes(const void* key) {
    LedgerState& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    auto it = s.domains.find(key);
    return it == s.domains.end() ? 0 : it->second.peak;
}

void resetDomainPeak(const void* key) {
    LedgerState& s = state();
    std::lock_guard<std::mutex> lock(s.mutex);
    DomainBytes& d = s.domains[key];
    d.peak = d.live;
}

}  // namespace dw::gl
