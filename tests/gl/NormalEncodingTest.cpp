// The G-buffer normal encoding (seed 000 section 3.1): the GLSL transform is
// exact, and RG16_SNORM storage keeps view-space normals to a small angle.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <random>

#include "renderer/gl/Buffer.h"
#include "renderer/gl/Program.h"
#include "renderer/gl/Texture.h"
#include "renderer/reference/ShadingReference.h"
#include "tests/support/TestSupport.h"

using namespace dw;

namespace {

// Encodes normals from an SSBO into an image of `format`, then decodes them back.
std::vector<glm::vec4> roundTrip(const std::vector<glm::vec4>& normals, GLenum format, const char* qualifier) {
    const std::string root = gl::ShaderLibrary::locateRoot().string();
    const std::string encode = std::string("#version 450 core\n#include \"common/gbuffer.glsl\"\n"
                                           "layout(local_size_x = 64) in;\n"
                                           "layout(std430, binding = 0) readonly buffer In { vec4 n[]; };\n"
                                           "layout(") + qualifier + ", binding = 0) uniform writeonly image2D img;\n"
                                           "void main() { uint i = gl_GlobalInvocationID.x; if (i >= n.length()) return;\n"
                                           "  imageStore(img, ivec2(i % 1024u, i / 1024u), vec4(encodeNormalKL(n[i].xyz), 0, 0)); }\n";
    const std::string decode = std::string("#version 450 core\n#include \"common/gbuffer.glsl\"\n"
                                           "layout(local_size_x = 64) in;\n"
                                           "layout(std430, binding = 1) writeonly buffer Out { vec4 d[]; };\n"
                                           "layout(") + qualifier + ", binding = 0) uniform readonly image2D img;\n"
                                           "void main() { uint i = gl_GlobalInvocationID.x; if (i >= d.length()) return;\n"
                                           "  d[i] = vec4(decodeNormalKL(imageLoad(img, ivec2(i % 1024u, i / 1024u)).xy), 0); }\n";
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
