// Binding points (shaders/common/bindings.glsl): every uniform block, storage
// block, sampler and image of every program the pipeline builds sits at the
// point its declaration names, and no two of one kind share a point in a
// program. The names come from the declarations in the program's files
// (`layout(... binding = NAME ...) uniform TYPE uName;`, `... buffer Name {`,
// DW_PARAM_BLOCK_AT(Name, instance, NAME, ...) and DW_PARAM_BLOCK's
// PASS_UBO); the points from the linked program (introspection); the values
// from dw::binding, the same header compiled as C++.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "renderer/gl/Program.h"
#include "renderer/gl/ShaderLibrary.h"
#include "shaders/common/bindings.glsl"
#include "tests/support/AnimatedGltf.h"
#include "tests/support/GltfBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

using Resource = gl::Program::ResourceBinding;

// Resource name -> the binding names its declarations give it.
using Declarations = std::map<std::string, std::set<std::string>>;

std::string withoutComments(const std::string& text) {
    static const std::regex comments(R"(/\*[\s\S]*?\*/|//[^\n]*)");
    std::string s = std::regex_replace(text, comments, " ");
    // A #define's body is not a declaration (prelude.h's DW_PARAM_BLOCK_AT).
    static const std::regex defines(R"((^|\n)[ \t]*#[ \t]*define[^\n]*)");
    return std::regex_replace(s, defines, "\n");
}

void addDeclarations(const std::string& source, Declarations& out) {
    const std::string text = withoutComments(source);
    static const std::regex layout(R"(layout\s*\(([^)]*)\)([^;{]*)([;{]))");
    static const std::regex binding(R"(\bbinding\s*=\s*(\w+))");
    static const std::regex bufferName(R"(\bbuffer\s+(\w+))");
    static const std::regex lastName(R"((\w+)\s*(\[[^\]]*\])?\s*$)");
    for (std::sregex_iterator it(text.begin(), text.end(), layout), end; it != end; ++it) {
        std::smatch b, n;
        const std::string args = (*it)[1], rest = (*it)[2];
        if (!std::regex_search(args, b, binding)) continue;
        if (std::regex_search(rest, n, bufferName) || std::regex_search(rest, n, lastName))
            out[n[1]].insert(b[1]);
    }
    static const std::regex blockAt(R"(DW_PARAM_BLOCK_AT\s*\(\s*(\w+)\s*,\s*\w+\s*,\s*(\w+))");
    for (std::sregex_iterator it(text.begin(), text.end(), blockAt), end; it != end; ++it)
        out[(*it)[1]].insert((*it)[2]);
    static const std::regex block(R"(DW_PARAM_BLOCK\s*\(\s*(\w+))");
    for (std::sregex_iterator it(text.begin(), text.end(), block), end; it != end; ++it)
        out[(*it)[1]].insert("PASS_UBO");
}

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const binding::Named* named(const std::string& name) {
    for (const binding::Named& n : binding::kAll)
        if (name == n.name) return &n;
    return nullptr;
}

binding::Kind kindOf(Resource::Kind k) {
    switch (k) {
    case Resource::Kind::UniformBlock: return binding::Kind::UBO;
    case Resource::Kind::StorageBlock: return binding::Kind::SSBO;
    case Resource::Kind::Texture: return binding::Kind::TEXTURE;
    case Resource::Kind::Image: return binding::Kind::IMAGE;
    }
    return binding::Kind::UBO;
}

const char* kindName(binding::Kind k) {
    switch (k) {
    case binding::Kind::UBO: return "uniform block";
    case binding::Kind::SSBO: return "storage block";
    case binding::Kind::TEXTURE: return "texture unit";
    case binding::Kind::IMAGE: return "image unit";
    }
    return "?";
}

// What is wrong with `program`'s binding points, one line each; the names
// each resource sits at go to `used`.
std::vector<std::string> problems(const gl::Program& program, const Declarations& declared,
                                  std::set<std::string>* used = nullptr) {
    std::vector<std::string> out;
    const std::vector<Resource> resources = program.resourceBindings();
    for (const Resource& r : resources) {
        const auto d = declared.find(r.name);
        if (d == declared.end() || d->second.empty()) {
            out.push_back(r.name + ": no layout(binding = NAME) declares it");
            continue;
        }
        if (d->second.size() > 1) {
            std::string names;
            for (const auto& n : d->second) names += " " + n;
            out.push_back(r.name + ": declared at more than one name:" + names);
            continue;
        }
        const std::string& name = *d->second.begin();
        const binding::Named* n = named(name);
        if (!n) {
            out.push_back(r.name + ": at '" + name + "', not a name of shaders/common/bindings.glsl");
            continue;
        }
        if (used) used->insert(name);
        if (n->kind != kindOf(r.kind))
            out.push_back(r.name + ": at " + name + ", a " + kindName(n->kind) + ", but it takes a " +
                          kindName(kindOf(r.kind)));
        if (r.binding != static_cast<GLint>(n->value))
            out.push_back(r.name + ": at " + std::to_string(r.binding) + ", " + name + " is " +
                          std::to_string(n->value));
    }
    // No two resources of one kind at one point (an array takes `count`).
    for (size_t i = 0; i < resources.size(); ++i)
        for (size_t j = i + 1; j < resources.size(); ++j) {
            const Resource &a = resources[i], &b = resources[j];
            if (kindOf(a.kind) != kindOf(b.kind)) continue;
            if (a.binding < b.binding + b.count && b.binding < a.binding + a.count)
                out.push_back(a.name + " and " + b.name + " share " + kindName(kindOf(a.kind)) + " " +
                              std::to_string(std::max(a.binding, b.binding)));
        }
    return out;
}


// Renders, and asks for `outputs` one at a time where a frame produces them.
void renderOutputs(RenderSession& s, const std::vector<std::string>& outputs) {
    s.render();
    for (const std::string& o : outputs) {
        try {
            s.render({{o}});
        } catch (const Error&) {
            // Not produced under these knobs (another strategy's or method's).
        }
    }
}

// Every program the pipeline builds: two scenes (opaque with sky, shadows
// and lights; transparent), every value of every enum and boolean knob in
// turn, every output looked at under each method and strategy (counting and
// decoding variants compile when their output is wanted), an animated glTF
// (the scene layer's skinning dispatch), and the buffer view's variants.
void buildEveryProgram(RenderSession& s) {
    std::vector<std::string> outputs;
    for (const std::string& o : s.pipeline().outputs().names())
        if (!s.isReferenceOutput(o)) outputs.push_back(o);
    KnobRegistry& knobs = s.knobs();
    for (const char* scene : {"default", "glass"}) {
        s.loadScene(scene);
        renderOutputs(s, outputs);
        for (size_t id = 0; id < knobs.size(); ++id) {
            const KnobSpec& spec = knobs.spec(static_cast<int>(id));
            std::vector<std::string> values;
            if (spec.type == KnobType::Bool) values = {"true", "false"};
            if (spec.type == KnobType::Enum) values = spec.choices;
            const bool method = spec.name.find(".method") != std::string::npos ||
                                spec.name.find(".strategy") != std::string::npos;
            for (const std::string& v : values) {
                knobs.setFromString(spec.name, v);
                if (method)
                    renderOutputs(s, outputs);
                else
                    s.render();
            }
            knobs.reset(static_cast<int>(id));
        }
    }
    s.loadScene(test::writeJson("bindings-animated.gltf", test::animatedGltf()).string());
    s.render();
    test::buildBufferViewVariants(s.shaders());
}

}  // namespace

TEST(Bindings, EveryProgramsBindingPointsAreTheNamesItDeclares) {
    auto s = test::makeSession(32, 18);
    buildEveryProgram(*s);
    std::map<std::filesystem::path, Declarations> perFile;
    std::set<std::string> used;
    int programs = 0;
    for (const gl::ShaderLibrary::Entry* e : s->shaders().programs()) {
        ++programs;
        Declarations declared;
        for (const auto& f : e->files) {
            if (!perFile.count(f)) addDeclarations(readText(f), perFile[f]);
            for (const auto& [name, bindings] : perFile[f]) declared[name].insert(bindings.begin(), bindings.end());
        }
        const auto p = problems(e->program, declared, &used);
        EXPECT_TRUE(p.empty()) << test::describeProgram(e->desc) << test::indentedLines(p);
    }
    EXPECT_GT(programs, 50);
    // The reflection sees an array's length: bloom's levels take units 1 to 6.
    for (const gl::ShaderLibrary::Entry* e : s->shaders().programs())
        for (const Resource& r : e->program.resourceBindings()) {
            if (r.name == "uLevels") {
                EXPECT_EQ(r.count, 6) << test::describeProgram(e->desc);
            }
        }
    // Every name is some program's: the enumeration above reaches every
    // program, and the header names no point nothing uses.
    for (const binding::Named& n : binding::kAll) EXPECT_TRUE(used.count(n.name)) << "no program uses " << n.name;
}

TEST(Bindings, TheCheckCatchesALiteralAClashAndAWrongName) {
    auto s = test::makeSession(16, 16);
    const std::string frag =
        "#version 450 core\n#include \"common/bindings.glsl\"\n"
        "layout(binding = 3) uniform sampler2D uLiteral;\n"
        "layout(binding = SKY_CUBE_TEXTURE) uniform sampler2D uClash;\n"  // unit 2, as ...
        "layout(binding = TONEMAP_BLOOM_TEXTURE) uniform sampler2D uOther;\n"  // ... this
        "layout(binding = OIT_LIST_HEADS_IMAGE, r32ui) uniform uimage2D uWrongKind;\n"
        "layout(std430, binding = CAMERA_UBO) buffer WrongKind { uint w[]; };\n"
        "out vec4 color;\nvoid main() {\n"
        "  color = texelFetch(uLiteral, ivec2(0), 0) + texelFetch(uClash, ivec2(0), 0) +\n"
        "          texelFetch(uOther, ivec2(0), 0) + vec4(imageLoad(uWrongKind, ivec2(0)).r + w[0]);\n}\n";
    const std::string vert = "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    const auto program = gl::Program::link(
        {{GL_VERTEX_SHADER, gl::ShaderSource::fromString(s->shaders().root(), "t.vert", vert, {})},
         {GL_FRAGMENT_SHADER, gl::ShaderSource::fromString(s->shaders().root(), "t.frag", frag, {})}});
    Declarations declared;
    addDeclarations(frag, declared);
    const std::string p = test::indentedLines(problems(program, declared));
    EXPECT_NE(p.find("uLiteral: at '3', not a name"), std::string::npos) << p;
    EXPECT_NE(p.find("uClash and uOther share texture unit 2"), std::string::npos) << p;
    EXPECT_NE(p.find("WrongKind: at CAMERA_UBO, a uniform block, but it takes a storage block"), std::string::npos) << p;
    EXPECT_EQ(p.find("uWrongKind"), std::string::npos) << p;  // an image at an image's name
}
