#pragma once
// The scene's GPU copy: one vertex and one index buffer for all meshes, one
// texture per (image, colour space) the materials use, a material SSBO and the
// draw list. Passes draw through drawOpaque(); they never touch raw GL names.
#include <functional>
#include <glm/glm.hpp>
#include <map>
#include <tuple>
#include <vector>

#include "renderer/gl/Buffer.h"
#include "renderer/gl/Program.h"
#include "renderer/gl/Sampler.h"
#include "renderer/gl/Texture.h"
#include "renderer/gl/VertexArray.h"
#include "renderer/scene/GpuSkinning.h"
#include "renderer/scene/Scene.h"
#include "shaders/common/bindings.glsl"  // dw::binding, the binding points

namespace dw {

class GpuScene {
public:
    struct Draw {
        int mesh = 0;
        int material = 0;
        glm::mat4 model{1.0f};
        GLsizei indexCount = 0;
        std::size_t indexOffsetBytes = 0;
        GLint baseVertex = 0;
        AlphaMode alphaMode = AlphaMode::Opaque;
        bool doubleSided = false;
        // The model matrix has a negative determinant (a mirroring scale): its
        // triangles' winding flips, so front faces are clockwise (glTF 2.0,
        // "Transformations").
        bool mirrored = false;
        Bounds bounds;  // world-space box of the instance (its mesh's box under `model`)
        int instance = 0;  // into Scene::instances
    };
    enum class Filter { Opaque, Blend, All };

    // Call on a fresh GpuScene. `shaders`: where the skinning program
    // (shaders/scene/skin.comp) comes from; null, or setGpuPosing(false)
    // before, poses on the CPU only (poseScene's vertices uploaded).
    void upload(const Scene& scene, gl::ShaderLibrary* shaders = nullptr);
    // After poseScene (ScenePose.h) posed the uploaded scene at another time:
    // the deformed meshes' vertices written again, every draw's model matrix
    // and box, and the scene's bounds. The vertices by GpuSkinning's compute
    // dispatch (joint matrices and morph weights uploaded, the rest on the
    // GPU since upload), or, with GPU posing off, poseScene's CPU vertices
    // uploaded (their range of the vertex buffer, which is dynamic for a
    // scene with animation). No-op without animation.
    void updatePose(const Scene& scene);
    // Whether the deformed vertices are posed on the GPU (default) or
    // uploaded from the CPU's pose; switching writes the current pose the
    // new way. Both give the same vertices to float rounding (GpuSkinningTest).
    void setGpuPosing(bool on, const Scene* scene = nullptr);
    bool posesOnGpu() const { return gpuPosing_ && !skinning_.empty(); }
    // Bytes the last updatePose sent to the GPU (vertices or joint matrices and weights).
    std::size_t lastPoseUploadBytes() const { return lastPoseBytes_; }
    bool empty() const { return draws_.empty(); }
    const std::vector<Draw>& draws() const { return draws_; }
    // Of the uploaded geometry, which does not change until the next upload
    // (the workbench edits lights, not meshes): computed once, read per frame.
    const Bounds& bounds() const { return bounds_; }  // (of the pose last uploaded)
    std::size_t triangleCount() const { return triangles_; }

    // Binds VAO, material SSBO and per-draw textures, then issues one draw per
    // instance that passes `filter`. Locations 0 and 1 of `program` receive the
    // model matrix and material index.
    // Material textures go to units binding::MATERIAL_BASE_COLOR_TEXTURE to
    // MATERIAL_EMISSIVE_TEXTURE (base colour, normal, specular / metallic-
    // roughness, emissive: four units in a row) and MATERIAL_OCCLUSION_TEXTURE,
    // each with its glTF sampler.
    void draw(const gl::Program& program, Filter filter, bool bindTextures = true) const;
    // As draw(), but calls `before(index into draws(), draw)` first for each
    // instance that passes `filter`: it sets the program's per-draw uniforms
    // and returns false to skip the instance (the forward lighting strategies).
    using PerDraw = std::function<bool(std::size_t, const Draw&)>;
    void drawEach(const gl::Program& program, Filter filter, const PerDraw& before) const;
    // Draws the instances `order` lists (indices into draws()), in that
    // order, whatever their alpha mode (the sorted forward transparency pass).
    // `backFacesFirst`: a double-sided draw is drawn twice, its back faces
    // (culling the front) and then its front faces, so a closed double-sided
    // object blended in one draw composites its far side under its near side.
    void drawInOrder(const gl::Program& program, const std::vector<std::size_t>& order, bool backFacesFirst = false) const;
    // Whether `draw` passes `filter` (Blend: alpha mode Blend; Opaque: the rest).
    static bool matches(const Draw& draw, Filter filter);
    // Draws geometry only (shadow maps): positions, model matrix at location 0,
    // of the instances `order` lists (indices into draws(), in that order; the
    // shadow maps pass the draws left after culling them against a map's volume).
    void drawDepthOnly(const gl::Program& program, const std::vector<std::size_t>& order) const;
    // The world position every draw's model matrix is made relative to, in
    // double precision, before it reaches the GPU (camera-relative rendering:
    // the pipeline sets the camera's position each frame, a shadow map its
    // light's while it draws). Not geometry, so settable on a const scene.
    void setDrawOrigin(const glm::dvec3& origin) const { origin_ = origin; }
    const glm::dvec3& drawOrigin() const { return origin_; }
    // gbuffer.texture_filter: the materials' textures filtered as their glTF
    // samplers ask (trilinear mip-mapping for a mip-mapped min filter) with at
    // most `anisotropy` anisotropic samples on the mip-mapped ones
    // (GL_TEXTURE_MAX_ANISOTROPY: 1 is none, 2..16 as aniso2..aniso16; capped
    // at maxAnisotropy()), or, with `baseLevel`, bilinearly at the base level,
    // one texel footprint, as the CPU reference samples
    // (renderer/reference/TextureSampler.h). Sampler objects are GL state, so
    // this changes no scene data; it costs a few GL calls when it changes.
    // Returns the anisotropy set (after the cap).
    float setTextureFiltering(bool baseLevel, float anisotropy) const;
    // The most anisotropy the filters use here: the device's
    // GL_MAX_TEXTURE_MAX_ANISOTROPY (deviceMaxAnisotropy), but 1 on llvmpipe,
    // whose anisotropic lookups spin for minutes at a grazing angle over a
    // texture repeated thousands of times (GpuScene.cpp). Need a current context.
    static float maxAnisotropy();
    static float deviceMaxAnisotropy();  // 1 without GL 4.6 or GL_EXT_texture_filter_anisotropic
    static bool onLlvmpipe();            // GL_RENDERER names llvmpipe
    std::size_t textureBytes() const { return textureBytes_; }
    // The sky's environment map (equirectangular 2D or cube), or null.
    const gl::Texture* environment() const { return environment_ ? &environment_ : nullptr; }

private:
    int textureFor(const Scene& scene, int image, bool srgb);
    // One sampler object per distinct glTF sampler (wrap S/T, min/mag filter).
    GLuint samplerFor(const TextureMapping& mapping);
    void applyFiltering(std::size_t sampler) const;
    void bindMaterialTextures(int material) const;
    void drawImpl(const gl::Program& program, Filter filter, bool bindTextures, const PerDraw* before) const;
    void drawList(const gl::Program& program, const std::vector<std::size_t>& order, bool bindTextures,
                  const PerDraw* before, bool backFacesFirst = false) const;
    glm::mat4 relativeModel(const glm::mat4& model) const;
    // d.model, d.mirrored and d.bounds from the instance's transform and its mesh's vertices.
    static void place(Draw& d, const Scene& scene);
    mutable glm::dvec3 origin_{0.0};

    gl::Buffer vertices_, indices_, materials_;
    gl::VertexArray vao_;
    std::vector<gl::Texture> textures_;
    std::map<std::pair<int, bool>, int> textureIndex_;
    struct MaterialTextures {
        int baseColor = -1, normal = -1, specular = -1, emissive = -1, occlusion = -1;
        GLuint samplers[Material::kSlotCount] = {};  // per slot, units 0-3 and binding::MATERIAL_OCCLUSION_TEXTURE
    };
    using SamplerKey = std::tuple<unsigned, unsigned, unsigned, unsigned>;
    std::vector<gl::Sampler> samplers_;
    std::vector<SamplerKey> samplerKeys_;  // per samplers_ entry
    std::map<SamplerKey, std::size_t> samplerIndex_;
    mutable bool baseLevel_ = false;
    mutable float anisotropy_ = 1.0f;
    std::vector<MaterialTextures> materialTextures_;
    gl::Texture white_, flatNormal_, environment_;
    std::vector<Draw> draws_;
    std::vector<GLint> baseVertex_;  // per mesh, its first vertex in vertices_
    void writePose(const Scene& scene);
    GpuSkinning skinning_;
    bool gpuPosing_ = true;
    std::size_t lastPoseBytes_ = 0;
    Bounds bounds_;
    std::size_t triangles_ = 0;
    std::size_t textureBytes_ = 0;
};

}  // namespace dw
