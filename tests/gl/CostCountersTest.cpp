// The cost counters (issue 34): a pass's GL pipeline statistics and
// samples-passed queries, harvested with its timestamps. Cases whose answer
// is known: a full-screen triangle at W x H passes W x H samples and shades
// at least W x H fragments (llvmpipe counts its rasteriser's blocks: a few
// more, docs/bench.md), the same draw failing the depth test everywhere
// passes no sample, a pass that draws nothing counts 0, a dispatch of N
// invocations counts N; and two renders of the same frame give the same
// counts, bit for bit.
#include <gtest/gtest.h>

#include "renderer/gl/CounterQuery.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/Program.h"
#include "renderer/gl/ShaderSource.h"
#include "renderer/gl/Texture.h"
#include "renderer/graph/PassTimer.h"
#include "renderer/graph/TimingReport.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

constexpr int kW = 37, kH = 23;  // odd, so a count per 2x2 quad or per tile would not match

gl::Program link(GLenum stage, const char* name, const std::string& text,
                 std::vector<gl::ShaderStage> more = {}) {
    more.push_back({stage, gl::ShaderSource::fromString(test::tempDir(), name, text, {})});
    return gl::Program::link(more);
}

gl::Program fullscreenProgram() {
    const std::string vs =
        "#version 450 core\nvoid main() {\n"
        "    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
        "    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n}\n";
    const std::string fs = "#version 450 core\nout vec4 color;\nvoid main() { color = vec4(1.0, 0.5, 0.25, 1.0); }\n";
    return link(GL_FRAGMENT_SHADER, "counters.frag", fs,
                {{GL_VERTEX_SHADER, gl::ShaderSource::fromString(test::tempDir(), "counters.vert", vs, {})}});
}

gl::Program computeProgram() {
    return link(GL_COMPUTE_SHADER, "counters.comp",
                "#version 450 core\nlayout(local_size_x = 4) in;\n"
                "layout(std430, binding = 0) buffer B { uint v[]; };\nvoid main() { atomicAdd(v[0], 1u); }\n");
}

const TimingSample& lastSample(const PassTimer& timer, const std::string& series) {
    const PassTimer::Series* s = timer.find(series);
    if (!s || s->samples.empty()) throw std::runtime_error("no samples of " + series);
    return s->samples.back();
}

// One frame of four passes: a full-screen draw (depth 0.5 into a cleared
// depth buffer), the same draw again (fails GL_LESS everywhere), a pass that
// draws nothing, and a dispatch of 3 x 2 groups of 4 invocations.
struct Targets {
    gl::Texture color = gl::Texture::create2D(GL_RGBA8, kW, kH);
    gl::Texture depth = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, kW, kH);
    gl::Framebuffer fb = gl::Framebuffer::create("counters");
    gl::Program draw = fullscreenProgram();
    gl::Program dispatch = computeProgram();
    gl::FullscreenTriangle triangle;
    Targets() {
        fb.attachColor(0, color);
        fb.attachDepth(depth);
    }
};

void countFrame(PassTimer& timer, std::uint64_t frame) {
    Targets t;
    gl::Framebuffer& fb = t.fb;
    gl::Program& draw = t.draw;
    gl::Program& dispatch = t.dispatch;
    gl::FullscreenTriangle& triangle = t.triangle;
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferData(buffer, 16, nullptr, GL_DYNAMIC_DRAW);
    gl::resetPipelineState(kW, kH);
    fb.bind();
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    draw.use();
    timer.beginFrame(frame);
    for (const char* pass : {"full", "occluded"}) {
        timer.beginPass(pass);
        triangle.draw();
        timer.setPassBytes(static_cast<std::int64_t>(kW) * kH * 8);
        timer.endPass();
    }
    // The same triangle twice with the depth test passing everywhere, then
    // into the left half of the target: twice the counts, then half the samples.
    glDepthFunc(GL_ALWAYS);
    timer.beginPass("twice");
    triangle.draw();
    triangle.draw();
    timer.setPassBytes(0);
    timer.endPass();
    glViewport(0, 0, kW / 2, kH);
    timer.beginPass("half");
    triangle.draw();
    timer.setPassBytes(0);
    timer.endPass();
    glViewport(0, 0, kW, kH);
    glDepthFunc(GL_LESS);
    timer.beginPass("nothing");
    timer.setPassBytes(0);
    timer.endPass();
    timer.beginPass("compute");
    dispatch.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
    glDispatchCompute(3, 2, 1);
    timer.setPassBytes(16);
    timer.endPass();
    timer.endFrame();
    glDeleteBuffers(1, &buffer);
    gl::resetPipelineState(kW, kH);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace

TEST(CostCounters, KnownCasesCountWhatTheyDraw) {
    PassTimer timer;
    timer.setCounting(true);
    countFrame(timer, 0);
    timer.collect(true);
    const PassCounts full = lastSample(timer, "full").counts;
    const PassCounts occluded = lastSample(timer, "occluded").counts;
    const PassCounts nothing = lastSample(timer, "nothing").counts;
    const PassCounts compute = lastSample(timer, "compute").counts;
    const std::int64_t pixels = std::int64_t{kW} * kH;
    // Samples passed is core GL: every driver counts it.
    EXPECT_EQ(full[PassCounts::Samples], pixels);
    EXPECT_EQ(occluded[PassCounts::Samples], 0);  // every fragment fails GL_LESS against its own depth
    EXPECT_EQ(nothing[PassCounts::Samples], 0);
    EXPECT_EQ(full[PassCounts::Bytes], pixels * 8);
    ASSERT_TRUE(gl::hasPipelineStatistics()) << "llvmpipe offers GL_ARB_pipeline_statistics_query";
    // Every pixel shaded once, and no more than a block-wide margin besides
    // (llvmpipe: 1136 at 37x23; 4352 = 64 x 68 at 64x64).
    EXPECT_GE(full[PassCounts::Fragments], pixels);
    EXPECT_LE(full[PassCounts::Fragments], std::int64_t{kW + 8} * (kH + 8));
    EXPECT_EQ(full[PassCounts::Vertices], 3);
    EXPECT_EQ(full[PassCounts::Primitives], 1);
    EXPECT_EQ(full[PassCounts::Compute], 0);
    // A pass that draws nothing counts nothing.
    for (int i = 0; i < PassCounts::kCount; ++i) EXPECT_EQ(nothing[i], 0) << PassCounts::name(i);
    EXPECT_EQ(compute[PassCounts::Compute], 3 * 2 * 4);
    EXPECT_EQ(compute[PassCounts::Fragments], 0);
    // Twice the draws, twice every count; half the viewport, half the samples.
    const PassCounts twice = lastSample(timer, "twice").counts;
    const PassCounts half = lastSample(timer, "half").counts;
    for (int i : {PassCounts::Fragments, PassCounts::Samples, PassCounts::Primitives, PassCounts::Vertices})
        EXPECT_EQ(twice[i], 2 * full[i]) << PassCounts::name(i);
    EXPECT_EQ(half[PassCounts::Samples], std::int64_t{kW / 2} * kH);
    EXPECT_GE(half[PassCounts::Fragments], std::int64_t{kW / 2} * kH);
    EXPECT_LT(half[PassCounts::Fragments], full[PassCounts::Fragments]);
    // The frame's counters are the sums of its passes'.
    const PassCounts frame = lastSample(timer, PassTimer::kFrameSeries).counts;
    for (int i = 0; i < PassCounts::kCount; ++i)
        EXPECT_EQ(frame[i], full[i] + occluded[i] + twice[i] + half[i] + nothing[i] + compute[i]) << PassCounts::name(i);
    // llvmpipe shades before the depth test: the occluded draw costs the
    // same fragments; only samples passed sees the depth test's saving.
    const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (renderer.find("llvmpipe") != std::string::npos) {
        EXPECT_EQ(occluded[PassCounts::Fragments], full[PassCounts::Fragments]);
    }
    std::printf("full-screen draw: %lld fragment shader invocations, %lld samples passed; ",
                static_cast<long long>(full[PassCounts::Fragments]), static_cast<long long>(full[PassCounts::Samples]));
    std::printf("occluded full-screen draw: %lld fragment shader invocations, %lld samples passed (%s)\n",
                static_cast<long long>(occluded[PassCounts::Fragments]),
                static_cast<long long>(occluded[PassCounts::Samples]), reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
}

TEST(CostCounters, WithoutCountingNoneIsMeasured) {
    PassTimer timer;
    countFrame(timer, 0);
    timer.collect(true);
    EXPECT_FALSE(lastSample(timer, "full").counts.measured());
    EXPECT_FALSE(lastSample(timer, PassTimer::kFrameSeries).counts.measured());
}

TEST(CostCounters, TwoRendersOfTheSameFrameCountTheSame) {
    auto s = test::makeSession(96, 54);
    s->loadScene("default");
    PassTimer& timer = s->pipeline().timer();
    timer.setCounting(true);
    FrameReport last;
    for (int i = 0; i < 3; ++i) last = s->render();
    timer.collect(true);
    const TimingReport report = TimingReport::build(timer, last, last.frameIndex - 1, 1);
    ASSERT_TRUE(report.counted());
    for (const auto& series : timer.series()) {
        if (series.name.find('/') != std::string::npos) continue;  // spans inside a pass are not counted
        ASSERT_GE(series.samples.size(), 3u) << series.name;
        const PassCounts& a = series.samples[series.samples.size() - 2].counts;
        const PassCounts& b = series.samples.back().counts;
        EXPECT_TRUE(a.measured()) << series.name;
        EXPECT_EQ(a, b) << series.name << ": the counters differ between two renders of the same frame";
    }
    for (const auto& row : report.rows()) EXPECT_FALSE(row.countsDiffer) << row.series;
    // The tone mapper and FXAA are one full-screen triangle each: a sample per
    // pixel, the same fragments (at least one per pixel), 3 vertices.
    const PassCounts& tonemap = report.find("tonemap")->counts;
    EXPECT_EQ(tonemap[PassCounts::Samples], 96 * 54);
    EXPECT_GE(tonemap[PassCounts::Fragments], 96 * 54);
    EXPECT_EQ(tonemap[PassCounts::Fragments], report.find("fxaa")->counts[PassCounts::Fragments]);
    EXPECT_EQ(tonemap[PassCounts::Vertices], 3);
    EXPECT_EQ(tonemap[PassCounts::Primitives], 1);
    EXPECT_GT(report.find("geometry")->counts[PassCounts::Bytes], 0);
    EXPECT_NE(report.table().find("cost counters per frame (exact; the same in all 2 counted frame(s))"), std::string::npos)
        << report.table();
}
