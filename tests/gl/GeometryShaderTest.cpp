// The geometry stage in the shader layer (issue 22): compile errors in a
// geometry shader (and in a file it includes) name the file and line as they
// do for the other stages, a link error that names the geometry stage names
// its file and the line of the variable it quotes, and hot reload rebuilds a
// program when its geometry shader changes, keeping the last good program
// while the file is broken.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>

#include "renderer/gl/Program.h"
#include "renderer/gl/ShaderLibrary.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

fs::path geometryDir() {
    const fs::path d = test::tempDir() / "geometry_shaders";
    fs::create_directories(d / "common");
    return d;
}
void writeFile(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
void touchLater(const fs::path& p, int seconds) {
    fs::last_write_time(p, fs::file_time_type::clock::now() + std::chrono::seconds(seconds));
}

const char* kVertex = "#version 450 core\nlayout(location = 0) in vec3 aPosition;\n"
                      "void main() { gl_Position = vec4(aPosition, 1.0); }\n";
const char* kFragment = "#version 450 core\nin vec3 gNormal;\nout vec4 outColor;\n"
                        "void main() { outColor = vec4(gNormal, 1.0); }\n";
// Lines: 1 #version, 2 #include, 3 layout in, 4 layout out, 5 out, 6 main, 7 loop, 8 emit, 9 end.
const char* kGeometry =
    "#version 450 core\n"
    "#include \"common/extrude.glsl\"\n"
    "layout(triangles) in;\n"
    "layout(triangle_strip, max_vertices = 3) out;\n"
    "out vec3 gNormal;\n"
    "void main() {\n"
    "    for (int i = 0; i < 3; ++i) {\n"
    "        gNormal = vec3(0.0, 0.0, 1.0); gl_Position = extrude(gl_in[i].gl_Position); EmitVertex();\n"
    "    }\n"
    "    EndPrimitive();\n"
    "}\n";
const char* kExtrude = "// helper\nvec4 extrude(vec4 p) { return p + vec4(0.0, 0.0, 0.1, 0.0); }\n";

}  // namespace

TEST(GeometryShader, CompileErrorsNameTheGeometryFileAndLine) {
    const fs::path dir = geometryDir();
    writeFile(dir / "common/extrude.glsl", kExtrude);
    // An undeclared name on line 8 of the geometry shader itself.
    std::string broken = kGeometry;
    broken.replace(broken.find("extrude(gl_in"), 7, "extrudeX");
    writeFile(dir / "broken.geom", broken);
    try {
        gl::Program::link({{GL_VERTEX_SHADER, gl::ShaderSource::fromString(dir, "v.vert", kVertex, {})},
                           {GL_GEOMETRY_SHADER, gl::ShaderSource::load(dir, "broken.geom", {})},
                           {GL_FRAGMENT_SHADER, gl::ShaderSource::fromString(dir, "f.frag", kFragment, {})}});
        FAIL() << "should not compile";
    } catch (const gl::ShaderError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("geometry shader"), std::string::npos) << msg;
        EXPECT_NE(msg.find("broken.geom failed to compile"), std::string::npos) << msg;
        EXPECT_NE(msg.find("broken.geom:8:"), std::string::npos) << msg;
        EXPECT_NE(msg.find("extrudeX"), std::string::npos) << msg;
    }
    // An error in the file the geometry shader includes names that file and its line.
    writeFile(dir / "common/extrude.glsl", "// helper\nvec4 extrude(vec4 p) { return p + notDeclared; }\n");
    writeFile(dir / "ok.geom", kGeometry);
    try {
        gl::Program::link({{GL_GEOMETRY_SHADER, gl::ShaderSource::load(dir, "ok.geom", {})}});
        FAIL() << "should not compile";
    } catch (const gl::ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("extrude.glsl:2:"), std::string::npos) << e.what();
    }
}

TEST(GeometryShader, LinkErrorsNameTheGeometryFileAndTheLineOfTheVariable) {
    const fs::path dir = geometryDir();
    writeFile(dir / "common/extrude.glsl", kExtrude);
    // The geometry shader writes gNormal as a vec3; this fragment shader reads it as a vec4.
    writeFile(dir / "link.geom", kGeometry);
    const char* mismatched = "#version 450 core\nin vec4 gNormal;\nout vec4 outColor;\nvoid main() { outColor = gNormal; }\n";
    try {
        gl::Program::link({{GL_VERTEX_SHADER, gl::ShaderSource::fromString(dir, "v.vert", kVertex, {})},
                           {GL_GEOMETRY_SHADER, gl::ShaderSource::load(dir, "link.geom", {})},
                           {GL_FRAGMENT_SHADER, gl::ShaderSource::fromString(dir, "mismatch.frag", mismatched, {})}});
        FAIL() << "should not link";
    } catch (const gl::ShaderError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("failed to link"), std::string::npos) << msg;
        // Mesa names the output of the geometry stage (or the fragment stage's
        // input): either way the line points at a declaration of gNormal.
        const bool geometryLine = msg.find("link.geom:5:") != std::string::npos;
        const bool fragmentLine = msg.find("mismatch.frag:2:") != std::string::npos;
        EXPECT_TRUE(geometryLine || fragmentLine) << msg;
    }
    // A geometry shader without max_vertices: Mesa reports it at link time,
    // naming the stage; the message names the file.
    std::string noMax = kGeometry;
    noMax.replace(noMax.find("layout(triangle_strip, max_vertices = 3) out;"),
                  std::string("layout(triangle_strip, max_vertices = 3) out;").size(), "layout(triangle_strip) out;");
    writeFile(dir / "nomax.geom", noMax);
    try {
        gl::Program::link({{GL_VERTEX_SHADER, gl::ShaderSource::fromString(dir, "v.vert", kVertex, {})},
                           {GL_GEOMETRY_SHADER, gl::ShaderSource::load(dir, "nomax.geom", {})},
                           {GL_FRAGMENT_SHADER, gl::ShaderSource::fromString(dir, "f.frag", kFragment, {})}});
        FAIL() << "should not link";
    } catch (const gl::ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("nomax.geom"), std::string::npos) << e.what();
    }
}

TEST(GeometryShader, HotReloadCoversTheGeometryStage) {
    const fs::path dir = geometryDir() / "reload";
    fs::create_directories(dir / "common");
    writeFile(dir / "common/extrude.glsl", kExtrude);
    writeFile(dir / "v.vert", kVertex);
    writeFile(dir / "f.frag", kFragment);
    writeFile(dir / "reload.geom", kGeometry);
    gl::ShaderLibrary lib(dir);
    auto handle = lib.get({.vertex = "v.vert", .fragment = "f.frag", .geometry = "reload.geom"});
    const GLuint before = handle->id();
    ASSERT_NE(before, 0u);
    // An unchanged library reloads nothing.
    EXPECT_TRUE(lib.reloadChanged().empty());
    EXPECT_EQ(handle->id(), before);
    // Break the geometry shader: the reload reports its file and line, the handle keeps the old program.
    std::string broken = kGeometry;
    broken.replace(broken.find("EmitVertex();"), 13, "EmitVertex()");
    writeFile(dir / "reload.geom", broken);
    touchLater(dir / "reload.geom", 2);
    const auto errors = lib.reloadChanged();
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].find("reload.geom:"), std::string::npos) << errors[0];
    EXPECT_NE(errors[0].find("geometry shader"), std::string::npos) << errors[0];
    EXPECT_EQ(handle->id(), before);
    EXPECT_EQ(lib.pendingErrors().size(), 1u);
    // Fix it through the file the geometry shader includes: rebuilt, error cleared.
    writeFile(dir / "reload.geom", kGeometry);
    touchLater(dir / "reload.geom", 3);
    writeFile(dir / "common/extrude.glsl", "vec4 extrude(vec4 p) { return p + vec4(0.0, 0.0, 0.2, 0.0); }\n");
    touchLater(dir / "common/extrude.glsl", 4);
    EXPECT_TRUE(lib.reloadChanged().empty());
    EXPECT_TRUE(lib.pendingErrors().empty());
    EXPECT_NE(handle->id(), 0u);
    // A change to the included file alone triggers a rebuild of the geometry program too.
    writeFile(dir / "common/extrude.glsl", "vec4 extrude(vec4 p) { return p * ; }\n");
    touchLater(dir / "common/extrude.glsl", 6);
    const auto again = lib.reloadChanged();
    ASSERT_EQ(again.size(), 1u);
    EXPECT_NE(again[0].find("extrude.glsl:1:"), std::string::npos) << again[0];
}
