#include "renderer/scene/GpuScene.h"
#include "renderer/gl/MemoryLedger.h"

#include <algorithm>
#include <cstring>

#include "renderer/Error.h"

namespace dw {

namespace {

// std430 mirror of `Material` in shaders/common/material.glsl.
struct MaterialGpu {
    glm::vec4 baseColor;
    glm::vec4 specular;          // rgb specular colour / dielectric F0, a Blinn-Phong exponent
    glm::vec4 emissive;          // rgb emissive, a normal-map scale
    glm::vec4 params;            // metallic, roughness, glossiness, alpha cutoff
    glm::ivec4 textures;         // 1 where the material has: base colour, normal, specular/MR, emissive
    glm::ivec4 flags;            // model, alpha mode, double sided, unused
    glm::ivec4 texCoords;        // UV set (0 or 1) of base colour, normal, specular/MR, emissive
    glm::vec4 occlusion;         // has an occlusion texture, strength, UV set, unused
    glm::vec4 uvTransform[2 * Material::kSlotCount];  // per texture slot: the two rows of its 2x3 UV transform
};
static_assert(sizeof(MaterialGpu) == 288, "std430 layout");

gl::Texture solidTexture(std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a, bool srgb) {
    gl::MemoryOwner owner("scene textures");
    gl::Texture t = gl::Texture::create2D(srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, 1, 1);
    const std::uint8_t px[4] = {r, g, b, a};
    t.upload(0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    t.setWrap(GL_REPEAT);
    return t;
}

// The sky's environment as RGBA16F (empty without one); NaN and Inf stay as
// they are (the tone mapper's guard is what handles them, and can be switched off).
gl::Texture environmentTexture(const Scene& scene) {
    auto rgba = [](const FloatImage& img) {
        std::vector<float> out(static_cast<size_t>(img.width) * img.height * 4, 1.0f);
        for (size_t p = 0; p < static_cast<size_t>(img.width) * img.height; ++p)
            for (int c = 0; c < std::min(img.channels, 4); ++c) out[p * 4 + c] = img.pixels[p * img.channels + c];
        return out;
    };
    gl::MemoryOwner owner("scene environment");
    gl::Texture t;
    if (!scene.sky.cubeFaces.empty()) {
        const int size = scene.sky.cubeFaces[0].width;
        t = gl::Texture::createCube(GL_RGBA16F, size, gl::Texture::fullMipCount(size, size));
        for (int f = 0; f < 6; ++f) t.uploadCubeFace(f, 0, size, GL_RGBA, GL_FLOAT, rgba(scene.sky.cubeFaces[f]).data());
        t.generateMipmaps();
    } else if (scene.sky.equirect.width > 0) {
        const FloatImage& e = scene.sky.equirect;
        t = gl::Texture::create2D(GL_RGBA16F, e.width, e.height, gl::Texture::fullMipCount(e.width, e.height));
        t.upload(0, e.width, e.height, GL_RGBA, GL_FLOAT, rgba(e).data());
        t.generateMipmaps();
        glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    }
    return t;
}

}  // namespace

bool GpuScene::onLlvmpipe() {
    static const bool llvmpipe = [] {
        const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        return renderer && std::strstr(renderer, "llvmpipe");
    }();
    return llvmpipe;
}

float GpuScene::deviceMaxAnisotropy() {
    static const float largest = [] {
        if (!epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic") && epoxy_gl_version() < 46) return 1.0f;
        GLfloat v = 1.0f;
        glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &v);
        return std::max(v, 1.0f);
    }();
    return largest;
}

// Mesa 22.3's llvmpipe: an anisotropic lookup at a grazing angle over a
// texture repeated thousands of times (a plane with uv-scale 2500, texture
// coordinates up to 1e5; the extremes suite's floor scaled by 1e4) spins for
// minutes per draw, whatever the level (aniso2 too) and with the footprint's
// ratio and length bounded in the shader (textureGrad) or the coordinates
// wrapped into one period: tried, still over 60 s for a 64x36 frame.
float GpuScene::maxAnisotropy() { return onLlvmpipe() ? 1.0f : deviceMaxAnisotropy(); }

GLuint GpuScene::samplerFor(const TextureMapping& m) {
    const SamplerKey key{m.wrapS, m.wrapT, m.minFilter, m.magFilter};
    auto it = samplerIndex_.find(key);
    if (it != samplerIndex_.end()) return samplers_[it->second].id();
    gl::Sampler s = gl::Sampler::create(m.minFilter, m.magFilter, m.wrapS, m.wrapT, "glTF sampler");
    samplers_.push_back(std::move(s));
    samplerKeys_.push_back(key);
    samplerIndex_[key] = samplers_.size() - 1;
    applyFiltering(samplers_.size() - 1);
    return samplers_.back().id();
}

void GpuScene::applyFiltering(std::size_t i) const {
    const auto [wrapS, wrapT, minFilter, magFilter] = samplerKeys_[i];
    (void)wrapS;
    (void)wrapT;
    const GLuint id = samplers_[i].id();
    const bool mipmapped = minFilter != GL_NEAREST && minFilter != GL_LINEAR;
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(baseLevel_ ? magFilter : minFilter));
    if (maxAnisotropy() > 1.0f)
        glSamplerParameterf(id, GL_TEXTURE_MAX_ANISOTROPY_EXT, mipmapped && !baseLevel_ ? anisotropy_ : 1.0f);
}

float GpuScene::setTextureFiltering(bool baseLevel, float anisotropy) const {
    const float capped = std::clamp(anisotropy, 1.0f, maxAnisotropy());
    if (baseLevel == baseLevel_ && capped == anisotropy_) return capped;
    baseLevel_ = baseLevel;
    anisotropy_ = capped;
    for (std::size_t i = 0; i < samplers_.size(); ++i) applyFiltering(i);
    return capped;
}

int GpuScene::textureFor(const Scene& scene, int image, bool srgb) {
    if (image < 0) return -1;
    auto key = std::make_pair(image, srgb);
    auto it = textureIndex_.find(key);
    if (it != textureIndex_.end()) return it->second;
    const Image& img = scene.images[image];
    const int levels = gl::Texture::fullMipCount(img.width, img.height);
    gl::MemoryOwner owner("scene textures");
    gl::Texture t = gl::Texture::create2D(srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, img.width, img.height, levels);
    t.upload(0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    t.generateMipmaps();
    t.setWrap(GL_REPEAT);
    textureBytes_ += static_cast<std::size_t>(img.width) * img.height * 4 * 4 / 3;
    textures_.push_back(std::move(t));
    const int idx = static_cast<int>(textures_.size() - 1);
    textureIndex_[key] = idx;
    return idx;
}

void GpuScene::upload(const Scene& scene, gl::ShaderLibrary* shaders) {
    bounds_ = scene.bounds();
    triangles_ = scene.triangleCount();
    white_ = solidTexture(255, 255, 255, 255, false);
    flatNormal_ = solidTexture(128, 128, 255, 255, false);

    std::vector<Vertex> verts;
    std::vector<std::uint32_t> idx;
    struct Range {
        std::size_t firstIndex;
        GLsizei count;
        GLint baseVertex;
    };
    std::vector<Range> ranges;
    for (const Mesh& m : scene.meshes) {
        ranges.push_back({idx.size(), static_cast<GLsizei>(m.indices.size()), static_cast<GLint>(verts.size())});
        verts.insert(verts.end(), m.vertices.begin(), m.vertices.end());
        idx.insert(idx.end(), m.indices.begin(), m.indices.end());
    }
    for (const Range& r : ranges) baseVertex_.push_back(r.baseVertex);
    {
        gl::MemoryOwner owner("scene geometry");
        vertices_ = gl::Buffer::fromVector(verts, scene.animation.moves(), "scene vertices");
        indices_ = gl::Buffer::fromVector(idx, false, "scene indices");
    }
    vao_ = gl::VertexArray::create();
    vao_.setVertexBuffer(0, vertices_, 0, sizeof(Vertex));
    vao_.setIndexBuffer(indices_);
    vao_.setAttribute(0, 0, 3, offsetof(Vertex, position));
    vao_.setAttribute(1, 0, 3, offsetof(Vertex, normal));
    vao_.setAttribute(2, 0, 4, offsetof(Vertex, tangent));
    vao_.setAttribute(3, 0, 2, offsetof(Vertex, uv));
    vao_.setAttribute(4, 0, 4, offsetof(Vertex, color));
    vao_.setAttribute(5, 0, 2, offsetof(Vertex, uv1));

    std::vector<MaterialGpu> mats;
    for (const Material& m : scene.materials) {
        MaterialTextures t;
        t.baseColor = textureFor(scene, m.baseColorTexture, true);
        t.normal = textureFor(scene, m.normalTexture, false);
        t.specular = textureFor(scene, m.model == MaterialModel::MetallicRoughness ? m.metallicRoughnessTexture : m.specularTexture,
                                m.model == MaterialModel::SpecularGlossiness);
        t.emissive = textureFor(scene, m.emissiveTexture, true);
        t.occlusion = textureFor(scene, m.occlusionTexture, false);
        for (int slot = 0; slot < Material::kSlotCount; ++slot) t.samplers[slot] = samplerFor(m.mapping[slot]);
        materialTextures_.push_back(t);
        MaterialGpu g{};
        g.baseColor = m.baseColor;
        g.specular = glm::vec4(m.specularColor, m.specularExponent);
        g.emissive = glm::vec4(m.emissive, m.normalScale);
        g.params = glm::vec4(m.metallic, m.roughness, m.glossiness, m.alphaCutoff);
        g.textures = glm::ivec4(t.baseColor >= 0, t.normal >= 0, t.specular >= 0, t.emissive >= 0);
        g.flags = glm::ivec4(static_cast<int>(m.model), static_cast<int>(m.alphaMode), m.doubleSided ? 1 : 0, 0);
        g.texCoords = glm::ivec4(m.mapping[0].texCoord, m.mapping[1].texCoord, m.mapping[2].texCoord, m.mapping[3].texCoord);
        g.occlusion = glm::vec4(t.occlusion >= 0 ? 1.0f : 0.0f, m.occlusionStrength,
                                static_cast<float>(m.mapping[Material::OcclusionSlot].texCoord), 0.0f);
        for (int slot = 0; slot < Material::kSlotCount; ++slot) {
            g.uvTransform[2 * slot] = glm::vec4(m.mapping[slot].row(0), 0.0f);
            g.uvTransform[2 * slot + 1] = glm::vec4(m.mapping[slot].row(1), 0.0f);
        }
        mats.push_back(g);
    }
    if (mats.empty()) mats.push_back(MaterialGpu{});
    gl::MemoryOwner materialsOwner("scene materials");
    materials_ = gl::Buffer::fromVector(mats, false, "materials");

    environment_ = environmentTexture(scene);

    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const MeshInstance& inst = scene.instances[i];
        const Mesh& mesh = scene.meshes[inst.mesh];
        Draw d;
        d.mesh = inst.mesh;
        d.instance = static_cast<int>(i);
        d.material = mesh.material;
        d.indexCount = ranges[inst.mesh].count;
        d.indexOffsetBytes = ranges[inst.mesh].firstIndex * sizeof(std::uint32_t);
        d.baseVertex = ranges[inst.mesh].baseVertex;
        d.alphaMode = scene.materials[mesh.material].alphaMode;
        d.doubleSided = scene.materials[mesh.material].doubleSided;
        place(d, scene);
        draws_.push_back(d);
    }
    // Group by material to save texture binds.
    std::stable_sort(draws_.begin(), draws_.end(), [](const Draw& a, const Draw& b) { return a.material < b.material; });
    // The deformed meshes' rest data to the GPU once; the pose uploaded
    // above (poseScene's) is then written again by the compute dispatch.
    if (shaders && !scene.animation.deformers.empty()) {
        gl::MemoryOwner skinningOwner("scene skinning");  // rest data, joints, morph deltas
        skinning_.upload(scene, baseVertex_, shaders->get({.compute = "scene/skin.comp"}));
        if (gpuPosing_) skinning_.pose(scene, vertices_);
    }
}

// The box from the mesh's vertices (not Mesh::bounds, which a caller may
// leave unset): O(vertices) per instance, as the draw's upload itself.
void GpuScene::place(Draw& d, const Scene& scene) {
    d.model = scene.instances[static_cast<std::size_t>(d.instance)].transform;
    d.mirrored = glm::determinant(glm::mat3(d.model)) < 0.0f;
    Bounds local;
    for (const Vertex& v : scene.meshes[static_cast<std::size_t>(d.mesh)].vertices) local.add(v.position);
    d.bounds = Bounds{};
    if (!local.empty())
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p((corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                              (corner & 4) ? local.max.z : local.min.z);
            d.bounds.add(glm::vec3(d.model * glm::vec4(p, 1.0f)));
        }
}

void GpuScene::writePose(const Scene& scene) {
    if (posesOnGpu()) {
        skinning_.pose(scene, vertices_);
        lastPoseBytes_ = skinning_.lastUploadBytes();
        return;
    }
    lastPoseBytes_ = 0;
    for (const Deformer& d : scene.animation.deformers) {
        const std::vector<Vertex>& v = scene.meshes[static_cast<std::size_t>(d.mesh)].vertices;
        vertices_.update(static_cast<std::size_t>(baseVertex_[static_cast<std::size_t>(d.mesh)]) * sizeof(Vertex),
                         v.size() * sizeof(Vertex), v.data());
        lastPoseBytes_ += v.size() * sizeof(Vertex);
    }
}

void GpuScene::updatePose(const Scene& scene) {
    if (scene.animation.empty() || draws_.empty()) return;
    writePose(scene);
    for (Draw& d : draws_) place(d, scene);
    bounds_ = scene.bounds();
}

void GpuScene::setGpuPosing(bool on, const Scene* scene) {
    if (on == gpuPosing_) return;
    gpuPosing_ = on;
    if (scene && !draws_.empty() && !scene->animation.deformers.empty()) writePose(*scene);
}

// Bound as a run of four from MATERIAL_BASE_COLOR_TEXTURE (shaders/common/material_eval.glsl).
static_assert(binding::MATERIAL_NORMAL_TEXTURE == binding::MATERIAL_BASE_COLOR_TEXTURE + 1 &&
              binding::MATERIAL_SPECULAR_TEXTURE == binding::MATERIAL_BASE_COLOR_TEXTURE + 2 &&
              binding::MATERIAL_EMISSIVE_TEXTURE == binding::MATERIAL_BASE_COLOR_TEXTURE + 3);

void GpuScene::bindMaterialTextures(int material) const {
    const MaterialTextures& t = materialTextures_[material];
    auto id = [&](int tex, const gl::Texture& fallback) { return tex >= 0 ? textures_[tex].id() : fallback.id(); };
    const GLuint ids[4] = {id(t.baseColor, white_), id(t.normal, flatNormal_), id(t.specular, white_), id(t.emissive, white_)};
    glBindTextures(binding::MATERIAL_BASE_COLOR_TEXTURE, 4, ids);
    glBindSamplers(binding::MATERIAL_BASE_COLOR_TEXTURE, 4, t.samplers);
    glBindTextureUnit(binding::MATERIAL_OCCLUSION_TEXTURE, id(t.occlusion, white_));
    glBindSampler(binding::MATERIAL_OCCLUSION_TEXTURE, t.samplers[Material::OcclusionSlot]);
}

bool GpuScene::matches(const Draw& d, Filter f) {
    if (f == Filter::All) return true;
    const bool blend = d.alphaMode == AlphaMode::Blend;
    return f == Filter::Blend ? blend : !blend;
}

glm::mat4 GpuScene::relativeModel(const glm::mat4& model) const {
    glm::dmat4 m(model);
    m[3] -= glm::dvec4(origin_, 0.0);
    return glm::mat4(m);
}

void GpuScene::draw(const gl::Program& program, Filter filter, bool bindTextures) const {
    drawImpl(program, filter, bindTextures, nullptr);
}

void GpuScene::drawEach(const gl::Program& program, Filter filter, const PerDraw& before) const {
    drawImpl(program, filter, true, &before);
}

void GpuScene::drawImpl(const gl::Program& program, Filter filter, bool bindTextures, const PerDraw* before) const {
    std::vector<std::size_t> order;
    order.reserve(draws_.size());
    for (std::size_t i = 0; i < draws_.size(); ++i)
        if (matches(draws_[i], filter)) order.push_back(i);
    drawList(program, order, bindTextures, before);
}

void GpuScene::drawInOrder(const gl::Program& program, const std::vector<std::size_t>& order, bool backFacesFirst) const {
    drawList(program, order, true, nullptr, backFacesFirst);
}

void GpuScene::drawList(const gl::Program& program, const std::vector<std::size_t>& order, bool bindTextures,
                        const PerDraw* before, bool backFacesFirst) const {
    if (draws_.empty() || order.empty()) return;
    vao_.bind();
    materials_.bindBase(GL_SHADER_STORAGE_BUFFER, binding::MATERIAL_SSBO);
    int boundMaterial = -1;
    bool cullOn = true;
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    for (std::size_t i : order) {
        const Draw& d = draws_.at(i);
        // Right before its draw: it sets the program's per-draw uniforms.
        if (before && !(*before)(i, d)) continue;
        if (d.doubleSided == cullOn) {
            cullOn = !d.doubleSided;
            if (cullOn) glEnable(GL_CULL_FACE);
            else glDisable(GL_CULL_FACE);
        }
        if (bindTextures && d.material != boundMaterial) {
            bindMaterialTextures(d.material);
            boundMaterial = d.material;
        }
        glFrontFace(d.mirrored ? GL_CW : GL_CCW);
        program.set(0, relativeModel(d.model));
        program.set(1, d.material);
        const auto drawIt = [&] {
            glDrawElementsBaseVertex(GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT,
                                     reinterpret_cast<const void*>(d.indexOffsetBytes), d.baseVertex);
        };
        if (backFacesFirst && d.doubleSided) {
            glEnable(GL_CULL_FACE);
            glCullFace(GL_FRONT);
            drawIt();
            glCullFace(GL_BACK);
            drawIt();
            glDisable(GL_CULL_FACE);  // as cullOn says for a double-sided draw
        } else {
            drawIt();
        }
    }
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    // The glTF samplers override the textures' own state: unbind them so later
    // passes sampling through the material maps' units get their textures' settings.
    if (bindTextures) {
        glBindSamplers(binding::MATERIAL_BASE_COLOR_TEXTURE, 4, nullptr);
        glBindSampler(binding::MATERIAL_OCCLUSION_TEXTURE, 0);
    }
}

void GpuScene::drawDepthOnly(const gl::Program& program, const std::vector<std::size_t>& order) const {
    if (draws_.empty() || order.empty()) return;
    vao_.bind();
    for (std::size_t i : order) {
        const Draw& d = draws_.at(i);
        glFrontFace(d.mirrored ? GL_CW : GL_CCW);
        program.set(0, relativeModel(d.model));
        glDrawElementsBaseVertex(GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(d.indexOffsetBytes), d.baseVertex);
    }
    glFrontFace(GL_CCW);
}

}  // namespace dw
