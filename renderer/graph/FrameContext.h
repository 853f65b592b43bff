#pragma once
// What a pass sees while it executes one frame.
#include <cstdint>
#include <glm/glm.hpp>
#include <set>
#include <string>

#include "renderer/gl/DepthConvention.h"
#include "renderer/graph/OutputRegistry.h"
#include "shaders/params/camera.h"

namespace dw {

class AoMethod;
class GpuScene;
class KnobRegistry;
class ShadowService;
struct LightTable;
class PassTimer;
struct Scene;
namespace gl {
class ShaderLibrary;
class Texture;
class Buffer;
}

// The camera block (gpu::CameraBlock, declared once in
// shaders/params/camera.h for C++ and shaders/common/camera.glsl) and the
// frame's world origin (C++ only: Pipeline uploads the gpu::CameraBlock part,
// the shaders never read it). Rendering is camera-relative: every world
// position reaches the GPU minus `origin` (the camera's position, subtracted
// in double precision), so `view` is a rotation and a scene 1e5 or 1e7 from
// the world origin keeps float's full precision near the camera. "World" in
// the shaders means world - origin.
struct CameraUniforms : gpu::CameraBlock {
    // Identity matrices, no viewport, DepthConvention::uniform() of reversed depth.
    CameraUniforms();

    glm::dvec3 origin{0.0};  // world position of the frame's origin (the camera), not uploaded to shaders

    // Absolute world space to view / clip space, in double precision.
    glm::dmat4 worldToView() const;
    glm::dmat4 worldToClip() const;
    // A world-space model matrix made relative to `origin` (what the GPU gets).
    glm::mat4 relative(const glm::mat4& model) const;
};

struct FrameContext {
    const Scene& scene;
    const GpuScene& gpu;
    const KnobRegistry& knobs;
    OutputRegistry& outputs;
    gl::ShaderLibrary& shaders;
    CameraUniforms camera;
    int width = 0;
    int height = 0;
    std::uint64_t frameIndex = 0;
    // Every output something consumes this frame (the request and pass inputs).
    std::set<std::string> wanted;
    // For sub-spans inside a pass (beginSubSpan/endSubSpan); may be null.
    PassTimer* timer = nullptr;

    // What the caller asked for this frame ("final" resolved), as opposed to
    // what passes consume: a pass may do more when its output is looked at.
    std::set<std::string> requested;
    // Whether an output is consumed this frame; passes skip optional work otherwise.
    bool wants(const std::string& name) const { return wanted.count(name) != 0; }

    // A Post pass's input image this frame (what kCurrentImage stands for).
    std::string image;
    // Frame data that is not an image or a buffer (Filament's blackboard),
    // set by the pass that makes it and null when that pass did not run:
    // the light table's CPU side (lights pass) and the shadow maps (shadows pass).
    LightTable* lightTable = nullptr;
    ShadowService* shadows = nullptr;
    // The AO method that wrote ao.raw (ao pass), for the shared filter.
    const AoMethod* aoMethod = nullptr;

    // Whether an (optional) input was written earlier this frame.
    bool produced(const std::string& name) const {
        const PublishedOutput* o = outputs.find(name);
        return o && o->producedThisFrame && o->allocated();
    }
    // An output's texture or buffer; throws dw::Error if it is not allocated
    // (a pass reading what it did not declare, or a resource of the wrong kind).
    const PublishedOutput& output(const std::string& name) const;
    const gl::Texture& texture(const std::string& name) const;
    const gl::Buffer& buffer(const std::string& name) const;
    // The current image of the post chain.
    const gl::Texture& currentImage() const { return texture(image); }
    // The depth convention of this frame (the depth.mode knob).
    DepthConvention depth() const { return DepthConvention::fromUniform(camera.depth); }
};

}  // namespace dw
