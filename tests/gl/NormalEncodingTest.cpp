// The G-buffer normal encoding (seed 000 section 3.1): the GLSL transform is
// exact, and RG16_SNORM storage keeps view-space normals to a small angle.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "renderer/gl/Buffer.h"
#include "renderer/gl/Program.h"
#include "renderer/gl/Texture.h"
#include "renderer/reference/ShadingReference.h"
#include "renderer/scene/ShapeBuilder.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

// Encodes normals from an SSBO into an image of `format`, then decodes them back,
// with the GLSL functions `encodeFn` / `decodeFn` of common/gbuffer.glsl.
std::vector<glm::vec4> roundTrip(const std::vector<glm::vec4>& normals, GLenum format, const char* qualifier,
                                 const std::string& encodeFn = "encodeNormalKL",
                                 const std::string& decodeFn = "decodeNormalKL") {
    const std::string root = gl::ShaderLibrary::locateRoot().string();
    const std::string encode = std::string("#version 450 core\n#include \"common/gbuffer.glsl\"\n"
                                           "layout(local_size_x = 64) in;\n"
                                           "layout(std430, binding = 0) readonly buffer In { vec4 n[]; };\n"
                                           "layout(") + qualifier + ", binding = 0) uniform writeonly image2D img;\n"
                                           "void main() { uint i = gl_GlobalInvocationID.x; if (i >= n.length()) return;\n"
                                           "  imageStore(img, ivec2(i % 1024u, i / 1024u), vec4(" + encodeFn + "(n[i].xyz), 0, 0)); }\n";
    const std::string decode = std::string("#version 450 core\n#include \"common/gbuffer.glsl\"\n"
                                           "layout(local_size_x = 64) in;\n"
                                           "layout(std430, binding = 1) writeonly buffer Out { vec4 d[]; };\n"
                                           "layout(") + qualifier + ", binding = 0) uniform readonly image2D img;\n"
                                           "void main() { uint i = gl_GlobalInvocationID.x; if (i >= d.length()) return;\n"
                                           "  d[i] = vec4(" + decodeFn + "(imageLoad(img, ivec2(i % 1024u, i / 1024u)).xy), 0); }\n";
    auto enc = gl::Program::link({{GL_COMPUTE_SHADER, gl::ShaderSource::fromString(root, "encode.comp", encode, {})}});
    auto dec = gl::Program::link({{GL_COMPUTE_SHADER, gl::ShaderSource::fromString(root, "decode.comp", decode, {})}});
    const int rows = static_cast<int>((normals.size() + 1023) / 1024);
    gl::Texture img = gl::Texture::create2D(format, 1024, rows);
    gl::Buffer in = gl::Buffer::fromVector(normals);
    gl::Buffer out = gl::Buffer::create(normals.size() * sizeof(glm::vec4), nullptr, false);
    in.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    out.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
    glBindImageTexture(0, img.id(), 0, GL_FALSE, 0, GL_READ_WRITE, format);
    const auto groups = static_cast<GLuint>((normals.size() + 63) / 64);
    enc.use();
    glDispatchCompute(groups, 1, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    dec.use();
    glDispatchCompute(groups, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> result(normals.size());
    out.read(0, result.size() * sizeof(glm::vec4), result.data());
    return result;
}

double angleDegrees(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

std::vector<glm::vec4> randomNormals(size_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> g;
    std::vector<glm::vec4> v;
    while (v.size() < n) {
        const glm::vec3 d(g(rng), g(rng), g(rng));
        if (glm::length(d) < 1e-3f) continue;
        v.emplace_back(glm::normalize(d), 0.0f);
    }
    // Edge cases: the axes, and almost straight away from the viewer.
    v.push_back({0, 0, 1, 0});
    v.push_back({1, 0, 0, 0});
    v.push_back({0, -1, 0, 0});
    v.push_back(glm::vec4(glm::normalize(glm::vec3(0.01f, 0.0f, -1.0f)), 0.0f));
    return v;
}

}  // namespace

TEST(NormalEncoding, GlslTransformIsExactBeforeQuantisation) {
    const auto normals = randomNormals(20000, 3);
    const auto decoded = roundTrip(normals, GL_RG32F, "rg32f");
    double worst = 0.0;
    for (size_t i = 0; i < normals.size(); ++i) {
        if (normals[i].z < -0.999f) continue;  // float32 itself loses the last digits there
        worst = std::max(worst, angleDegrees(glm::dvec3(normals[i]), glm::dvec3(decoded[i])));
        // The CPU reference transform agrees with the GLSL one.
        const glm::dvec3 n = glm::normalize(glm::dvec3(normals[i]));
        ASSERT_NEAR(glm::length(reference::decodeNormalKL(reference::encodeNormalKL(n)) - n), 0.0, 1e-12);
    }
    EXPECT_LT(worst, 0.01) << "float32 KL round trip worst error " << worst << " deg";
}

TEST(NormalEncoding, Rg16SnormKeepsViewSpaceNormalsWithinHundredthsOfADegree) {
    const auto normals = randomNormals(100000, 11);
    const auto decoded = roundTrip(normals, GL_RG16_SNORM, "rg16_snorm");
    double worstVisible = 0.0, worstAll = 0.0, sum = 0.0;
    int counted = 0;
    for (size_t i = 0; i < normals.size(); ++i) {
        const double a = angleDegrees(glm::dvec3(normals[i]), glm::dvec3(decoded[i]));
        ASSERT_TRUE(std::isfinite(a));
        ASSERT_NEAR(glm::length(decoded[i]), 1.0f, 1e-3f);
        if (normals[i].z >= -0.9f) {  // covers every surface a perspective camera can see
            worstVisible = std::max(worstVisible, a);
            sum += a;
            ++counted;
        }
        if (normals[i].z >= -0.9999f) worstAll = std::max(worstAll, a);
    }
    RecordProperty("worst_visible_deg", std::to_string(worstVisible));
    RecordProperty("mean_visible_deg", std::to_string(sum / counted));
    std::printf("RG16_SNORM KL normals: mean %.5f deg, worst %.5f deg (n.z >= -0.9), worst %.4f deg (n.z >= -0.9999)\n",
                sum / counted, worstVisible, worstAll);
    EXPECT_LT(worstVisible, 0.02);
    EXPECT_LT(worstAll, 1.0);
}

// gbuffer.normal_encoding (issue 23): each encoding's round trip through its
// G-buffer format over a dense, even set of unit vectors (a Fibonacci sphere),
// in degrees; octahedral 16-bit beats Kircher-Lawrance's worst case near -z
// (normals facing away from the viewer, where KL's z = sqrt(1 - |e|^2) has no
// precision left), and oct8 costs about a degree.
namespace {

std::vector<glm::vec4> fibonacciSphere(int n) {
    std::vector<glm::vec4> v;
    const double golden = glm::pi<double>() * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / n;
        const double r = std::sqrt(1.0 - z * z);
        v.emplace_back(static_cast<float>(r * std::cos(golden * i)), static_cast<float>(r * std::sin(golden * i)),
                       static_cast<float>(z), 0.0f);
    }
    return v;
}

struct AngularError {
    double worst = 0, mean = 0, worstNearMinusZ = 0;  // the last over n.z < -0.99 (within 8 deg of -z)
};

AngularError measure(const std::vector<glm::vec4>& normals, const std::vector<glm::vec4>& decoded) {
    AngularError e;
    for (size_t i = 0; i < normals.size(); ++i) {
        const double a = angleDegrees(glm::dvec3(normals[i]), glm::dvec3(decoded[i]));
        EXPECT_TRUE(std::isfinite(a)) << i;
        e.worst = std::max(e.worst, a);
        e.mean += a;
        if (normals[i].z < -0.99f) e.worstNearMinusZ = std::max(e.worstNearMinusZ, a);
    }
    e.mean /= static_cast<double>(normals.size());
    return e;
}

}  // namespace

TEST(NormalEncoding, EachEncodingsRoundTripErrorOverADenseSphere) {
    const auto normals = fibonacciSphere(200000);
    const AngularError kl16 = measure(normals, roundTrip(normals, GL_RG16_SNORM, "rg16_snorm"));
    const AngularError oct16 =
        measure(normals, roundTrip(normals, GL_RG16_SNORM, "rg16_snorm", "encodeNormalOct", "decodeNormalOct"));
    const AngularError oct8 =
        measure(normals, roundTrip(normals, GL_RG8_SNORM, "rg8_snorm", "encodeNormalOct", "decodeNormalOct"));
    for (const auto& [name, e] : {std::pair{"kl16", kl16}, std::pair{"oct16", oct16}, std::pair{"oct8", oct8}}) {
        std::printf("gbuffer.normal_encoding=%s over 200000 directions: worst %.5f deg, mean %.5f deg, worst within 8 "
                    "deg of -z %.5f deg\n",
                    name, e.worst, e.mean, e.worstNearMinusZ);
        RecordProperty(std::string(name) + "_worst_deg", std::to_string(e.worst));
        RecordProperty(std::string(name) + "_mean_deg", std::to_string(e.mean));
    }
    // Octahedral 16-bit: uniform, a few thousandths of a degree everywhere.
    EXPECT_LT(oct16.worst, 0.01);
    EXPECT_LT(oct16.mean, 0.005);
    // Kircher-Lawrance is as good facing the viewer but loses it near -z.
    EXPECT_GT(kl16.worstNearMinusZ, 10.0 * oct16.worstNearMinusZ);
    EXPECT_LT(oct16.worstNearMinusZ, kl16.worstNearMinusZ);
    // Octahedral 8-bit: under a degree and a half at worst, a few tenths on average.
    EXPECT_LT(oct8.worst, 1.5);
    EXPECT_LT(oct8.mean, 0.5);
    EXPECT_GT(oct8.mean, oct16.mean);
    // The CPU transform (the probe's decode) agrees with the GLSL one.
    for (size_t i = 0; i < normals.size(); i += 97) {
        const glm::dvec3 n = glm::normalize(glm::dvec3(normals[i]));
        ASSERT_NEAR(glm::length(reference::decodeNormalOct(reference::encodeNormalOct(n)) - n), 0.0, 1e-12) << i;
    }
}

// The whole path: the geometry pass encodes, the decode pass (and every other
// reader: lighting, SSAO, buffer view) decodes by the frame's choice. A sphere's
// rasterised normal is exactly the normalised offset of its reconstructed
// position from the centre (the interpolated vertex normals of a sphere mesh
// are the barycentric blend of the vertices' offsets), so gbuffer.view_normal
// is compared with the analytic normal at every covered pixel.
TEST(NormalEncoding, RenderedSphereDecodesWithEachEncoding) {
    const int W = 160, H = 120;
    auto session = test::makeSession(W, H);
    const char* encodings[] = {"kl16", "oct16", "oct8"};
    double worst[3] = {}, mean[3] = {};
    FloatImage lbuffers[3];
    for (int k = 0; k < 3; ++k) {
        Scene s = test::planeScene(1.0f);
        s.instances.clear();
        Mesh ball = shapes::sphere(1.0f, 96, 48);
        ball.material = test::addBlinnPhong(s, {0.6f, 0.6f, 0.6f}, glm::vec3(0.3f), 30.0f);
        const glm::vec3 centre(0.3f, 0.2f, -0.5f);
        s.instances.push_back({s.addMesh(std::move(ball)), glm::translate(glm::mat4(1.0f), centre)});
        s.camera.position = {0.0f, 0.5f, 2.8f};
        s.camera.target = {0.0f, 0.0f, 0.0f};
        session->setScene(std::move(s));
        session->knobs().setFromString("gbuffer.normal_encoding", encodings[k]);
        session->render({{"gbuffer.view_normal", "gbuffer.view_position", "lbuffer"}});
        const FloatImage n = session->readRaw("gbuffer.view_normal");
        const FloatImage p = session->readRaw("gbuffer.view_position");
        lbuffers[k] = session->readRaw("lbuffer");
        const glm::dvec3 c = glm::dvec3(session->scene().camera.view() * glm::vec4(centre, 1.0f));
        int covered = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                if (p.at(x, y, 3) == 0.0f) continue;
                const glm::dvec3 pos(p.at(x, y, 0), p.at(x, y, 1), p.at(x, y, 2));
                const glm::dvec3 got(n.at(x, y, 0), n.at(x, y, 1), n.at(x, y, 2));
                const double a = angleDegrees(glm::normalize(pos - c), got);
                worst[k] = std::max(worst[k], a);
                mean[k] += a;
                ++covered;
            }
        ASSERT_GT(covered, W * H / 8) << encodings[k];
        mean[k] /= covered;
        std::printf("rendered sphere, gbuffer.normal_encoding=%s: view_normal vs analytic over %d pixels: worst %.4f "
                    "deg, mean %.4f deg\n",
                    encodings[k], covered, worst[k], mean[k]);
    }
    EXPECT_LT(worst[0], 0.02);
    EXPECT_LT(worst[1], 0.02);
    EXPECT_LT(worst[2], 1.5);
    EXPECT_GT(mean[2], mean[1]);
    // The lighting pass decodes the same way: oct16 lights the sphere as kl16 does.
    EXPECT_LT(test::maxAbsDifference(lbuffers[0], lbuffers[1], 3), 2e-3);
    EXPECT_LT(test::maxAbsDifference(lbuffers[0], lbuffers[2], 3), 0.05);
}
