#pragma once
// Flames (seed 004, "Fire Simulation"): the scene's flame particles drawn as
// soft, camera-facing sprites, each the same particle that is a point light
// (scene/FlameParticles: position, age and light intensity are one function
// of the frame index), so the fire is seen and lights what is round it.
//
// A forward pass after the transparency pass, not a method of it: flames are
// emissive and added (blend ONE, ONE), and a sum is the same in any order, so
// they need no sorting and no per-pixel fragment storage (the A-buffer's
// samples would go to glass, not to hundreds of overlapping sprites). What it
// gives up: a flame behind a blended surface is added over it unfiltered.
//
// Reads gbuffer.depth (hidden behind opaque surfaces, soft-particle fade of
// flames.softness scene units in front of them); modifies lbuffer (adds the
// flames); writes flames.result (RGBA16F: the flames' radiance alone, alpha
// their summed coverage), both in one draw with two colour targets.
//
// Colour by temperature: each particle cools along its life from
// kFlameBirthKelvin to kFlameDeathKelvin, and its colour is the chromaticity
// of a black body at that temperature (Planck's law at 610, 550 and 465 nm,
// the brightest channel 1: orange-yellow at 2000 K, deep red at 1000 K); its
// radiance is that colour times its light's brightness (fading in at birth
// and out with age, flickering) times flames.intensity.
#include <glm/glm.hpp>

#include "renderer/graph/RenderPass.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/gl/ParamBuffer.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/VertexArray.h"
#include "renderer/knobs/KnobRegistry.h"
#include "shaders/params/flames.h"

namespace dw {

inline constexpr double kFlameBirthKelvin = 2000.0;
inline constexpr double kFlameDeathKelvin = 1000.0;

// A black body's colour at `kelvin` (> 0): Planck's spectral radiance at 610,
// 550 and 465 nm, divided by the largest of the three (so each channel is in
// (0, 1] and the largest is 1).
glm::vec3 blackbodyColour(double kelvin);
// A particle's temperature at `age` (0 birth .. 1 death): linear from
// kFlameBirthKelvin to kFlameDeathKelvin.
double flameTemperature(float age);

class FlamesPass : public RenderPass {
public:
    explicit FlamesPass(KnobRegistry& knobs);
    const char* name() const override { return "flames"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"flames.result", OutputKind::HdrColor,
                 "the flame particles' radiance alone, as added into the L-buffer (RGBA16F; alpha: summed coverage)",
                 texture2D(GL_RGBA16F)}};
    }
    PassIO inputs(const KnobRegistry&) const override { return {{"gbuffer.depth"}, {}, {"lbuffer"}}; }
    std::string skipReason(const KnobRegistry& knobs, const Scene& scene) const override;
    void setup(gl::ShaderLibrary& shaders) override;
    void execute(FrameContext& ctx) override;
    std::string stats() const override { return stats_; }

private:
    // The frame's particles into batches of the parameter block's size.
    std::vector<gpu::FlamesParams> batches(const FrameContext& ctx) const;
    BoolKnob enabled_;
    FloatKnob intensity_, size_, softness_;
    gl::ShaderLibrary::Handle program_;
    gl::ParamBuffer<gpu::FlamesParams> params_;
    gl::VertexArray vao_;
    TargetFramebuffer target_;
    std::string stats_;
};

}  // namespace dw
