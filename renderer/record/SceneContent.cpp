#include "renderer/record/SceneContent.h"

#include <openssl/evp.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>

#include "renderer/Error.h"

namespace dw {

namespace {

// An incremental sha256 over typed values: each value's bytes, a list's or
// a string's length before it, so no two different contents share a stream.
class ContentDigest {
public:
    ContentDigest() : ctx_(EVP_MD_CTX_new(), EVP_MD_CTX_free) {
        if (!ctx_ || !EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr)) throw Error("sha256 failed");
    }
    void bytes(const void* data, size_t size) {
        if (size && !EVP_DigestUpdate(ctx_.get(), data, size)) throw Error("sha256 failed");
    }
    void u64(std::uint64_t v) { bytes(&v, sizeof v); }
    void i32(int v) { bytes(&v, sizeof v); }
    void f32(float v) { bytes(&v, sizeof v); }
    void flag(bool v) { i32(v ? 1 : 0); }
    void text(const std::string& s) {
        u64(s.size());
        bytes(s.data(), s.size());
    }
    template <int N>
    void vec(const glm::vec<N, float, glm::defaultp>& v) {
        for (int i = 0; i < N; ++i) f32(v[i]);
    }
    std::string hex() {
        unsigned char digest[EVP_MAX_MD_SIZE];
        unsigned int length = 0;
        if (!EVP_DigestFinal_ex(ctx_.get(), digest, &length)) throw Error("sha256 failed");
        std::string out;
        char byte[3];
        for (unsigned int i = 0; i < length; ++i) {
            std::snprintf(byte, sizeof(byte), "%02x", digest[i]);
            out += byte;
        }
        return out;
    }

private:
    std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> ctx_;
};

void addMeshes(ContentDigest& d, const Scene& s) {
    d.u64(s.meshes.size());
    for (const Mesh& m : s.meshes) {
        d.text(m.name);
        d.i32(m.material);
        d.u64(m.vertices.size());
        // Vertex is 18 floats with no padding (static_assert in Mesh.h).
        d.bytes(m.vertices.data(), m.vertices.size() * sizeof(Vertex));
        d.u64(m.indices.size());
        d.bytes(m.indices.data(), m.indices.size() * sizeof(std::uint32_t));
    }
    d.u64(s.instances.size());
    for (const MeshInstance& i : s.instances) {
        d.i32(i.mesh);
        for (int c = 0; c < 4; ++c) d.vec(i.transform[c]);
    }
}

void addMaterials(ContentDigest& d, const Scene& s) {
    d.u64(s.materials.size());
    for (const Material& m : s.materials) {
        d.text(m.name);
        d.i32(static_cast<int>(m.model));
        d.vec(m.baseColor);
        d.vec(m.specularColor);
        d.vec(m.emissive);
        for (float v : {m.specularExponent, m.glossiness, m.metallic, m.roughness, m.normalScale, m.alphaCutoff,
                        m.occlusionStrength})
            d.f32(v);
        for (int t : {m.baseColorTexture, m.specularTexture, m.metallicRoughnessTexture, m.normalTexture,
                      m.emissiveTexture, m.occlusionTexture, static_cast<int>(m.alphaMode)})
            d.i32(t);
        d.flag(m.doubleSided);
        for (const TextureMapping& t : m.mapping) {
            d.i32(t.texCoord);
            for (unsigned v : {t.wrapS, t.wrapT, t.minFilter, t.magFilter}) d.i32(static_cast<int>(v));
            d.vec(t.offset);
            d.f32(t.rotation);
            d.vec(t.scale);
        }
    }
    d.u64(s.images.size());
    for (const Image& i : s.images) {
        d.i32(i.width);
        d.i32(i.height);
        d.u64(i.rgba.size());
        d.bytes(i.rgba.data(), i.rgba.size());
    }
}

// Every light but the fire's particles (they move with the frame index).
void addLights(ContentDigest& d, const Scene& s) {
    const size_t firstFlame = s.flames.empty() ? s.lights.size() : s.flames.firstLight;
    const size_t flameCount = s.flames.empty() ? 0 : static_cast<size_t>(s.flames.count());
    d.u64(s.lights.size() - std::min(flameCount, s.lights.size()));
    for (size_t i = 0; i < s.lights.size(); ++i) {
        if (i >= firstFlame && i < firstFlame + flameCount) continue;
        const Light& l = s.lights[i];
        d.text(l.name);
        d.i32(static_cast<int>(l.type));
        d.i32(static_cast<int>(l.falloff));
        d.vec(l.position);
        d.vec(l.direction);
        d.vec(l.intensity);
        for (float v : {l.cutoffDegrees, l.exponent, l.innerConeDegrees, l.attenuation.constant, l.attenuation.linear,
                        l.attenuation.quadratic})
            d.f32(v);
        d.flag(l.castShadows);
        d.flag(l.enabled);
    }
    d.u64(s.flames.emitters.size());
    for (const FlameEmitter& e : s.flames.emitters) {
        d.vec(e.base);
        for (float v : {e.radius, e.height, e.brightness}) d.f32(v);
        d.i32(e.particles);
    }
}

void addView(ContentDigest& d, const Scene& s) {
    const Camera& c = s.camera;
    d.vec(c.position);
    d.vec(c.target);
    d.vec(c.up);
    for (float v : {c.fovYDegrees, c.nearPlane, c.farPlane}) d.f32(v);
    d.u64(s.cameraPath.size());
    for (const CameraKeyframe& k : s.cameraPath) {
        d.f32(k.time);
        d.vec(k.position);
        d.vec(k.target);
    }
    d.vec(s.ambient);
    d.vec(s.background);
    const Sky& sky = s.sky;
    d.i32(static_cast<int>(sky.kind));
    d.vec(sky.zenith);
    d.vec(sky.horizon);
    d.vec(sky.ground);
    for (float v : {sky.sunSizeDegrees, sky.intensity, sky.rotationDegrees}) d.f32(v);
    d.text(sky.environmentSource);
    d.u64(s.settings.size());
    for (const auto& [knob, value] : s.settings) {
        d.text(knob);
        d.text(value);
    }
}

}  // namespace

std::string sceneContentSha256(const Scene& scene) {
    ContentDigest d;
    d.text("deferred-workbench scene content 1");
    d.text(scene.name);
    addMeshes(d, scene);
    addMaterials(d, scene);
    addLights(d, scene);
    addView(d, scene);
    return d.hex();
}

}  // namespace dw
