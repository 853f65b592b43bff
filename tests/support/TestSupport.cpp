#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <cstdio>
#include <fstream>

#include "headless/HeadlessGlContext.h"
#include "renderer/lighting/LightVolume.h"
#include "renderer/scene/ShapeBuilder.h"

namespace dw::test {

int addBlinnPhong(Scene& s, glm::vec3 diffuse, glm::vec3 specular, float exponent) {
    Material m;
    m.baseColor = glm::vec4(diffuse, 1.0f);
    m.specularColor = specular;
    m.specularExponent = exponent;
    return s.addMaterial(m);
}

Scene boxesScene(bool withSun) {
    Scene s = planeScene(30.0f);
    const int mat = addBlinnPhong(s, {0.7f, 0.6f, 0.5f}, glm::vec3(0.4f), 40.0f);
    Mesh box = shapes::box({1.5f, 2.0f, 1.5f});
    box.material = mat;
    const int mesh = s.addMesh(std::move(box));
    for (int i = 0; i < 5; ++i)
        s.instances.push_back({mesh, glm::translate(glm::mat4(1.0f), {-6.0f + i * 3.0f, 1.0f, -2.0f + (i % 2) * 3.0f})});
    for (int i = 0; i < 12; ++i) {
        const float a = static_cast<float>(i) * 0.52f;
        addPointLight(s, {std::cos(a) * 5.0f, 0.4f + 0.3f * (i % 3), std::sin(a) * 4.0f},
                      glm::vec3(0.5f + 0.1f * (i % 4), 0.8f, 1.2f - 0.1f * (i % 5)), {1.0f, 0.5f, 2.0f});
    }
    for (int i = 0; i < 4; ++i)
        addSpotLight(s, {-4.5f + i * 3.0f, 4.0f, 3.0f}, {0.1f * i, -1.0f, -0.5f}, 20.0f + 8.0f * i, 4.0f,
                     glm::vec3(4.0f, 3.0f, 2.0f), {1.0f, 0.2f, 0.3f});
    if (withSun) {
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));
        sun.intensity = glm::vec3(0.3f);
        s.lights.push_back(sun);
    }
    s.ambient = glm::vec3(0.02f);
    return s;
}

// 200 small lights (radius 1 to 2) on a jittered grid over the left part of a
// floor with boxes: their spheres cross tile edges at 96x54 and, at heights
// from 0.1 to 1.6 over surfaces 3 to 20 units away, several depth slices.
// The right part of the floor has no light near it. Every 9th light is a spot.
Scene straddleScene(int shadowed) {
    Scene s = planeScene(40.0f);
    s.lights.clear();
    s.camera.position = {0.0f, 7.0f, 11.0f};
    s.camera.target = {0.0f, 0.0f, -2.0f};
    Material m;
    m.baseColor = glm::vec4(0.8f, 0.75f, 0.7f, 1.0f);
    m.specularColor = glm::vec3(0.3f);
    m.specularExponent = 24.0f;
    const int mat = s.addMaterial(m);
    Mesh box = shapes::box({1.0f, 1.5f, 1.0f});
    box.material = mat;
    const int mesh = s.addMesh(std::move(box));
    for (int i = 0; i < 6; ++i)
        s.instances.push_back({mesh, glm::translate(glm::mat4(1.0f), {-9.0f + i * 2.3f, 0.75f, -6.0f + (i % 3) * 3.1f})});
    for (int i = 0; i < 200; ++i) {
        const int gx = i % 20, gz = i / 20;
        const float jx = std::fmod(i * 0.618f, 1.0f) - 0.5f, jz = std::fmod(i * 0.414f, 1.0f) - 0.5f;
        const glm::vec3 pos(-11.0f + gx * 0.65f + jx * 0.5f, 0.1f + 1.5f * std::fmod(i * 0.273f, 1.0f),
                            -12.0f + gz * 1.7f + jz * 0.8f);
        const float radius = 1.0f + std::fmod(i * 0.37f, 1.0f);
        const glm::vec3 colour(0.4f + 0.6f * std::fmod(i * 0.31f, 1.0f), 0.4f + 0.6f * std::fmod(i * 0.57f, 1.0f),
                               0.4f + 0.6f * std::fmod(i * 0.79f, 1.0f));
        const float peak = std::max(colour.r, std::max(colour.g, colour.b));
        // Reaches 1/255 (lighting.threshold's default) at `radius`.
        const Attenuation att{1.0f, 0.0f, (255.0f * peak - 1.0f) / (radius * radius)};
        Light& l = i % 9 == 4 ? addSpotLight(s, pos + glm::vec3(0, 0.5f, 0), {0.2f, -1.0f, 0.1f}, 35.0f, 2.0f, colour, att)
                              : addPointLight(s, pos, colour, att);
        l.castShadows = i % 67 == 10 && shadowed-- > 0;
    }
    s.ambient = glm::vec3(0.01f);
    return s;
}

CommandResult runCommand(const std::string& command) {
    const std::filesystem::path errFile = tempDir() / "stderr.txt";
    const std::string cmd = "(" + command + ") 2>" + errFile.string();
    CommandResult r;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf{};
    while (size_t n = fread(buf.data(), 1, buf.size(), p)) r.out.append(buf.data(), n);
    const int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream e(errFile);
    r.err.assign(std::istreambuf_iterator<char>(e), std::istreambuf_iterator<char>());
    return r;
}

CommandResult runWorkbench(const std::string& args) { return runCommand(std::string(DW_WORKBENCH_BINARY) + " " + args); }

namespace {
std::unique_ptr<HeadlessGlContext>& context() {
    static std::unique_ptr<HeadlessGlContext> c;
    return c;
}
}  // namespace

void initGl() {
    if (!context()) context() = HeadlessGlContext::create();
}

std::unique_ptr<RenderSession> makeSession(int width, int height) {
    initGl();
    auto s = std::make_unique<RenderSession>();
    s->resize(width, height);
    return s;
}

Scene planeScene(float size) {
    Scene s;
    s.name = "test plane";
    s.source = "test:plane";
    s.ambient = glm::vec3(0.0f);
    s.background = glm::vec3(0.0f);
    Material m;
    m.name = "matte";
    m.baseColor = glm::vec4(1.0f);
    m.specularColor = glm::vec3(0.0f);
    m.specularExponent = 1.0f;
    const int mat = s.addMaterial(m);
    Mesh plane = shapes::plane(size, size);
    plane.material = mat;
    s.instances.push_back({s.addMesh(std::move(plane)), glm::mat4(1.0f)});
    s.camera.position = {0.0f, 6.0f, 10.0f};
    s.camera.target = {0.0f, 0.0f, 0.0f};
    s.camera.fovYDegrees = 60.0f;
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 100.0f;
    return s;
}

Light& addPointLight(Scene& s, glm::vec3 pos, glm::vec3 intensity, Attenuation att) {
    Light l;
    l.name = "point" + std::to_string(s.lights.size());
    l.type = LightType::Point;
    l.position = pos;
    l.intensity = intensity;
    l.attenuation = att;
    s.lights.push_back(l);
    return s.lights.back();
}

Light& addSpotLight(Scene& s, glm::vec3 pos, glm::vec3 dir, float cutoff, float exponent, glm::vec3 intensity,
                    Attenuation att) {
    Light l;
    l.name = "spot" + std::to_string(s.lights.size());
    l.type = LightType::Spot;
    l.position = pos;
    l.direction = glm::normalize(dir);
    l.cutoffDegrees = cutoff;
    l.exponent = exponent;
    l.intensity = intensity;
    l.attenuation = att;
    s.lights.push_back(l);
    return s.lights.back();
}

std::filesystem::path dataDir() { return DW_TEST_DATA_DIR; }
std::filesystem::path goldenDir() { return DW_TEST_GOLDEN_DIR; }
std::filesystem::path scenesDir() { return DW_TEST_SCENES_DIR; }

std::filesystem::path tempDir() {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("dw-tests-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

std::map<std::string, std::string> readKnobDump(const std::filesystem::path& path) {
    std::map<std::string, std::string> values;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("# scene ", 0) == 0) values["#scene"] = line.substr(8);
        const auto eq = line.find('=');
        if (line.empty() || line[0] == '#' || eq == std::string::npos) continue;
        values[line.substr(0, eq)] = line.substr(eq + 1);
    }
    return values;
}

ChannelStats stats(const FloatImage& img, int channel) {
    ChannelStats s;
    s.min = 1e300;
    s.max = -1e300;
    double sum = 0;
    long long n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const double v = img.at(x, y, channel);
            if (!std::isfinite(v)) {
                ++s.nonFinite;
                continue;
            }
            sum += v;
            s.min = std::min(s.min, v);
            s.max = std::max(s.max, v);
            ++n;
        }
    s.mean = n ? sum / static_cast<double>(n) : 0.0;
    return s;
}

double maxAbsDifference(const FloatImage& a, const FloatImage& b, int channels, int* worstX, int* worstY) {
    double worst = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < channels; ++c) {
                const double d = std::fabs(static_cast<double>(a.at(x, y, c)) - b.at(x, y, c));
                if (d > worst || std::isnan(d)) {
                    worst = std::isnan(d) ? 1e30 : d;
                    if (worstX) *worstX = x;
                    if (worstY) *worstY = y;
                }
            }
    return worst;
}

double fractionOff(const FloatImage& a, const FloatImage& b, float relative, float absolute) {
    long long off = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (!(std::fabs(a.at(x, y, c) - b.at(x, y, c)) <= relative * std::fabs(a.at(x, y, c)) + absolute)) {
                    ++off;
                    break;
                }
    return static_cast<double>(off) / (static_cast<double>(a.width) * a.height);
}

reference::SurfacePoint GBufferImages::at(int x, int y) const {
    reference::SurfacePoint sp;
    sp.position = {position.at(x, y, 0), position.at(x, y, 1), position.at(x, y, 2)};
    sp.normal = glm::normalize(glm::dvec3(normal.at(x, y, 0), normal.at(x, y, 1), normal.at(x, y, 2)));
    sp.diffuse = {albedo.at(x, y, 0), albedo.at(x, y, 1), albedo.at(x, y, 2)};
    sp.specular = {specular.at(x, y, 0), specular.at(x, y, 1), specular.at(x, y, 2)};
    sp.exponent = std::exp2(specular.at(x, y, 3) * 11.0);
    return sp;
}

GBufferImages readGBuffer(const RenderSession& session) {
    return {session.readRaw("gbuffer.view_position"), session.readRaw("gbuffer.view_normal"),
            session.readRaw("gbuffer.albedo"), session.readRaw("gbuffer.specular")};
}

glm::dvec3 referenceRadiance(const std::vector<Light>& lights, const glm::dmat4& worldToView,
                             const reference::SurfacePoint& s, double threshold, reference::AttenuationModel model,
                             double windowExponent) {
    glm::dvec3 sum(0.0);
    for (const Light& l : lights) {
        const LightVolume v = computeLightVolume(l, threshold);
        if (v.shape == VolumeShape::Culled) continue;
        const glm::dvec3 lp = glm::dvec3(worldToView * glm::dvec4(glm::dvec3(l.position), 1.0));
        const glm::dvec3 ld = glm::dvec3(worldToView * glm::dvec4(glm::dvec3(l.direction), 0.0));
        sum += reference::shadeLight(l, lp, ld, std::isfinite(v.radius) ? v.radius : 0.0, s, model, windowExponent);
    }
    return sum;
}

std::string describeProgram(const gl::ProgramDesc& d) {
    std::string s = d.vertex + " " + d.geometry + " " + d.fragment + " " + d.compute;
    for (const auto& def : d.defines) s += " -D" + def;
    return s;
}

std::string indentedLines(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += "\n  " + l;
    return s;
}

void buildBufferViewVariants(gl::ShaderLibrary& shaders) {
    for (const char* source : {"", "SOURCE_MS", "SOURCE_ARRAY", "SOURCE_3D", "SOURCE_BUFFER"})
        for (const char* type : {"", "SOURCE_UINT", "SOURCE_INT"}) {
            std::vector<std::string> defines;
            for (const char* d : {source, type})
                if (*d) defines.push_back(d);
            shaders.get({.vertex = "fullscreen.vert", .fragment = "bufferview/view.frag", .defines = defines});
            defines.insert(defines.begin(), "FIRST_PASS");
            shaders.get({.compute = "bufferview/minmax.comp", .defines = defines});
        }
}

}  // namespace dw::test
