// The buffer view, the pixel probe and the raw read-back for every resource
// kind: a multisample texture per sample and resolved, a per-pixel buffer as an
// image and a fixed buffer as a table, a cube as an unfolded cross, arrays, cube
// arrays and 3D textures by layer, an integer texture. The outputs come from
// test-only passes registered below; nothing consumes them, so the pipeline
// runs them only when a test asks for them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "renderer/inspect/OutputReadback.h"
#include "renderer/inspect/PixelProbe.h"
#include "renderer/graph/RenderPass.h"
#include "renderer/gl/FullscreenTriangle.h"
#include "renderer/gl/Program.h"
#include "renderer/graph/PassCatalog.h"
#include "renderer/graph/TargetFramebuffer.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

int msSamples() {
    GLint maxSamples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    return std::clamp(maxSamples, 1, 4);
}

// Every sample of test.ms holds (sample + 1, x, y, 1), (x, y) the pixel (y from the bottom).
class TestMultisamplePass : public RenderPass {
public:
    explicit TestMultisamplePass(KnobRegistry&) {}
    const char* name() const override { return "test_ms"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"test.ms", OutputKind::Vector, "test: (sample + 1, x, y, 1) in every sample", textureMultisample(GL_RGBA16F, 4)}};
    }
    ResourceDesc resource(const OutputDecl& o, const KnobRegistry&) const override {
        ResourceDesc d = o.resource;
        d.samples = samples_;
        return d;
    }
    PassIO inputs(const KnobRegistry&) const override { return {}; }
    void setup(gl::ShaderLibrary& shaders) override {
        samples_ = msSamples();
        // gl_SampleID makes the shader run once per sample.
        program_ = gl::Program::link(
            {{GL_VERTEX_SHADER, gl::ShaderSource::load(shaders.root(), "fullscreen.vert", {})},
             {GL_FRAGMENT_SHADER, gl::ShaderSource::fromString(shaders.root(), "test_ms.frag", R"(#version 450 core
out vec4 outColor;
void main() { outColor = vec4(float(gl_SampleID + 1), floor(gl_FragCoord.xy), 1.0); }
)", {})}});
    }
    void execute(FrameContext& ctx) override {
        const gl::Texture& t = ctx.texture("test.ms");
        target_.get(ctx, {"test.ms"}, {}, "test ms").bind();
        glViewport(0, 0, t.width(), t.height());
        program_.use();
        glEnable(GL_MULTISAMPLE);  // the pipeline starts every pass with it off
        triangle_.draw();
    }

private:
    int samples_ = 1;
    gl::Program program_;
    gl::FullscreenTriangle triangle_;
    TargetFramebuffer target_;
};

// test.pixels: per pixel two words, x + 1000 y (y from the bottom) and 7.
// test.table: 5 elements of 3 floats, word k of element e = 10 e + k + 1.
class TestBufferPass : public RenderPass {
public:
    explicit TestBufferPass(KnobRegistry&) {}
    const char* name() const override { return "test_buffers"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"test.pixels", OutputKind::Count, "test: x + 1000 y and 7 per pixel (uint32)", bufferPerPixel(8, 8), 1},
                {"test.table", OutputKind::Scalar, "test: 5 elements of 3 floats", bufferFixed(60, 12), 1}};
    }
    PassIO inputs(const KnobRegistry&) const override { return {}; }
    void setup(gl::ShaderLibrary&) override {}
    void execute(FrameContext& ctx) override {
        std::vector<std::uint32_t> pixels;
        for (int y = 0; y < ctx.height; ++y)
            for (int x = 0; x < ctx.width; ++x) {
                pixels.push_back(static_cast<std::uint32_t>(x + 1000 * y));
                pixels.push_back(7u);
            }
        glNamedBufferSubData(ctx.buffer("test.pixels").id(), 0, static_cast<GLsizeiptr>(pixels.size() * 4), pixels.data());
        std::vector<float> table;
        for (int e = 0; e < 5; ++e)
            for (int k = 0; k < 3; ++k) table.push_back(static_cast<float>(10 * e + k + 1));
        glNamedBufferSubData(ctx.buffer("test.table").id(), 0, static_cast<GLsizeiptr>(table.size() * 4), table.data());
    }
};

ResourceDesc fixedTexture(ResourceKind kind, GLenum format, int w, int h, int layers) {
    ResourceDesc d;
    d.kind = kind;
    d.format = format;
    d.size = SizeMode::Fixed;
    d.width = w;
    d.height = h;
    d.layers = layers;
    return d;
}

// Texel (x, y) of layer (face, slice) z holds 100 z + 10 y + x + 1, so 0 means "no texel".
float layeredValue(int x, int y, int z) { return static_cast<float>(100 * z + 10 * y + x + 1); }

// test.array (4x2, 5 layers), test.cube (3x3), test.cube_array (2x2, 2 cubes),
// test.volume (2x2x3), all R32F; test.counts: R32UI at the frame size, x + 1000 y.
class TestLayersPass : public RenderPass {
public:
    explicit TestLayersPass(KnobRegistry&) {}
    const char* name() const override { return "test_layers"; }
    std::vector<OutputDecl> outputs() const override {
        return {{"test.array", OutputKind::Scalar, "test: 2D array", fixedTexture(ResourceKind::Texture2DArray, GL_R32F, 4, 2, 5), 1},
                {"test.cube", OutputKind::Scalar, "test: cube", fixedTexture(ResourceKind::TextureCube, GL_R32F, 3, 3, 1), 1},
                {"test.cube_array", OutputKind::Scalar, "test: cube array",
                 fixedTexture(ResourceKind::TextureCubeArray, GL_R32F, 2, 2, 12), 1},
                {"test.volume", OutputKind::Scalar, "test: 3D", fixedTexture(ResourceKind::Texture3D, GL_R32F, 2, 2, 3), 1},
                {"test.counts", OutputKind::Count, "test: x + 1000 y (R32UI)", texture2D(GL_R32UI), 1}};
    }
    PassIO inputs(const KnobRegistry&) const override { return {}; }
    void setup(gl::ShaderLibrary&) override {}
    void execute(FrameContext& ctx) override {
        auto fill = [&](const char* name, int layers) {
            const gl::Texture& t = ctx.texture(name);
            std::vector<float> v;
            for (int z = 0; z < layers; ++z)
                for (int y = 0; y < t.height(); ++y)
                    for (int x = 0; x < t.width(); ++x) v.push_back(layeredValue(x, y, z));
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTextureSubImage3D(t.id(), 0, 0, 0, 0, t.width(), t.height(), layers, GL_RED, GL_FLOAT, v.data());
        };
        fill("test.array", 5);
        fill("test.cube", 6);
        fill("test.cube_array", 12);
        fill("test.volume", 3);
        const gl::Texture& counts = ctx.texture("test.counts");
        std::vector<std::uint32_t> c;
        for (int y = 0; y < counts.height(); ++y)
            for (int x = 0; x < counts.width(); ++x) c.push_back(static_cast<std::uint32_t>(x + 1000 * y));
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage2D(counts.id(), 0, 0, 0, counts.width(), counts.height(), GL_RED_INTEGER, GL_UNSIGNED_INT, c.data());
    }
};

static RegisterPass<TestMultisamplePass> registerMs(PassStage::Screen);
static RegisterPass<TestBufferPass> registerBuffers(PassStage::Screen);
static RegisterPass<TestLayersPass> registerLayers(PassStage::Screen);

constexpr int kW = 32, kH = 16;

std::unique_ptr<RenderSession> session(std::vector<std::string> outputs) {
    auto s = test::makeSession(kW, kH);
    s->setScene(test::planeScene());
    s->render({std::move(outputs)});
    return s;
}

// The buffer view of `name` with a direct mapping of [lo, hi] in one channel.
FloatImage directView(RenderSession& s, const std::string& name, float lo, float hi, ViewSelection sel = {},
                      BufferViewSettings::Channel channel = BufferViewSettings::Channel::R) {
    BufferViewSettings v;
    v.mapping = BufferViewSettings::Mapping::Direct;
    v.channel = channel;
    v.autoRange = 0;
    v.rangeMin = lo;
    v.rangeMax = hi;
    v.layer = sel.layer;
    v.sample = sel.sample;
    return s.readDisplay(name, v);
}

// The view shows the raw read-back, cell for cell: same size, each value at
// the same place, empty cells dark.
void expectViewMatchesRaw(RenderSession& s, const std::string& name, ViewSelection sel, float hi) {
    const FloatImage raw = s.readRaw(name, sel);
    const FloatImage view = directView(s, name, 0.0f, hi, sel);
    ASSERT_EQ(view.width, raw.width) << name;
    ASSERT_EQ(view.height, raw.height) << name;
    for (int y = 0; y < raw.height; ++y)
        for (int x = 0; x < raw.width; ++x) {
            const float v = raw.at(x, y, 0);
            const float expected = v == 0.0f ? 0.03f : std::clamp(v / hi, 0.0f, 1.0f);
            ASSERT_NEAR(view.at(x, y, 0), expected, 1.0f / 255.0f) << name << " at " << x << "," << y;
        }
}

const ProbeValue* probed(const ProbeResult& r, const std::string& name) {
    for (const auto& v : r.values)
        if (v.output == name) return &v;
    return nullptr;
}

}  // namespace

TEST(ResourceViews, TestPassesRunOnlyWhenAsked) {
    auto s = test::makeSession(kW, kH);
    s->setScene(test::planeScene());
    const FrameReport r = s->render();
    for (const char* pass : {"test_ms", "test_buffers", "test_layers"}) {
        ASSERT_NE(r.find(pass), nullptr) << pass;
        EXPECT_FALSE(r.find(pass)->ran) << pass;
    }
    for (const auto& res : s->pipeline().resources()) EXPECT_NE(res.name.rfind("test.", 0), 0u) << res.name;
    const FrameReport ms = s->render({{"test.ms"}});
    EXPECT_TRUE(ms.find("test_ms")->ran);
    EXPECT_FALSE(ms.find("geometry")->ran);
}

TEST(ResourceViews, MultisamplePerSampleAndResolved) {
    auto s = session({"test.ms"});
    const PublishedOutput& o = *s->pipeline().outputs().find("test.ms");
    const int n = msSamples();
    ASSERT_EQ(sampleCount(o), n);
    const float mean = (n + 1) * 0.5f;
    // Raw read-back: one sample, or the mean of them.
    for (int sample = -1; sample < n; ++sample) {
        const FloatImage img = s->readRaw("test.ms", {-1, sample});
        ASSERT_EQ(img.width, kW);
        ASSERT_EQ(img.height, kH);
        ASSERT_EQ(img.channels, 4);
        for (int y = 0; y < kH; y += 5)
            for (int x = 0; x < kW; x += 3) {
                EXPECT_FLOAT_EQ(img.at(x, y, 0), sample < 0 ? mean : static_cast<float>(sample + 1));
                EXPECT_FLOAT_EQ(img.at(x, y, 1), static_cast<float>(x));
                EXPECT_FLOAT_EQ(img.at(x, y, 2), static_cast<float>(kH - 1 - y));
            }
    }
    // The view: the same values, and auto range finds them.
    for (int sample = -1; sample < n; ++sample) {
        const float value = sample < 0 ? mean : static_cast<float>(sample + 1);
        const FloatImage view = directView(*s, "test.ms", 0.0f, static_cast<float>(n + 1), {-1, sample});
        ASSERT_EQ(view.width, kW);
        EXPECT_NEAR(view.at(7, 3, 0), value / (n + 1), 1.0f / 255.0f) << sample;
        BufferViewSettings a;
        a.autoRange = 1;
        a.sample = sample;
        a.channel = BufferViewSettings::Channel::RGB;
        s->readDisplay("test.ms", a);
        auto [lo, hi] = s->bufferView().lastAutoRange();
        EXPECT_FLOAT_EQ(lo.r, value) << sample;
        EXPECT_FLOAT_EQ(hi.r, value) << sample;
        EXPECT_FLOAT_EQ(lo.g, 0.0f);
        EXPECT_FLOAT_EQ(hi.g, kW - 1.0f);
    }
    // The probe: every sample and their mean.
    const ProbeResult r = probePixel(s->pipeline(), 5, 2);
    const ProbeValue* v = probed(r, "test.ms");
    ASSERT_NE(v, nullptr);
    ASSERT_EQ(static_cast<int>(v->samples.size()), n);
    for (int i = 0; i < n; ++i) {
        EXPECT_FLOAT_EQ(v->samples[static_cast<size_t>(i)].r, i + 1.0f);
        EXPECT_FLOAT_EQ(v->samples[static_cast<size_t>(i)].g, 5.0f);
        EXPECT_FLOAT_EQ(v->samples[static_cast<size_t>(i)].b, kH - 1 - 2.0f);
    }
    EXPECT_FLOAT_EQ(v->raw.r, mean);
}

TEST(ResourceViews, PerPixelBufferIsAnImageAndFixedBufferATable) {
    auto s = session({"test.pixels", "test.table"});
    // Element y * width + x, y from the bottom; read-back rows are top-down.
    const FloatImage img = s->readRaw("test.pixels");
    ASSERT_EQ(img.width, kW);
    ASSERT_EQ(img.height, kH);
    ASSERT_EQ(img.channels, 1);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) ASSERT_EQ(img.at(x, kH - 1 - y, 0), static_cast<float>(x + 1000 * y)) << x << "," << y;
    // The view: counts as a heat map over their range; direct over [0, 32] on the bottom row.
    s->readDisplay("test.pixels");
    auto [lo, hi] = s->bufferView().lastAutoRange();
    EXPECT_FLOAT_EQ(lo.r, 0.0f);
    EXPECT_FLOAT_EQ(hi.r, (kW - 1) + 1000.0f * (kH - 1));
    const FloatImage view = directView(*s, "test.pixels", 0.0f, 32.0f);
    ASSERT_EQ(view.width, kW);
    ASSERT_EQ(view.height, kH);
    for (int x = 0; x < kW; ++x) EXPECT_NEAR(view.at(x, kH - 1, 0), x / 32.0f, 1.0f / 255.0f) << x;
    // The probe: the element's words at the pixel.
    const ProbeResult r = probePixel(s->pipeline(), 9, 4);
    const ProbeValue* v = probed(r, "test.pixels");
    ASSERT_NE(v, nullptr);
    const std::uint32_t expected = 9 + 1000 * (kH - 1 - 4);
    EXPECT_EQ(v->words, (std::vector<std::uint32_t>{expected, 7u}));
    EXPECT_EQ(v->channels, 2);
    EXPECT_FLOAT_EQ(v->raw.x, static_cast<float>(expected));
    EXPECT_FLOAT_EQ(v->raw.y, 7.0f);
    // A table: one row per element (element 0 on top), one column per word; no pixel in the probe.
    const FloatImage table = s->readRaw("test.table");
    ASSERT_EQ(table.width, 3);
    ASSERT_EQ(table.height, 5);
    for (int e = 0; e < 5; ++e)
        for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(table.at(k, e, 0), 10.0f * e + k + 1.0f);
    expectViewMatchesRaw(*s, "test.table", {}, 50.0f);
    EXPECT_EQ(probed(r, "test.table"), nullptr);
}

TEST(ResourceViews, CubeUnfoldsAsACross) {
    auto s = session({"test.cube", "test.cube_array"});
    // Cells of the 4x3 cross (top-down): +Y above +Z; -X +Z +X -Z; -Y below.
    const int faceAt[3][4] = {{-1, 2, -1, -1}, {1, 4, 0, 5}, {-1, 3, -1, -1}};
    auto expectCross = [&](const FloatImage& img, int originX, int size, int cube) {
        for (int cy = 0; cy < 3; ++cy)
            for (int cx = 0; cx < 4; ++cx)
                for (int v = 0; v < size; ++v)
                    for (int u = 0; u < size; ++u) {
                        const int face = faceAt[cy][cx];
                        // Row t = 0 of each face on top, as the cube map addresses it.
                        const float expected = face < 0 ? 0.0f : layeredValue(u, v, cube * 6 + face);
                        ASSERT_EQ(img.at(originX + cx * size + u, cy * size + v, 0), expected)
                            << "cell " << cx << "," << cy << " texel " << u << "," << v;
                    }
    };
    const FloatImage cube = s->readRaw("test.cube");
    ASSERT_EQ(cube.width, 12);
    ASSERT_EQ(cube.height, 9);
    expectCross(cube, 0, 3, 0);
    expectViewMatchesRaw(*s, "test.cube", {}, 700.0f);
    // A cube array: the cubes side by side, or the one selected.
    const FloatImage all = s->readRaw("test.cube_array");
    ASSERT_EQ(all.width, 16);
    ASSERT_EQ(all.height, 6);
    expectCross(all, 0, 2, 0);
    expectCross(all, 8, 2, 1);
    const FloatImage second = s->readRaw("test.cube_array", {1, -1});
    ASSERT_EQ(second.width, 8);
    expectCross(second, 0, 2, 1);
    expectViewMatchesRaw(*s, "test.cube_array", {}, 1300.0f);
    expectViewMatchesRaw(*s, "test.cube_array", {1, -1}, 1300.0f);
    EXPECT_EQ(selectableLayers(*s->pipeline().outputs().find("test.cube_array")), 2);
}

TEST(ResourceViews, ArraysAndVolumesByLayer) {
    auto s = session({"test.array", "test.volume"});
    // Five 4x2 layers in a grid of 3 columns (reading order), the sixth cell empty.
    const FloatImage atlas = s->readRaw("test.array");
    ASSERT_EQ(atlas.width, 12);
    ASSERT_EQ(atlas.height, 4);
    for (int cell = 0; cell < 6; ++cell)
        for (int v = 0; v < 2; ++v)
            for (int u = 0; u < 4; ++u) {
                // Within a layer rows keep the texture's orientation (row 0 at the bottom), like any 2D output.
                const float expected = cell < 5 ? layeredValue(u, 1 - v, cell) : 0.0f;
                EXPECT_EQ(atlas.at((cell % 3) * 4 + u, (cell / 3) * 2 + v, 0), expected) << "layer " << cell;
            }
    const FloatImage layer3 = s->readRaw("test.array", {3, -1});
    ASSERT_EQ(layer3.width, 4);
    ASSERT_EQ(layer3.height, 2);
    EXPECT_EQ(layer3.at(1, 1, 0), layeredValue(1, 0, 3));
    expectViewMatchesRaw(*s, "test.array", {}, 500.0f);
    expectViewMatchesRaw(*s, "test.array", {3, -1}, 500.0f);
    // Auto range leaves out the empty cell.
    BufferViewSettings a;
    a.autoRange = 1;
    s->readDisplay("test.array", a);
    auto [lo, hi] = s->bufferView().lastAutoRange();
    EXPECT_FLOAT_EQ(lo.r, 1.0f);
    EXPECT_FLOAT_EQ(hi.r, layeredValue(3, 1, 4));
    // A 3D texture: its slices, like layers.
    const FloatImage volume = s->readRaw("test.volume");
    ASSERT_EQ(volume.width, 4);
    ASSERT_EQ(volume.height, 4);
    EXPECT_EQ(volume.at(2, 1, 0), layeredValue(0, 0, 1));
    EXPECT_EQ(volume.at(2, 3, 0), 0.0f);
    EXPECT_EQ(s->readRaw("test.volume", {2, -1}).at(1, 0, 0), layeredValue(1, 1, 2));
    expectViewMatchesRaw(*s, "test.volume", {}, 300.0f);
    // Layered outputs have no texel at a frame pixel: the probe leaves them out.
    const ProbeResult r = probePixel(s->pipeline(), 1, 1);
    EXPECT_EQ(probed(r, "test.array"), nullptr);
    EXPECT_EQ(probed(r, "test.volume"), nullptr);
}

TEST(ResourceViews, IntegerTexturesReadAsTheirValues) {
    auto s = session({"test.counts"});
    const FloatImage img = s->readRaw("test.counts");
    ASSERT_EQ(img.width, kW);
    for (int y = 0; y < kH; y += 3)
        for (int x = 0; x < kW; x += 5) EXPECT_EQ(img.at(x, kH - 1 - y, 0), static_cast<float>(x + 1000 * y));
    s->readDisplay("test.counts");
    auto [lo, hi] = s->bufferView().lastAutoRange();
    EXPECT_FLOAT_EQ(lo.r, 0.0f);
    EXPECT_FLOAT_EQ(hi.r, (kW - 1) + 1000.0f * (kH - 1));
    const ProbeResult r = probePixel(s->pipeline(), 4, 3);  // v points into it
    const ProbeValue* v = probed(r, "test.counts");
    ASSERT_NE(v, nullptr);
    EXPECT_FLOAT_EQ(v->raw.x, 4.0f + 1000.0f * (kH - 1 - 3));
}

TEST(ResourceViews, WriteOutputWritesEveryKind) {
    auto s = session({"test.ms", "test.pixels", "test.table", "test.cube", "test.array", "test.cube_array", "test.volume"});
    for (const char* name : {"test.ms", "test.pixels", "test.table", "test.cube", "test.array", "test.cube_array", "test.volume"}) {
        const std::string base = (test::tempDir() / name).string();
        s->writeOutput(name, base + ".exr");
        s->writeOutput(name, base + ".png");
        const FloatImage raw = s->readRaw(name);
        const FloatImage exr = loadImageFloat(base + ".exr");
        ASSERT_EQ(exr.width, raw.width) << name;
        ASSERT_EQ(exr.height, raw.height) << name;
        EXPECT_EQ(test::maxAbsDifference(exr, raw, raw.channels), 0.0) << name;
        const FloatImage png = loadImageFloat(base + ".png");
        EXPECT_EQ(png.width, raw.width) << name;
        EXPECT_EQ(png.height, raw.height) << name;
    }
    // One layer and one sample through the same call.
    BufferViewSettings one;
    one.layer = 2;
    s->writeOutput("test.array", (test::tempDir() / "layer2.exr").string(), one);
    EXPECT_EQ(loadImageFloat((test::tempDir() / "layer2.exr").string()).width, 4);
}
