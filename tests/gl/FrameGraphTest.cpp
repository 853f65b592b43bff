// The frame graph's promises: a new pass is one class and one registration
// line (it appears in the pass list, the output registry and, for a post
// pass, in `final`); managed resources exist only while something needs them;
// the order follows the read / write / modify edges.
#include <gtest/gtest.h>

#include <algorithm>

#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/Program.h"
#include "renderer/graph/PassCatalog.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "renderer/lighting/LightTable.h"
#include "renderer/lighting/LightingStrategy.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

// A post pass that exists only in this test binary: 1 - colour of the chain's
// current image. Off by default, so the other tests in this binary see the
// built-in chain.
class InvertPass : public RenderPass {
public:
    explicit InvertPass(KnobRegistry& knobs) {
        enabled_ = knobs.addBool("invert.enabled", false, "invert", "test-only: invert the display image");
    }
    const char* name() const override { return "invert"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"invert.result", OutputKind::Color, "the inverted image", texture2D(GL_RGBA8)}};
    }
    PassIO inputs(const KnobRegistry&) const override { return {{kCurrentImage}, {}}; }
    std::string skipReason(const KnobRegistry& knobs, const Scene&) const override {
        return knobs.get(enabled_) ? std::string() : "switched off (invert.enabled = false)";
    }
    void setup(gl::ShaderLibrary& shaders) override {
        const char* frag =
            "#version 450 core\n"
            "layout(binding = 0) uniform sampler2D uImage;\n"
            "out vec4 outColor;\n"
            "void main() { vec4 c = texelFetch(uImage, ivec2(gl_FragCoord.xy), 0); outColor = vec4(1.0 - c.rgb, 1.0); }\n";
        program_ = gl::Program::link(
            {{GL_VERTEX_SHADER, gl::ShaderSource::load(shaders.root(), "fullscreen.vert", {})},
             {GL_FRAGMENT_SHADER, gl::ShaderSource::fromString(shaders.root(), "invert.frag", frag, {})}});
    }
    void execute(FrameContext& ctx) override {
        ctx.currentImage().bind(0);
        target_.get(ctx, {"invert.result"}, {}, "invert").bind();
        program_.use();
        triangle_.draw();
    }

private:
    BoolKnob enabled_;
    gl::Program program_;
    gl::FullscreenTriangle triangle_;
    TargetFramebuffer target_;
};

// The one line that adds it.
const RegisterPass<InvertPass> registerInvert(PassStage::Post);

bool hasResource(const Pipeline& p, const std::string& name) {
    const auto r = p.resources();
    return std::any_of(r.begin(), r.end(), [&](const ResourceRecord& x) { return x.name == name; });
}

}  // namespace

TEST(FrameGraph, ARegisteredPostPassJoinsThePassListTheOutputsAndTheChain) {
    auto s = test::makeSession(48, 27);
    s->loadScene("spheres");
    // In `list passes` (the same function), after FXAA, reading the chain's image.
    const auto list = s->pipeline().passList();
    auto it = std::find_if(list.begin(), list.end(), [](const PassInfo& p) { return p.name == "invert"; });
    ASSERT_NE(it, list.end());
    EXPECT_EQ(it->stage, PassStage::Post);
    EXPECT_EQ(it->reads, (std::vector<std::string>{"fxaa.result"}));
    EXPECT_EQ(std::prev(it)->name, "taa");  // after the anti-aliasing passes (ssaa, taa off: it reads FXAA's image)
    ASSERT_NE(s->pipeline().outputs().find("invert.result"), nullptr);

    // Off: final is FXAA's image and the pass allocates nothing.
    s->render();
    const FloatImage plain = s->readRaw("final");
    EXPECT_EQ(s->pipeline().resolveFinal(), "fxaa.result");
    EXPECT_FALSE(hasResource(s->pipeline(), "invert.result"));

    // On: final is its output, and every pixel is 1 - the image before it.
    s->knobs().setFromString("invert.enabled", "true");
    const FrameReport r = s->render();
    EXPECT_TRUE(r.find("invert")->ran);
    EXPECT_EQ(s->pipeline().resolveFinal(), "invert.result");
    EXPECT_EQ(s->pipeline().outputs().find("final")->pass, "invert");
    const FloatImage inverted = s->readRaw("final");
    ASSERT_EQ(inverted.width, plain.width);
    double worst = 0.0;
    for (int y = 0; y < plain.height; ++y)
        for (int x = 0; x < plain.width; ++x)
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(1.0 - plain.at(x, y, c) - inverted.at(x, y, c)));
    EXPECT_LT(worst, 1.0 / 255.0 + 1e-6);

    // With depth of field on, the chain is tonemap -> dof -> fxaa -> invert.
    s->knobs().setFromString("dof.enabled", "true");
    const auto chain = s->pipeline().passList();
    auto find = [&](const char* n) {
        return *std::find_if(chain.begin(), chain.end(), [&](const PassInfo& p) { return p.name == n; });
    };
    EXPECT_EQ(find("dof").reads.front(), "tonemap.result");
    EXPECT_EQ(find("fxaa").reads.front(), "dof.result");
    EXPECT_EQ(find("invert").reads.front(), "fxaa.result");
}

TEST(FrameGraph, UnusedResourcesAreNotAllocated) {
    auto s = test::makeSession(64, 36);
    s->loadScene("default");
    s->render();
    EXPECT_TRUE(hasResource(s->pipeline(), "ao.raw"));
    EXPECT_TRUE(hasResource(s->pipeline(), "ao.filtered"));
    s->knobs().setFromString("ao.enabled", "false");
    s->render();
    EXPECT_FALSE(hasResource(s->pipeline(), "ao.raw"));
    EXPECT_FALSE(hasResource(s->pipeline(), "ao.filtered"));
    EXPECT_EQ(s->pipeline().outputs().find("ao.raw")->texture, nullptr);
    // Inspecting one G-buffer channel allocates the G-buffer and nothing downstream.
    s->render({{"gbuffer.normal"}});
    EXPECT_TRUE(hasResource(s->pipeline(), "gbuffer.normal"));
    EXPECT_FALSE(hasResource(s->pipeline(), "tonemap.result"));
    EXPECT_FALSE(hasResource(s->pipeline(), "sky"));
    // On-demand outputs exist only while asked for.
    s->knobs().setFromString("dof.enabled", "true");
    s->render();
    EXPECT_TRUE(hasResource(s->pipeline(), "dof.result"));
    EXPECT_FALSE(hasResource(s->pipeline(), "dof.coc"));
    s->render({{"final", "dof.coc"}});
    EXPECT_TRUE(hasResource(s->pipeline(), "dof.coc"));
}

TEST(FrameGraph, ResourcesFollowTheirDescriptorsAndKnobs) {
    auto s = test::makeSession(64, 36);
    s->loadScene("default");
    s->render();
    const auto find = [&](const char* name) {
        for (const auto& r : s->pipeline().resources())
            if (r.name == name) return r;
        ADD_FAILURE() << name;
        return ResourceRecord{};
    };
    EXPECT_EQ(find("ao.raw").desc.width, 32);  // half resolution by default
    EXPECT_EQ(find("gbuffer.depth").desc.format, static_cast<GLenum>(GL_DEPTH32F_STENCIL8));
    EXPECT_EQ(find("gbuffer.depth").bytes, 64u * 36u * 5u);
    const std::uint64_t before = s->pipeline().outputs().find("ao.raw")->serial;
    s->knobs().setFromString("ssao.resolution", "quarter");
    s->render();
    EXPECT_EQ(find("ao.raw").desc.width, 16);
    EXPECT_NE(s->pipeline().outputs().find("ao.raw")->serial, before);
    // A frame that changes nothing re-allocates nothing.
    const std::uint64_t same = s->pipeline().outputs().find("ao.raw")->serial;
    s->render();
    EXPECT_EQ(s->pipeline().outputs().find("ao.raw")->serial, same);
}

TEST(FrameGraph, KnobsReadAcrossPassesAreCheckedOnce) {
    KnobRegistry knobs;
    knobs.addBool("a.flag", true, "a", "");
    EXPECT_NO_THROW(knobs.requireBool("a.flag"));
    EXPECT_THROW(knobs.requireFloat("a.flag"), Error);
    EXPECT_THROW(knobs.requireBool("b.missing"), Error);
}

namespace {

// A lighting strategy that exists only in this test binary: brute force, but
// it records which light-table rows it was given.
class RecordingStrategy : public LightingStrategy {
public:
    explicit RecordingStrategy(KnobRegistry&) {}
    const char* name() const override { return "test_recording"; }
    std::string description() const override { return "test-only: every light full-screen, recording the rows"; }
    StrategyCounts shade(LightingFrame& f) override {
        StrategyCounts c;
        rows().clear();
        const gl::Program& program = f.shading.fullscreen(f.counting);
        for (const LightTableEntry* e : f.lights) {
            rows().push_back(e->row);
            f.beginLight(*e);
            program.use();
            program.set(0, e->row);
            f.shading.drawFullscreenTriangle();
            ++c.fullscreen;
        }
        return c;
    }
    static std::vector<int>& rows() {
        static std::vector<int> r;
        return r;
    }
};

// The one line that adds it.
const RegisterLightingStrategy<RecordingStrategy> registerRecording;

}  // namespace

TEST(FrameGraph, ARegisteredLightingStrategyIsAChoiceAndShadesTheSameImage) {
    auto s = test::makeSession(64, 36);
    s->loadScene("default");
    const auto id = s->knobs().find("lighting.strategy");
    ASSERT_TRUE(id);
    const auto& choices = s->knobs().spec(*id).choices;
    EXPECT_NE(std::find(choices.begin(), choices.end(), "test_recording"), choices.end());
    EXPECT_EQ(choices.front(), "stencil_volumes");  // the built-in default stays first

    s->knobs().setFromString("lighting.strategy", "fullscreen");
    s->render({{"lbuffer"}});
    const FloatImage brute = s->readRaw("lbuffer");
    s->knobs().setFromString("lighting.strategy", "test_recording");
    const FrameReport r = s->render({{"lbuffer"}});
    EXPECT_NE(r.find("lighting")->stats.find("test_recording"), std::string::npos);
    const FloatImage recorded = s->readRaw("lbuffer");
    EXPECT_EQ(test::maxAbsDifference(brute, recorded, 3), 0.0);
    // It was handed every bounded light of the table: the default scene's 36 point and 8 spot lights.
    EXPECT_EQ(RecordingStrategy::rows().size(), 44u);
}

namespace {

// A test-only pass that adds a constant into another pass's target, as
// transparency compositing adds into the L-buffer. Registered at the earliest
// stage on purpose: the modify edge, not the stage, must place it after the
// lighting pass and before everything that reads the L-buffer.
class AddIntoLBufferPass : public RenderPass {
public:
    explicit AddIntoLBufferPass(KnobRegistry& knobs) {
        enabled_ = knobs.addBool("add_glow.enabled", false, "add_glow", "test-only: add 0.25 into the L-buffer");
    }
    const char* name() const override { return "add_glow"; }
    std::vector<OutputDecl> outputs() const override { return {}; }
    PassIO inputs(const KnobRegistry&) const override { return {{}, {}, {"lbuffer"}}; }
    std::string skipReason(const KnobRegistry& knobs, const Scene&) const override {
        return knobs.get(enabled_) ? std::string() : "switched off";
    }
    void setup(gl::ShaderLibrary& shaders) override {
        const char* frag = "#version 450 core\nout vec4 outColor;\nvoid main() { outColor = vec4(0.25, 0.25, 0.25, 0.0); }\n";
        program_ = gl::Program::link(
            {{GL_VERTEX_SHADER, gl::ShaderSource::load(shaders.root(), "fullscreen.vert", {})},
             {GL_FRAGMENT_SHADER, gl::ShaderSource::fromString(shaders.root(), "add.frag", frag, {})}});
    }
    void execute(FrameContext& ctx) override {
        target_.get(ctx, {"lbuffer"}, {}, "add glow").bind();
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);  // adds into what the lighting pass wrote
        program_.use();
        triangle_.draw();
    }

private:
    BoolKnob enabled_;
    gl::Program program_;
    TargetFramebuffer target_;
    gl::FullscreenTriangle triangle_;
};

const RegisterPass<AddIntoLBufferPass> registerAddGlow(PassStage::GBuffer);

}  // namespace

TEST(FrameGraph, APassThatModifiesAnotherPassesTargetRunsBetweenItsWriterAndItsReaders) {
    auto s = test::makeSession(48, 27);
    s->loadScene("spheres");
    s->render({{"lbuffer"}});
    const FloatImage before = s->readRaw("lbuffer");
    s->knobs().setFromString("add_glow.enabled", "true");
    const FrameReport r = s->render({{"final", "lbuffer"}});
    std::vector<std::string> order;
    for (const auto& p : r.passes)
        if (p.ran) order.push_back(p.name);
    const auto at = [&](const char* n) { return std::find(order.begin(), order.end(), n) - order.begin(); };
    EXPECT_GT(at("add_glow"), at("lighting"));
    EXPECT_LT(at("add_glow"), at("luminance"));
    EXPECT_LT(at("add_glow"), at("tonemap"));
    const FloatImage after = s->readRaw("lbuffer");
    double worst = 0.0;
    for (int y = 0; y < before.height; ++y)
        for (int x = 0; x < before.width; ++x)
            worst = std::max(worst, std::abs(after.at(x, y, 0) - before.at(x, y, 0) - 0.25) / (1.0 + before.at(x, y, 0)));
    EXPECT_LT(worst, 2e-3);  // RGBA16F rounding
    // Nothing reads the L-buffer when only the G-buffer is asked for: the modifier does not run either.
    EXPECT_FALSE(s->render({{"gbuffer.depth"}}).find("add_glow")->ran);
}

TEST(FrameGraph, ShadowArraysHoldEveryMapWhenShownAndRefuseWhenEmpty) {
    auto s = test::makeSession(64, 36);
    s->loadScene("default");  // the sun and two spots cast shadows; no point light does
    s->knobs().setFromString("shadows.map_size", "64");
    ASSERT_TRUE(s->knobs().get(BoolKnob{*s->knobs().find("shadows.reuse_map")}));
    s->render({{"shadow.maps"}});
    EXPECT_EQ(s->pipeline().outputs().find("shadow.maps")->texture->layers(), 3);  // kept, not one reused layer
    try {
        s->render({{"shadow.cubes"}});
        FAIL() << "an empty cube array was shown";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("shadow.cubes is empty"), std::string::npos) << e.what();
    }
    // The light table asked for on its own carries every shadow lookup (mode != 0 for the three casters).
    s->render({{"lights.table"}});
    const PublishedOutput* table = s->pipeline().outputs().find("lights.table");
    ASSERT_NE(table->buffer, nullptr);
    std::vector<LightGpu> rows(table->desc.bytes / sizeof(LightGpu));
    table->buffer->read(0, rows.size() * sizeof(LightGpu), rows.data());
    int withMaps = 0;
    for (const LightGpu& r : rows) withMaps += r.shadowParams.x > 0.5f ? 1 : 0;
    EXPECT_EQ(withMaps, 3);
}
