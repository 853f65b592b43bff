// Parameter blocks (shaders/params/*.h): what C++ writes is where GLSL reads.
// The C++ side checks std140's rules at compile time; these tests ask the GL
// compiler itself, through program introspection, where each member of each
// block is in every program the pipeline built, and compare that with the
// C++ struct field by field: the passes' blocks, the buffer view's and the
// camera's. And the enum defines the passes give their shaders carry the
// knob's choice indices, and the buffer view's constants are its C++ enums'.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "renderer/gl/Buffer.h"
#include "renderer/gl/Program.h"
#include "renderer/inspect/BufferView.h"
#include "renderer/lighting/LightTable.h"
#include "renderer/scene/GpuScene.h"
#include "shaders/params/bloom.h"
#include "shaders/params/bufferview.h"
#include "shaders/params/camera.h"
#include "shaders/params/oit.h"
#include "shaders/params/dof.h"
#include "shaders/params/flames.h"
#include "shaders/params/fxaa.h"
#include "shaders/params/light.h"
#include "shaders/params/lighting.h"
#include "shaders/params/luminance.h"
#include "shaders/params/sky.h"
#include "shaders/params/ssao.h"
#include "shaders/params/ssao_blur.h"
#include "shaders/params/ssaa.h"
#include "shaders/params/taa.h"
#include "shaders/params/gtao.h"
#include "shaders/params/aov.h"
#include "shaders/params/tonemap.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

struct BlockInfo {
    std::string name;
    std::size_t size = 0;
    unsigned binding = 0;
    std::vector<gpu::ParamField> fields;
};

template <typename Block>
BlockInfo describe() {
    return {Block::kBlockName, sizeof(Block), Block::kBinding, Block::fields()};
}

// The blocks' bindings are named in shaders/common/bindings.glsl, dw::binding
// in C++ (tests/gl/BindingsTest.cpp checks every other binding point).
static_assert(gpu::CameraBlock::kBinding == binding::CAMERA_UBO &&
              gpu::SsaoParams::kBinding == binding::PASS_UBO &&
              gpu::BufferViewParams::kBinding == binding::PASS_UBO);

// Every parameter block in shaders/params. A new header adds a line here.
std::vector<BlockInfo> allBlocks() {
    return {describe<gpu::SsaoParams>(),      describe<gpu::SsaoBlurParams>(),
            describe<gpu::SkyParams>(),       describe<gpu::LightingParams>(),
            describe<gpu::LuminanceParams>(), describe<gpu::BloomParams>(),
            describe<gpu::TonemapParams>(),   describe<gpu::DofParams>(),
            describe<gpu::FxaaParams>(),      describe<gpu::BufferViewParams>(),
            describe<gpu::CameraBlock>(),     describe<gpu::OitParams>(),
            describe<gpu::GtaoParams>(),      describe<gpu::AovParams>(),
            describe<gpu::SsaaParams>(),      describe<gpu::TaaParams>(),
            describe<gpu::FlamesParams>()};
}

GLenum glType(const std::string& glsl) {
    static const std::map<std::string, GLenum> types = {{"int", GL_INT},
                                                        {"uint", GL_UNSIGNED_INT},
                                                        {"float", GL_FLOAT},
                                                        {"vec2", GL_FLOAT_VEC2},
                                                        {"vec3", GL_FLOAT_VEC3},
                                                        {"vec4", GL_FLOAT_VEC4},
                                                        {"ivec2", GL_INT_VEC2},
                                                        {"ivec3", GL_INT_VEC3},
                                                        {"ivec4", GL_INT_VEC4},
                                                        {"uvec2", GL_UNSIGNED_INT_VEC2},
                                                        {"uvec4", GL_UNSIGNED_INT_VEC4},
                                                        {"mat4", GL_FLOAT_MAT4}};
    const auto it = types.find(glsl);
    return it == types.end() ? 0 : it->second;
}

// Where the program's block differs from the C++ struct, one line each.
std::vector<std::string> mismatches(const BlockInfo& b, const gl::UniformBlockLayout& layout) {
    std::vector<std::string> out;
    auto differ = [&](const std::string& what, long long gl, long long cpp) {
        if (gl != cpp)
            out.push_back(what + ": GLSL " + std::to_string(gl) + ", C++ " + std::to_string(cpp));
    };
    differ("binding", layout.binding, b.binding);
    differ("size", layout.dataSize, static_cast<long long>(b.size));
    // std140 blocks have every member active, used or not.
    differ("member count", static_cast<long long>(layout.members.size()),
           static_cast<long long>(b.fields.size()));
    for (const gpu::ParamField& f : b.fields) {
        const std::string name = std::string(f.name) + (f.arraySize > 0 ? "[0]" : "");
        const auto m = std::find_if(layout.members.begin(), layout.members.end(),
                                    [&](const auto& member) { return member.name == name; });
        if (m == layout.members.end()) {
            out.push_back(name + ": not a member in GLSL");
            continue;
        }
        differ(name + " offset", m->offset, static_cast<long long>(f.offset));
        differ(name + " type (GLenum)", m->type, glType(f.type));
        if (f.arraySize > 0) {
            differ(name + " array size", m->arraySize, f.arraySize);
            differ(name + " array stride", m->arrayStride, 16);
        }
    }
    return out;
}


}  // namespace

TEST(ParamBlocks, EveryPassProgramLaysOutItsBlockAsTheCppStruct) {
    auto s = test::makeSession(64, 36);
    test::buildBufferViewVariants(s->shaders());
    const std::vector<BlockInfo> blocks = allBlocks();
    std::map<std::string, int> programsWithBlock;
    for (const gl::ShaderLibrary::Entry* e : s->shaders().programs()) {
        const std::string where = test::describeProgram(e->desc);
        for (const std::string& name : e->program.uniformBlockNames()) {
            const auto layout = e->program.uniformBlock(name);
            ASSERT_TRUE(layout);
            const auto b = std::find_if(blocks.begin(), blocks.end(),
                                        [&](const BlockInfo& i) { return i.name == name; });
            if (b == blocks.end()) {
                // Every uniform block is declared in shaders/params.
                ADD_FAILURE() << where << " declares " << name << " by hand";
                continue;
            }
            ++programsWithBlock[name];
            const auto diff = mismatches(*b, *layout);
            EXPECT_TRUE(diff.empty()) << name << " in " << where << test::indentedLines(diff);
        }
    }
    for (const BlockInfo& b : blocks)
        EXPECT_GT(programsWithBlock[b.name], 0) << "no program declares " << b.name;
}

// The light table's row (a std430 array, shaders/params/light.h) where every
// program that reads it has it: each field that program uses at the C++
// offset, rows 224 bytes apart.
TEST(ParamBlocks, EveryProgramReadingTheLightTableLaysOutItsRowAsTheCppStruct) {
    auto s = test::makeSession(64, 36);
    // Every lighting strategy's programs.
    s->loadScene("default");
    for (const char* strategy : {"stencil_volumes", "volumes", "fullscreen", "tiled", "clustered", "forward", "forward_multipass"}) {
        s->knobs().setFromString("lighting.strategy", strategy);
        s->render();
    }
    std::map<std::string, int> seen;
    int programs = 0;
    for (const gl::ShaderLibrary::Entry* e : s->shaders().programs()) {
        bool reads = false;
        for (const gpu::ParamField& f : gpu::Light::fields()) {
            const auto v = e->program.bufferVariable(std::string("lights[0].") + f.name);
            if (!v) continue;
            reads = true;
            ++seen[f.name];
            EXPECT_EQ(v->offset, static_cast<GLint>(f.offset)) << f.name << " in " << test::describeProgram(e->desc);
            EXPECT_EQ(v->topLevelStride, static_cast<GLint>(sizeof(gpu::Light))) << test::describeProgram(e->desc);
        }
        programs += reads;
    }
    EXPECT_GE(programs, 5) << "the lighting programs read the light table";
    for (const gpu::ParamField& f : gpu::Light::fields()) EXPECT_GT(seen[f.name], 0) << "no program reads " << f.name;
    // The kinds, as GLSL compiles them, are the C++ ones the table writes.
    static_assert(gpu::LIGHT_DIRECTIONAL == 0 && gpu::LIGHT_POINT == 1 && gpu::LIGHT_SPOT == 2 &&
                  gpu::LIGHT_SPOT_CONE == kLightKindSpotCone);
}

TEST(ParamBlocks, TheComparisonCatchesABlockMirroredByPosition) {
    // The blur block as it was before shaders/params: the same bytes read by
    // position. Every named field of the C++ struct must fail to match.
    auto s = test::makeSession(16, 16);
    const std::string frag =
        "#version 450 core\n"
        "layout(std140, binding = 3) uniform SsaoBlurParams { ivec4 modes; vec4 values; } blur;\n"
        "out vec4 color;\nvoid main() { color = vec4(blur.modes) + blur.values; }\n";
    const std::string vert = "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    const auto program = gl::Program::link(
        {{GL_VERTEX_SHADER,
          gl::ShaderSource::fromString(s->shaders().root(), "old.vert", vert, {})},
         {GL_FRAGMENT_SHADER,
          gl::ShaderSource::fromString(s->shaders().root(), "old.frag", frag, {})}});
    const auto layout = program.uniformBlock("SsaoBlurParams");
    ASSERT_TRUE(layout);
    EXPECT_EQ(
        layout->dataSize,
        static_cast<GLint>(sizeof(gpu::SsaoBlurParams)));  // same size: a size check alone passes
    const auto diff = mismatches(describe<gpu::SsaoBlurParams>(), *layout);
    EXPECT_GE(diff.size(), gpu::SsaoBlurParams::fields().size()) << test::indentedLines(diff);
}

TEST(ParamBlocks, EnumDefinesCarryTheKnobsChoiceIndices) {
    auto s = test::makeSession(16, 16);
    const KnobRegistry& knobs = s->knobs();
    std::vector<std::string> defines, names;
    std::vector<int> expected;
    for (size_t id = 0; id < knobs.size(); ++id) {
        const KnobSpec& spec = knobs.spec(static_cast<int>(id));
        if (spec.type != KnobType::Enum) continue;
        for (const std::string& d : knobs.choiceDefines(EnumKnob{static_cast<int>(id)}))
            defines.push_back(d);
        for (size_t i = 0; i < spec.choices.size(); ++i) {
            names.push_back(KnobRegistry::choiceDefineName(spec.name, spec.choices[i]));
            expected.push_back(static_cast<int>(i));
        }
    }
    ASSERT_GT(names.size(), 10u);
    std::string src =
        "#version 450 core\nlayout(local_size_x = 1) in;\n"
        "layout(std430, binding = 0) writeonly buffer Out { int v[]; };\nvoid main() {\n";
    for (size_t i = 0; i < names.size(); ++i)
        src += "    v[" + std::to_string(i) + "] = " + names[i] + ";\n";
    src += "}\n";
    const auto program = gl::Program::link(
        {{GL_COMPUTE_SHADER,
          gl::ShaderSource::fromString(s->shaders().root(), "defines.comp", src, defines)}});
    gl::Buffer out = gl::Buffer::create(names.size() * sizeof(int), nullptr, false);
    out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    program.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<int> got(names.size());
    out.read(0, got.size() * sizeof(int), got.data());
    for (size_t i = 0; i < names.size(); ++i) EXPECT_EQ(got[i], expected[i]) << names[i];
}

TEST(ParamBlocks, BoundsSharedWithGlslAreTheKnobsBounds) {
    auto s = test::makeSession(16, 16);
    const KnobRegistry& knobs = s->knobs();
    EXPECT_EQ(knobs.spec(*knobs.find("ssao.samples")).maxValue, gpu::SSAO_MAX_SAMPLES);
    EXPECT_EQ(std::size(gpu::SsaoParams{}.kernel), static_cast<std::size_t>(gpu::SSAO_MAX_SAMPLES));
    // The GLSL array has the same length (the block test compares its layout too).
    for (const gl::ShaderLibrary::Entry* e : s->shaders().programs())
        if (auto layout = e->program.uniformBlock(gpu::SsaoParams::kBlockName)) {
            const auto kernel = std::find_if(layout->members.begin(), layout->members.end(),
                                             [](const auto& m) { return m.name == "kernel[0]"; });
            ASSERT_NE(kernel, layout->members.end());
            EXPECT_EQ(kernel->arraySize, gpu::SSAO_MAX_SAMPLES);
        }
}

TEST(ParamBlocks, BufferViewConstantsAreItsCppEnums) {
    // The VIEW_* values as GLSL compiles them from shaders/params/bufferview.h,
    // against the C++ enums BufferView.cpp static_asserts against the same header.
    using M = BufferViewSettings::Mapping;
    using C = BufferViewSettings::Channel;
    using A = ImageLayout::Arrangement;
    const std::vector<std::pair<std::string, int>> expected = {
        {"VIEW_MAP_DIRECT", static_cast<int>(M::Direct)},
        {"VIEW_MAP_LINEAR_DEPTH", static_cast<int>(M::LinearDepth)},
        {"VIEW_MAP_NORMAL", static_cast<int>(M::Normal)},
        {"VIEW_MAP_HEATMAP", static_cast<int>(M::Heatmap)},
        {"VIEW_MAP_TONEMAP", static_cast<int>(M::Tonemap)},
        {"VIEW_MAP_NON_FINITE", static_cast<int>(M::NonFinite)},
        {"VIEW_CHANNEL_RGB", static_cast<int>(C::RGB)},
        {"VIEW_CHANNEL_R", static_cast<int>(C::R)},
        {"VIEW_CHANNEL_G", static_cast<int>(C::G)},
        {"VIEW_CHANNEL_B", static_cast<int>(C::B)},
        {"VIEW_CHANNEL_A", static_cast<int>(C::A)},
        {"VIEW_ARRANGE_PLAIN", static_cast<int>(A::Plain)},
        {"VIEW_ARRANGE_LAYERS", static_cast<int>(A::Layers)},
        {"VIEW_ARRANGE_CROSSES", static_cast<int>(A::Crosses)},
        {"VIEW_ARRANGE_TABLE", static_cast<int>(A::Table)},
    };
    auto s = test::makeSession(16, 16);
    std::string src =
        "#version 450 core\n#include \"params/bufferview.h\"\nlayout(local_size_x = 1) in;\n"
        "layout(std430, binding = 0) writeonly buffer Out { int v[]; };\nvoid main() {\n";
    for (size_t i = 0; i < expected.size(); ++i)
        src += "    v[" + std::to_string(i) + "] = " + expected[i].first + ";\n";
    src += "}\n";
    const auto program = gl::Program::link(
        {{GL_COMPUTE_SHADER,
          gl::ShaderSource::fromString(s->shaders().root(), "constants.comp", src, {})}});
    gl::Buffer out = gl::Buffer::create(expected.size() * sizeof(int), nullptr, false);
    out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    program.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<int> got(expected.size());
    out.read(0, got.size() * sizeof(int), got.data());
    for (size_t i = 0; i < expected.size(); ++i)
        EXPECT_EQ(got[i], expected[i].second) << expected[i].first;
}
