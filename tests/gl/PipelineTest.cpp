// The pipeline runs only what the request and the knobs need, says why the
// rest did not run, and times what ran.
#include <gtest/gtest.h>

#include "renderer/Error.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {
std::vector<std::string> ran(const FrameReport& r) {
    std::vector<std::string> names;
    for (const auto& p : r.passes)
        if (p.ran) names.push_back(p.name);
    return names;
}
}  // namespace

TEST(Pipeline, TheFinalImageRunsTheSeedOrderAndSkipsTheDecoder) {
    auto s = test::makeSession(96, 54);
    s->loadScene("default");
    const FrameReport r = s->render();
    // Seed 002 section 6 with the sky, the light table and the shadow maps before the L-buffer and FXAA last.
    EXPECT_EQ(ran(r), (std::vector<std::string>{"geometry", "ao", "ao_filter", "skybox", "lights", "shadows", "lighting", "luminance", "bloom",
                                                "tonemap", "fxaa"}));
    EXPECT_EQ(r.find("gbuffer_decode")->reason, "nothing this frame consumes its outputs");
    EXPECT_EQ(r.find("dof")->reason, "switched off (dof.enabled = false)");
    EXPECT_NE(r.find("lighting")->stats.find("lights"), std::string::npos);
    // "final" is the last post pass's result, and is listed under it.
    EXPECT_EQ(s->pipeline().outputs().find("final")->texture, s->pipeline().outputs().find("fxaa.result")->texture);
    EXPECT_EQ(s->pipeline().outputs().find("final")->pass, "fxaa");
}

TEST(Pipeline, InspectingAGBufferRunsOnlyTheGeometryPass) {
    auto s = test::makeSession(96, 54);
    s->loadScene("spheres");
    EXPECT_EQ(ran(s->render({{"gbuffer.normal"}})), (std::vector<std::string>{"geometry"}));
    EXPECT_EQ(ran(s->render({{"gbuffer.view_position"}})), (std::vector<std::string>{"geometry", "gbuffer_decode"}));
}

TEST(Pipeline, TheSimpleToneMapperNeedsNoLuminancePass) {
    auto s = test::makeSession(96, 54);
    s->loadScene("spheres");
    s->knobs().setFromString("tonemap.operator", "simple");
    s->knobs().setFromString("bloom.enabled", "false");  // bloom's threshold needs the statistics too
    const FrameReport r = s->render();
    EXPECT_FALSE(r.find("luminance")->ran);
    EXPECT_EQ(r.find("luminance")->reason, "nothing this frame consumes its outputs");
    // Asking for the statistics explicitly runs it again.
    EXPECT_TRUE(s->render({{"final", "luminance.stats"}}).find("luminance")->ran);
}

TEST(Pipeline, UnknownBuffersAreRejectedWithAHint) {
    auto s = test::makeSession(32, 32);
    s->loadScene("spheres");
    try {
        s->render({{"gbuffer.nope"}});
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("list buffers"), std::string::npos);
    }
}

TEST(Pipeline, EveryPassThatRanIsTimed) {
    auto s = test::makeSession(64, 36);
    s->loadScene("default");
    FrameReport r;
    for (int i = 0; i < 4; ++i) r = s->render();
    s->pipeline().timer().collect(true);
    for (const auto& p : r.passes) {
        const TimingStats g = s->pipeline().timer().gpuStats(p.name);
        if (p.ran) {
            EXPECT_EQ(g.count, 4) << p.name;
            EXPECT_GE(g.min, 0.0f) << p.name;
        } else {
            EXPECT_EQ(g.count, 0) << p.name;
        }
    }
    const TimingStats frame = s->pipeline().timer().gpuStats(PassTimer::kFrameSeries);
    EXPECT_EQ(frame.count, 4);
    EXPECT_GE(frame.median, s->pipeline().timer().gpuStats("lighting").median);
}

TEST(Pipeline, ResizeRecreatesEverySizeDependentBuffer) {
    auto s = test::makeSession(64, 36);
    s->loadScene("default");
    s->render();
    s->resize(80, 50);
    s->render({{"final", "gbuffer.view_normal"}});
    for (const char* name : {"gbuffer.albedo", "gbuffer.normal", "gbuffer.depth", "gbuffer.view_normal", "ao.filtered", "sky",
                             "lbuffer", "tonemap.result", "fxaa.result", "final"}) {
        const PublishedOutput* o = s->pipeline().outputs().find(name);
        ASSERT_NE(o->texture, nullptr) << name;
        EXPECT_EQ(o->texture->width(), 80) << name;
        EXPECT_EQ(o->texture->height(), 50) << name;
    }
    EXPECT_EQ(s->pipeline().outputs().find("ao.raw")->texture->width(), 40);  // half resolution by default
    EXPECT_EQ(s->pipeline().outputs().find("bloom.bright")->texture->width(), 40);
    EXPECT_EQ(s->readRaw("final").width, 80);
}

TEST(Pipeline, BadSceneSettingsKeepThePreviousSceneAndKnobs) {
    auto s = test::makeSession(32, 32);
    s->loadScene("spheres");
    const std::string before = s->scene().name;
    Scene bad = test::planeScene();
    bad.source = "bad.json";
    bad.settings = {{"tonemap.key", "99"}};
    EXPECT_THROW(s->setScene(std::move(bad)), FileError);
    EXPECT_EQ(s->scene().name, before);
    EXPECT_FLOAT_EQ(static_cast<float>(s->knobs().value(*s->knobs().find("tonemap.key"))), 0.18f);
}
