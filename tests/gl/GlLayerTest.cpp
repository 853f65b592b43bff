#include <gtest/gtest.h>

#include <fstream>

#include "renderer/Error.h"
#include "renderer/gl/Framebuffer.h"
#include "renderer/gl/Program.h"
#include "renderer/gl/ShaderLibrary.h"
#include "renderer/gl/Texture.h"
#include "renderer/gl/TimestampQuery.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {
fs::path shaderDir() {
    const fs::path d = test::tempDir() / "shaders";
    fs::create_directories(d / "common");
    return d;
}
void writeFile(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
const char* kGoodCompute =
    "#version 450 core\n#include \"common/util.glsl\"\nlayout(local_size_x = 1) in;\n"
    "layout(std430, binding = 0) buffer B { float v[]; };\nvoid main() { v[0] = twice(v[0]); }\n";
}  // namespace

TEST(ShaderSource, ErrorsInIncludedFilesNameTheFileAndLine) {
    const fs::path dir = shaderDir();
    writeFile(dir / "common/util.glsl", "// helper\nfloat twice(float x) {\n    return x * 2.0 + undefinedThing;\n}\n");
    writeFile(dir / "broken.comp", kGoodCompute);
    try {
        gl::Program::link({{GL_COMPUTE_SHADER, gl::ShaderSource::load(dir, "broken.comp", {})}});
        FAIL() << "should not compile";
    } catch (const gl::ShaderError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("util.glsl:3:"), std::string::npos) << msg;
        EXPECT_NE(msg.find("undefinedThing"), std::string::npos) << msg;
        EXPECT_NE(msg.find("broken.comp failed to compile"), std::string::npos) << msg;
    }
}

TEST(ShaderSource, LineNumbersAfterAnIncludeStayRight) {
    const fs::path dir = shaderDir();
    writeFile(dir / "common/ok.glsl", "float one() { return 1.0; }\n\n\n\n");
    writeFile(dir / "after.comp",
              "#version 450 core\n#include \"common/ok.glsl\"\nlayout(local_size_x = 1) in;\nvoid main() {\n    nope();\n}\n");
    try {
        gl::Program::link({{GL_COMPUTE_SHADER, gl::ShaderSource::load(dir, "after.comp", {})}});
        FAIL();
    } catch (const gl::ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("after.comp:5:"), std::string::npos) << e.what();
    }
}

TEST(ShaderSource, MissingIncludesAreReportedAndCyclesIncludeOnce) {
    const fs::path dir = shaderDir();
    writeFile(dir / "missing.comp", "#version 450 core\n\n#include \"common/none.glsl\"\nvoid main() {}\n");
    try {
        gl::ShaderSource::load(dir, "missing.comp", {});
        FAIL();
    } catch (const gl::ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("missing.comp:3: #include \"common/none.glsl\" not found"), std::string::npos)
            << e.what();
    }
    writeFile(dir / "common/a.glsl", "#include \"b.glsl\"\nfloat fa() { return 1.0; }\n");
    writeFile(dir / "common/b.glsl", "#include \"a.glsl\"\nfloat fb() { return 2.0; }\n");
    writeFile(dir / "cycle.comp", "#version 450 core\n#include \"common/a.glsl\"\n#include \"common/b.glsl\"\n"
                                  "layout(local_size_x = 1) in;\nvoid main() {}\n");
    const gl::ShaderSource src = gl::ShaderSource::load(dir, "cycle.comp", {});
    EXPECT_EQ(src.files.size(), 3u);
    EXPECT_NO_THROW(gl::Program::link({{GL_COMPUTE_SHADER, src}}));
}

TEST(ShaderLibrary, FailedReloadKeepsTheLastGoodProgram) {
    const fs::path dir = shaderDir();
    writeFile(dir / "common/util.glsl", "float twice(float x) { return x * 2.0; }\n");
    writeFile(dir / "reload.comp", kGoodCompute);
    gl::ShaderLibrary lib(dir);
    auto handle = lib.get({.compute = "reload.comp"});
    const GLuint before = handle->id();
    ASSERT_NE(before, 0u);
    // Break the included file: the reload fails, the handle keeps the old program.
    writeFile(dir / "common/util.glsl", "float twice(float x) { return x * ; }\n");
    fs::last_write_time(dir / "common/util.glsl", fs::file_time_type::clock::now() + std::chrono::seconds(2));
    const auto errors = lib.reloadChanged();
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].find("util.glsl:1:"), std::string::npos) << errors[0];
    EXPECT_EQ(handle->id(), before);
    EXPECT_EQ(lib.pendingErrors().size(), 1u);
    // Fix it: the program is rebuilt and the error clears.
    writeFile(dir / "common/util.glsl", "float twice(float x) { return x + x; }\n");
    fs::last_write_time(dir / "common/util.glsl", fs::file_time_type::clock::now() + std::chrono::seconds(4));
    EXPECT_TRUE(lib.reloadChanged().empty());
    EXPECT_TRUE(lib.pendingErrors().empty());
    EXPECT_NE(handle->id(), 0u);
}

TEST(GlWrappers, TextureRoundTripAndMoveSemantics) {
    gl::Texture t = gl::Texture::create2D(GL_RGBA32F, 3, 2);
    std::vector<float> data(3 * 2 * 4);
    for (size_t i = 0; i < data.size(); ++i) data[i] = static_cast<float>(i) * 0.5f - 3.0f;
    t.upload(0, 3, 2, GL_RGBA, GL_FLOAT, data.data());
    EXPECT_EQ(t.readFloats(0, GL_RGBA, 4), data);
    const GLuint id = t.id();
    gl::Texture moved = std::move(t);
    EXPECT_EQ(moved.id(), id);
    EXPECT_EQ(t.id(), 0u);  // NOLINT(bugprone-use-after-move): moved-from is empty by contract
    EXPECT_EQ(gl::Texture::fullMipCount(1280, 720), 11);
}

TEST(GlWrappers, IncompleteFramebufferThrowsWithItsStatus) {
    gl::Framebuffer fb = gl::Framebuffer::create("empty");
    try {
        fb.checkComplete("test target");
        FAIL();
    } catch (const GlUnsupportedError& e) {
        EXPECT_NE(std::string(e.what()).find("test target"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("INCOMPLETE_MISSING_ATTACHMENT"), std::string::npos);
    }
}

TEST(GlWrappers, TimestampPairsAreOrdered) {
    auto a = gl::TimestampQuery::create();
    auto b = gl::TimestampQuery::create();
    a.record();
    glFinish();
    b.record();
    EXPECT_LE(a.result(), b.result());
    EXPECT_TRUE(b.available());
}
