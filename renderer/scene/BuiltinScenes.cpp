#include "renderer/scene/BuiltinScenes.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "renderer/Error.h"
#include "renderer/scene/IntegerHash.h"
#include "renderer/scene/ShapeBuilder.h"

namespace dw {

namespace {

// ---- deterministic procedural textures (no files, no RNG state)
std::uint32_t hash(std::uint32_t x) { return hashU32(x); }
float noise01(int x, int y, std::uint32_t seed) {
    return static_cast<float>(hash(static_cast<std::uint32_t>(x) * 73856093U ^ static_cast<std::uint32_t>(y) * 19349663U ^ seed) & 0xffff) / 65535.0f;
}

// Height field of rectangular blocks separated by mortar; `rowOffset` staggers rows (bricks).
float blockHeight(int x, int y, int size, int blocksX, int blocksY, float mortar, bool stagger) {
    const float fy = static_cast<float>(y) / size * blocksY;
    const int row = static_cast<int>(fy);
    float fx = static_cast<float>(x) / size * blocksX + (stagger && (row % 2) ? 0.5f : 0.0f);
    const float ux = fx - std::floor(fx), uy = fy - std::floor(fy);
    const float d = std::min(std::min(ux, 1.0f - ux) * (static_cast<float>(size) / blocksX),
                             std::min(uy, 1.0f - uy) * (static_cast<float>(size) / blocksY));
    return std::clamp(d / mortar, 0.0f, 1.0f);
}

struct BlockTexture {
    Image albedo;
    Image normal;
};

BlockTexture blockTexture(const std::string& name, int size, int blocksX, int blocksY, bool stagger,
                          glm::vec3 colorA, glm::vec3 colorB, glm::vec3 mortarColor, std::uint32_t seed) {
    BlockTexture t;
    t.albedo = Image{size, size, std::vector<std::uint8_t>(size * size * 4), "builtin:" + name};
    t.normal = Image{size, size, std::vector<std::uint8_t>(size * size * 4), "builtin:" + name + "-normal"};
    std::vector<float> h(size * size);
    const float mortar = 3.0f;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float hb = blockHeight(x, y, size, blocksX, blocksY, mortar, stagger);
            const float fy = static_cast<float>(y) / size * blocksY;
            const int row = static_cast<int>(fy);
            const int col = static_cast<int>(static_cast<float>(x) / size * blocksX + (stagger && (row % 2) ? 0.5f : 0.0f));
            const float blockTone = noise01(col, row, seed);
            const float grain = noise01(x, y, seed * 7 + 1) * 0.12f;
            glm::vec3 c = glm::mix(colorA, colorB, blockTone) * (0.94f + grain);
            c = glm::mix(mortarColor, c, hb);
            h[y * size + x] = hb * 0.8f + grain * 0.3f;
            std::uint8_t* p = &t.albedo.rgba[(y * size + x) * 4];
            for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(std::clamp(c[k], 0.0f, 1.0f) * 255.0f + 0.5f);
            p[3] = 255;
        }
    // Tangent-space normals from the height field (image rows top-down; +v is up).
    const float strength = 2.0f;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            auto H = [&](int xx, int yy) { return h[((yy + size) % size) * size + (xx + size) % size]; };
            const float dx = (H(x + 1, y) - H(x - 1, y)) * 0.5f * strength;
            const float dy = (H(x, y - 1) - H(x, y + 1)) * 0.5f * strength;
            const glm::vec3 n = glm::normalize(glm::vec3(-dx, -dy, 1.0f));
            std::uint8_t* p = &t.normal.rgba[(y * size + x) * 4];
            for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>((n[k] * 0.5f + 0.5f) * 255.0f + 0.5f);
            p[3] = 255;
        }
    return t;
}

glm::vec3 hueColor(float h) {
    const glm::vec3 k(0.0f, 2.0f / 3.0f, 1.0f / 3.0f);
    glm::vec3 c;
    for (int i = 0; i < 3; ++i) c[i] = std::clamp(std::fabs(std::fmod(h + k[i], 1.0f) * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
    return c;
}

class Builder {
public:
    explicit Builder(Scene& s) : s_(s) {}
    int material(const std::string& name, glm::vec3 diffuse, glm::vec3 specular, float exponent,
                 int albedoTex = -1, int normalTex = -1, glm::vec3 emissive = glm::vec3(0.0f)) {
        Material m;
        m.name = name;
        m.baseColor = glm::vec4(diffuse, 1.0f);
        m.specularColor = specular;
        m.specularExponent = exponent;
        m.baseColorTexture = albedoTex;
        m.normalTexture = normalTex;
        m.emissive = emissive;
        return s_.addMaterial(m);
    }
    int mesh(Mesh m, int material) {
        m.material = material;
        return s_.addMesh(std::move(m));
    }
    void place(int mesh, const glm::vec3& pos, float yawDegrees = 0.0f, glm::vec3 scale = glm::vec3(1.0f)) {
        glm::mat4 t = glm::translate(glm::mat4(1.0f), pos);
        t = glm::rotate(t, glm::radians(yawDegrees), glm::vec3(0, 1, 0));
        s_.instances.push_back({mesh, glm::scale(t, scale)});
    }
    // A blended material (issue 21): double-sided, so both faces of a
    // closed shape are layers, with `opacity` as the base colour's alpha.
    int glass(const std::string& name, glm::vec3 colour, float opacity, glm::vec3 specular = glm::vec3(0.5f),
              float exponent = 96.0f) {
        Material m;
        m.name = name;
        m.baseColor = glm::vec4(colour, opacity);
        m.specularColor = specular;
        m.specularExponent = exponent;
        m.alphaMode = AlphaMode::Blend;
        m.doubleSided = true;
        return s_.addMaterial(m);
    }
    Light& light(LightType type, const std::string& name, glm::vec3 pos, glm::vec3 dir, glm::vec3 intensity,
                 Attenuation att = {}, float cutoff = 45.0f, float exponent = 0.0f) {
        Light l;
        l.type = type;
        l.name = name;
        l.position = pos;
        l.direction = glm::normalize(dir);
        l.intensity = intensity;
        l.attenuation = att;
        l.cutoffDegrees = cutoff;
        l.exponent = exponent;
        s_.lights.push_back(l);
        return s_.lights.back();
    }

private:
    Scene& s_;
};

Scene courtyard() {
    Scene s;
    s.name = "default";
    s.ambient = glm::vec3(0.035f, 0.04f, 0.05f);
    s.background = glm::vec3(0.10f, 0.12f, 0.20f);
    s.sky.kind = Sky::Kind::Procedural;  // dusk, the sun low in the west
    s.sky.zenith = {0.06f, 0.09f, 0.22f};
    s.sky.horizon = {0.62f, 0.42f, 0.32f};
    s.sky.ground = {0.06f, 0.05f, 0.05f};
    s.sky.sunSizeDegrees = 2.0f;
    Builder b(s);
    BlockTexture tiles = blockTexture("tiles", 256, 4, 4, false, {0.55f, 0.52f, 0.47f}, {0.70f, 0.66f, 0.58f}, {0.25f, 0.24f, 0.22f}, 11);
    BlockTexture bricks = blockTexture("bricks", 256, 4, 8, true, {0.50f, 0.22f, 0.15f}, {0.65f, 0.33f, 0.22f}, {0.55f, 0.52f, 0.48f}, 23);
    const int tilesA = s.addImage(std::move(tiles.albedo)), tilesN = s.addImage(std::move(tiles.normal));
    const int bricksA = s.addImage(std::move(bricks.albedo)), bricksN = s.addImage(std::move(bricks.normal));
    const int floorMat = b.material("flagstones", glm::vec3(1.0f), glm::vec3(0.15f), 40.0f, tilesA, tilesN);
    const int wallMat = b.material("brick", glm::vec3(1.0f), glm::vec3(0.05f), 12.0f, bricksA, bricksN);
    const int stoneMat = b.material("marble", {0.82f, 0.80f, 0.76f}, glm::vec3(0.5f), 90.0f);
    const int bronzeMat = b.material("bronze", {0.25f, 0.16f, 0.08f}, {0.9f, 0.65f, 0.35f}, 200.0f);
    const int woodMat = b.material("crate", {0.45f, 0.30f, 0.16f}, glm::vec3(0.08f), 16.0f, bricksA);
    const int waterMat = b.material("basin", {0.15f, 0.22f, 0.25f}, glm::vec3(0.9f), 400.0f);

    const float W = 32.0f, D = 24.0f, H = 5.0f;
    b.place(b.mesh(shapes::plane(W + 8, D + 8, 0.5f), floorMat), {0, 0, 0});
    const int wallX = b.mesh(shapes::box({W, H, 0.6f}, 0.5f), wallMat);
    const int wallZ = b.mesh(shapes::box({0.6f, H, D}, 0.5f), wallMat);
    b.place(wallX, {0, H / 2, -D / 2});
    b.place(wallZ, {-W / 2, H / 2, 0});
    b.place(wallZ, {W / 2, H / 2, 0});
    // Two colonnades with architraves.
    const int column = b.mesh(shapes::cylinder(0.35f, 3.6f, 24), stoneMat);
    const int capital = b.mesh(shapes::box({1.0f, 0.3f, 1.0f}), stoneMat);
    const int plinth = b.mesh(shapes::box({0.9f, 0.2f, 0.9f}), stoneMat);
    const int beam = b.mesh(shapes::box({22.5f, 0.5f, 1.0f}), stoneMat);
    for (float z : {-5.0f, 5.0f}) {
        for (int i = 0; i < 6; ++i) {
            const float x = -11.25f + i * 4.5f;
            b.place(plinth, {x, 0.1f, z});
            b.place(column, {x, 0.2f, z});
            b.place(capital, {x, 3.95f, z});
        }
        b.place(beam, {0, 4.35f, z});
    }
    // Fountain with a bronze sphere.
    b.place(b.mesh(shapes::cylinder(2.2f, 0.5f, 48), stoneMat), {0, 0, 0});
    b.place(b.mesh(shapes::cylinder(1.9f, 0.52f, 48), waterMat), {0, 0, 0});
    b.place(b.mesh(shapes::cylinder(0.25f, 1.4f, 16), stoneMat), {0, 0.5f, 0});
    b.place(b.mesh(shapes::sphere(0.6f, 48, 24), bronzeMat), {0, 2.5f, 0});
    const int crate = b.mesh(shapes::box(glm::vec3(1.0f)), woodMat);
    const glm::vec4 crates[] = {{-13.5f, 0.5f, -9.5f, 10}, {-12.2f, 0.5f, -9.8f, 35}, {-12.9f, 1.5f, -9.6f, 20},
                                {13.2f, 0.5f, 9.0f, 5}, {9.5f, 0.5f, -9.5f, 60}};
    for (const auto& c : crates) b.place(crate, glm::vec3(c), c.w);

    // Low warm sun and a cool sky fill.
    Light& sun = b.light(LightType::Directional, "sun", {}, {-0.55f, -0.45f, -0.7f}, {0.9f, 0.62f, 0.38f});
    sun.castShadows = true;
    b.light(LightType::Directional, "sky fill", {}, {0.3f, -1.0f, 0.4f}, {0.05f, 0.07f, 0.12f});
    // 36 coloured point lights: lanterns along both colonnades and a ring round the fountain.
    int n = 0;
    for (float z : {-3.2f, 3.2f, -7.0f, 7.0f})
        for (int i = 0; i < 6; ++i) {
            const float x = -11.25f + i * 4.5f + (z < 0 ? 0.8f : -0.8f);
            const glm::vec3 c = hueColor(std::fmod(n * 0.137f + 0.05f, 1.0f));
            b.light(LightType::Point, "lantern" + std::to_string(n), {x, 0.6f + 0.3f * (n % 3), z}, {0, -1, 0},
                    c * 1.6f, {1.0f, 0.7f, 1.8f});
            ++n;
        }
    for (int i = 0; i < 12; ++i) {
        const float a = i / 12.0f * glm::two_pi<float>();
        const glm::vec3 c = hueColor(i / 12.0f);
        b.light(LightType::Point, "fountain" + std::to_string(i), {std::cos(a) * 2.7f, 0.35f, std::sin(a) * 2.7f},
                {0, -1, 0}, c * 1.2f, {1.0f, 1.2f, 3.0f});
    }
    // 8 wall-mounted spot lights aimed at the columns and the fountain.
    for (int i = 0; i < 8; ++i) {
        const float x = -12.0f + i * (24.0f / 7.0f);
        const glm::vec3 pos(x, 4.6f, -D / 2 + 0.6f);
        const glm::vec3 target(x * 0.6f, 0.0f, (i % 2) ? -5.0f : 0.0f);
        const glm::vec3 c = glm::mix(glm::vec3(1.0f, 0.85f, 0.6f), hueColor(i / 8.0f), 0.35f);
        Light& spot = b.light(LightType::Spot, "spot" + std::to_string(i), pos, target - pos, c * 6.0f, {1.0f, 0.35f, 0.25f}, 24.0f, 6.0f);
        spot.castShadows = i == 2 || i == 5;
    }
    s.camera.position = {-14.0f, 7.5f, 16.0f};
    s.camera.target = {0.5f, 1.2f, -1.0f};
    s.camera.fovYDegrees = 55.0f;
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 120.0f;
    return s;
}

Scene street() {
    Scene s;
    s.name = "street";
    // A night scene: a low key value (Reinhard 2002 suggests 0.045-0.09 for low-key images).
    s.settings = {{"tonemap.key", "0.05"}};
    s.ambient = glm::vec3(0.006f, 0.007f, 0.01f);
    s.background = glm::vec3(0.002f, 0.003f, 0.008f);
    s.sky.kind = Sky::Kind::Procedural;  // night: a faint glow at the horizon, the moon
    s.sky.zenith = {0.001f, 0.0015f, 0.005f};
    s.sky.horizon = {0.012f, 0.012f, 0.018f};
    s.sky.ground = {0.002f, 0.002f, 0.002f};
    s.sky.sunSizeDegrees = 1.0f;
    Builder b(s);
    BlockTexture paving = blockTexture("paving", 256, 8, 8, true, {0.42f, 0.41f, 0.40f}, {0.52f, 0.50f, 0.48f}, {0.2f, 0.2f, 0.2f}, 5);
    BlockTexture facade = blockTexture("facade", 256, 2, 6, true, {0.55f, 0.50f, 0.42f}, {0.62f, 0.58f, 0.50f}, {0.4f, 0.4f, 0.38f}, 9);
    const int pavingA = s.addImage(std::move(paving.albedo)), pavingN = s.addImage(std::move(paving.normal));
    const int facadeA = s.addImage(std::move(facade.albedo)), facadeN = s.addImage(std::move(facade.normal));
    const int asphalt = b.material("asphalt", {0.13f, 0.13f, 0.135f}, glm::vec3(0.08f), 30.0f);
    const int paint = b.material("lane paint", {0.8f, 0.78f, 0.7f}, glm::vec3(0.1f), 20.0f);
    const int pavingMat = b.material("paving", glm::vec3(1.0f), glm::vec3(0.06f), 20.0f, pavingA, pavingN);
    const int facadeMat = b.material("facade", glm::vec3(1.0f), glm::vec3(0.04f), 10.0f, facadeA, facadeN);
    const int steel = b.material("lamp steel", {0.12f, 0.13f, 0.14f}, glm::vec3(0.6f), 120.0f);
    const int bulb = b.material("bulb", {1.0f, 0.9f, 0.7f}, glm::vec3(0.0f), 1.0f, -1, -1, {6.0f, 4.8f, 3.0f});
    const int carPaint[3] = {b.material("car red", {0.45f, 0.03f, 0.03f}, glm::vec3(0.7f), 250.0f),
                             b.material("car blue", {0.03f, 0.08f, 0.35f}, glm::vec3(0.7f), 250.0f),
                             b.material("car white", {0.75f, 0.75f, 0.72f}, glm::vec3(0.7f), 250.0f)};

    const float L = 140.0f;
    b.place(b.mesh(shapes::plane(8.0f, L, 1.0f), asphalt), {0, 0, 0});
    const int dash = b.mesh(shapes::plane(0.15f, 3.0f), paint);
    for (float z = -L / 2 + 3; z < L / 2; z += 6.0f) b.place(dash, {0, 0.005f, z});
    const int walk = b.mesh(shapes::box({3.0f, 0.15f, L}, 0.5f), pavingMat);
    b.place(walk, {-5.5f, 0.075f, 0});
    b.place(walk, {5.5f, 0.075f, 0});
    const int building = b.mesh(shapes::box({6.0f, 12.0f, 14.0f}, 0.25f), facadeMat);
    for (float z = -L / 2 + 8; z < L / 2; z += 15.0f) {
        b.place(building, {-10.0f, 6.0f, z});
        b.place(building, {10.0f, 6.0f, z + 7.0f}, 0.0f, {1.0f, 0.8f, 1.0f});
    }
    // Street lamps: pole, arm, emissive bulb, and a spot light pointing down.
    const int pole = b.mesh(shapes::cylinder(0.09f, 6.0f, 12), steel);
    const int arm = b.mesh(shapes::box({1.4f, 0.1f, 0.1f}), steel);
    const int head = b.mesh(shapes::box({0.5f, 0.12f, 0.3f}), steel);
    const int glow = b.mesh(shapes::box({0.4f, 0.04f, 0.22f}), bulb);
    int n = 0;
    for (float z = -L / 2 + 6; z < L / 2 - 4; z += 12.0f) {
        for (int side : {-1, 1}) {
            const float zz = z + (side > 0 ? 6.0f : 0.0f);
            const float xPole = side * 4.4f;
            const float xLamp = side * 3.4f;
            b.place(pole, {xPole, 0.15f, zz});
            b.place(arm, {side * 3.8f, 6.1f, zz});
            b.place(head, {xLamp, 6.05f, zz});
            b.place(glow, {xLamp, 5.97f, zz});
            Light& lamp = b.light(LightType::Spot, "lamp" + std::to_string(n++), {xLamp, 5.9f, zz},
                                  {-side * 0.15f, -1.0f, 0.0f}, glm::vec3(1.0f, 0.82f, 0.55f) * 16.0f, {1.0f, 0.22f, 0.2f},
                                  42.0f, 6.0f);
            lamp.castShadows = zz > 12.0f;  // the lamps near the camera
        }
    }
    // Parked cars as simple boxes.
    const int body = b.mesh(shapes::box({1.8f, 0.75f, 4.2f}), carPaint[0]);
    const int body2 = b.mesh(shapes::box({1.8f, 0.75f, 4.2f}), carPaint[1]);
    const int body3 = b.mesh(shapes::box({1.8f, 0.75f, 4.2f}), carPaint[2]);
    const int cabin = b.mesh(shapes::box({1.6f, 0.6f, 2.2f}), steel);
    const glm::vec3 cars[] = {{-2.6f, 0, -30}, {2.6f, 0, -12}, {-2.6f, 0, 8}, {2.6f, 0, 21}, {-2.6f, 0, 40}};
    for (int i = 0; i < 5; ++i) {
        b.place(i % 3 == 0 ? body : (i % 3 == 1 ? body2 : body3), cars[i] + glm::vec3(0, 0.55f, 0));
        b.place(cabin, cars[i] + glm::vec3(0, 1.2f, -0.3f));
    }
    b.light(LightType::Directional, "moon", {}, {0.4f, -1.0f, 0.3f}, {0.015f, 0.02f, 0.035f});
    s.camera.position = {1.5f, 3.2f, 48.0f};
    s.camera.target = {0.0f, 1.5f, 0.0f};
    s.camera.fovYDegrees = 50.0f;
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 200.0f;
    return s;
}

Scene spheres() {
    Scene s;
    s.name = "spheres";
    s.ambient = glm::vec3(0.06f);
    s.background = glm::vec3(0.18f, 0.2f, 0.24f);
    Builder b(s);
    BlockTexture checker = blockTexture("checker", 128, 8, 8, false, {0.35f, 0.35f, 0.35f}, {0.6f, 0.6f, 0.6f}, {0.3f, 0.3f, 0.3f}, 3);
    const int checkerA = s.addImage(std::move(checker.albedo));
    const int floorMat = b.material("floor", glm::vec3(1.0f), glm::vec3(0.05f), 10.0f, checkerA);
    b.place(b.mesh(shapes::plane(20.0f, 14.0f, 0.5f), floorMat), {0, -0.75f, 0});
    // Rows: specular colour family; columns: Blinn-Phong exponent 4 .. 1024.
    struct Row {
        const char* name;
        glm::vec3 diffuse, specular;
    };
    const Row rows[] = {{"plastic", {0.6f, 0.08f, 0.06f}, glm::vec3(0.04f)},
                        {"glossy", {0.08f, 0.25f, 0.6f}, glm::vec3(0.25f)},
                        {"gold", {0.05f, 0.035f, 0.01f}, {1.0f, 0.78f, 0.34f}},
                        {"copper", {0.05f, 0.03f, 0.02f}, {0.95f, 0.64f, 0.54f}}};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 9; ++c) {
            const float exponent = std::pow(2.0f, 2.0f + c);
            const int mat = b.material(std::string(rows[r].name) + " n=" + std::to_string(static_cast<int>(exponent)),
                                       rows[r].diffuse, rows[r].specular, exponent);
            b.place(b.mesh(shapes::sphere(0.62f, 48, 24), mat), {-6.4f + c * 1.6f, 0.0f, -2.4f + r * 1.6f});
        }
    // One shadow caster of each kind: directional, point (cube map) and spot.
    b.light(LightType::Directional, "key", {}, {0.7f, -0.7f, 0.25f}, glm::vec3(1.1f, 1.05f, 1.0f)).castShadows = true;
    b.light(LightType::Point, "warm", {-4.0f, 1.6f, 3.5f}, {0, -1, 0}, {2.0f, 1.2f, 0.5f}, {1.0f, 0.3f, 0.4f}).castShadows = true;
    b.light(LightType::Point, "cool", {4.0f, 1.6f, 3.5f}, {0, -1, 0}, {0.5f, 1.0f, 2.0f}, {1.0f, 0.3f, 0.4f});
    b.light(LightType::Spot, "spot", {0.0f, 5.0f, 2.0f}, {0.0f, -1.0f, -0.6f}, glm::vec3(3.0f), {1.0f, 0.1f, 0.05f}, 20.0f, 10.0f)
        .castShadows = true;
    s.camera.position = {0.0f, 5.0f, 10.5f};
    s.camera.target = {0.0f, -0.4f, 0.0f};
    s.camera.fovYDegrees = 50.0f;
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 60.0f;
    return s;
}

// Issue 21's transparency scene: intersecting coloured panes (thin boxes, so
// each pane is two layers) in a fan about one vertical axis, a row of eight
// parallel panes, and nested transparent objects (a sphere in a box in a
// sphere); the row and the nest put more than 8 layers on some pixels, so
// a 4-sample A-buffer overflows there. Every map is kept
// (shadows.reuse_map = false), so the glass receives shadows too.
Scene glassScene() {
    Scene s;
    s.name = "glass";
    s.ambient = glm::vec3(0.08f);
    s.background = glm::vec3(0.16f, 0.18f, 0.22f);
    Builder b(s);
    BlockTexture checker = blockTexture("checker", 128, 8, 8, false, {0.35f, 0.35f, 0.35f}, {0.7f, 0.7f, 0.7f}, {0.3f, 0.3f, 0.3f}, 3);
    const int checkerA = s.addImage(std::move(checker.albedo));
    const int floorMat = b.material("floor", glm::vec3(1.0f), glm::vec3(0.05f), 10.0f, checkerA);
    b.place(b.mesh(shapes::plane(24.0f, 16.0f, 0.5f), floorMat), {0, 0, 0});
    const int wallMat = b.material("wall", {0.55f, 0.5f, 0.45f}, glm::vec3(0.05f), 10.0f);
    b.place(b.mesh(shapes::box({24.0f, 6.0f, 0.3f}), wallMat), {0, 3.0f, -6.0f});
    const int pillarMat = b.material("pillar", {0.7f, 0.2f, 0.15f}, glm::vec3(0.2f), 40.0f);
    b.place(b.mesh(shapes::cylinder(0.35f, 3.0f), pillarMat), {-4.5f, 1.5f, -2.0f});
    // The fan: four panes through the axis x = -4.5, z = 0.5, 45 degrees apart.
    const glm::vec3 fanColours[] = {{1.0f, 0.2f, 0.2f}, {0.2f, 1.0f, 0.3f}, {0.25f, 0.4f, 1.0f}, {1.0f, 0.9f, 0.2f}};
    for (int i = 0; i < 4; ++i) {
        const int mat = b.glass("fan pane " + std::to_string(i), fanColours[i], 0.35f);
        b.place(b.mesh(shapes::box({3.0f, 2.4f, 0.04f}), mat), {-4.5f, 1.3f, 0.5f}, 45.0f * i);
    }
    // The row: eight parallel panes one behind the other, 0.35 apart, each a little to the side.
    for (int i = 0; i < 8; ++i) {
        const float t = i / 7.0f;
        const int mat = b.glass("row pane " + std::to_string(i), {0.3f + 0.7f * t, 0.8f - 0.5f * t, 1.0f - 0.7f * t}, 0.25f);
        b.place(b.mesh(shapes::box({2.2f, 2.0f, 0.03f}), mat), {0.0f + 0.12f * i, 1.2f, 1.5f - 0.35f * i});
    }
    // The nest: a sphere in a box in a sphere.
    const int outer = b.glass("outer sphere", {0.6f, 0.9f, 1.0f}, 0.2f);
    const int middle = b.glass("middle box", {1.0f, 0.6f, 0.2f}, 0.3f);
    const int inner = b.glass("inner sphere", {1.0f, 0.15f, 0.5f}, 0.5f);
    b.place(b.mesh(shapes::sphere(1.4f, 40, 20), outer), {4.5f, 1.5f, 0.5f});
    b.place(b.mesh(shapes::box({1.5f, 1.5f, 1.5f}), middle), {4.5f, 1.5f, 0.5f}, 30.0f);
    b.place(b.mesh(shapes::sphere(0.5f, 32, 16), inner), {4.5f, 1.5f, 0.5f});
    b.light(LightType::Directional, "sun", {}, {-0.4f, -0.8f, -0.45f}, glm::vec3(1.6f, 1.5f, 1.4f)).castShadows = true;
    b.light(LightType::Point, "warm", {2.0f, 3.5f, 3.0f}, {0, -1, 0}, {2.5f, 1.6f, 0.8f}, {1.0f, 0.2f, 0.15f});
    b.light(LightType::Point, "cool", {-3.0f, 3.0f, 3.5f}, {0, -1, 0}, {0.6f, 1.0f, 2.2f}, {1.0f, 0.2f, 0.15f});
    s.settings.push_back({"shadows.reuse_map", "false"});
    s.camera.position = {0.0f, 3.2f, 9.5f};
    s.camera.target = {0.0f, 1.3f, 0.0f};
    s.camera.fovYDegrees = 55.0f;
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 60.0f;
    return s;
}

// Seed 004's fire: a central fire pit and four braziers in a ring of columns
// under a night sky; every flame particle is a small point light (300 in all)
// that rises, sways, fades and respawns frame by frame (FlameParticles).
Scene fire() {
    Scene s;
    s.name = "fire";
    s.settings = {{"tonemap.key", "0.045"}};
    s.ambient = glm::vec3(0.002f, 0.0025f, 0.004f);
    s.background = glm::vec3(0.002f, 0.003f, 0.008f);
    s.sky.kind = Sky::Kind::Procedural;  // night, as the street scene's
    s.sky.zenith = {0.0005f, 0.0007f, 0.0025f};
    s.sky.horizon = {0.004f, 0.004f, 0.007f};
    s.sky.ground = {0.001f, 0.001f, 0.001f};
    s.sky.sunSizeDegrees = 1.0f;
    Builder b(s);
    BlockTexture paving = blockTexture("fire-paving", 256, 6, 6, true, {0.40f, 0.38f, 0.36f}, {0.52f, 0.49f, 0.45f}, {0.18f, 0.17f, 0.16f}, 41);
    BlockTexture stones = blockTexture("fire-stones", 256, 3, 6, true, {0.50f, 0.46f, 0.40f}, {0.62f, 0.58f, 0.50f}, {0.30f, 0.28f, 0.26f}, 43);
    const int pavingA = s.addImage(std::move(paving.albedo)), pavingN = s.addImage(std::move(paving.normal));
    const int stonesA = s.addImage(std::move(stones.albedo)), stonesN = s.addImage(std::move(stones.normal));
    const int groundMat = b.material("paving", glm::vec3(1.0f), glm::vec3(0.08f), 24.0f, pavingA, pavingN);
    const int wallMat = b.material("stone wall", glm::vec3(1.0f), glm::vec3(0.05f), 12.0f, stonesA, stonesN);
    const int columnMat = b.material("sandstone", {0.72f, 0.64f, 0.52f}, glm::vec3(0.25f), 40.0f);
    const int iron = b.material("iron", {0.07f, 0.06f, 0.055f}, {0.6f, 0.55f, 0.5f}, 90.0f);
    const int rimMat = b.material("fire-pit stones", {0.35f, 0.33f, 0.31f}, glm::vec3(0.1f), 20.0f, stonesA, stonesN);
    const int logMat = b.material("charred wood", {0.10f, 0.06f, 0.04f}, glm::vec3(0.03f), 8.0f, -1, -1, {0.6f, 0.1f, 0.0f});
    const int emberMat = b.material("embers", {0.2f, 0.05f, 0.02f}, glm::vec3(0.0f), 1.0f, -1, -1, {6.0f, 1.8f, 0.3f});

    b.place(b.mesh(shapes::plane(34.0f, 28.0f, 0.5f), groundMat), {0, 0, 0});
    const int backWall = b.mesh(shapes::box({28.0f, 4.5f, 0.8f}, 0.5f), wallMat);
    const int sideWall = b.mesh(shapes::box({0.8f, 3.0f, 18.0f}, 0.5f), wallMat);
    b.place(backWall, {0, 2.25f, -10.0f});
    b.place(sideWall, {-14.0f, 1.5f, -1.5f});
    b.place(sideWall, {14.0f, 1.5f, -1.5f});
    // A ring of columns round the central pit.
    const int column = b.mesh(shapes::cylinder(0.32f, 3.4f, 24), columnMat);
    const int capital = b.mesh(shapes::box({0.9f, 0.25f, 0.9f}), columnMat);
    const int plinth = b.mesh(shapes::box({0.8f, 0.2f, 0.8f}), columnMat);
    for (int i = 0; i < 8; ++i) {
        const float a = (i + 0.5f) / 8.0f * glm::two_pi<float>();
        const glm::vec3 p(std::cos(a) * 5.0f, 0.0f, std::sin(a) * 5.0f);
        b.place(plinth, p + glm::vec3(0, 0.1f, 0));
        b.place(column, p + glm::vec3(0, 0.2f, 0));
        b.place(capital, p + glm::vec3(0, 3.72f, 0), glm::degrees(a));
    }
    // The central pit: a stone rim, a bed of embers and a few logs.
    b.place(b.mesh(shapes::cylinder(1.25f, 0.35f, 40), rimMat), {0, 0, 0});
    b.place(b.mesh(shapes::cylinder(1.0f, 0.37f, 40), emberMat), {0, 0, 0});
    const int log = b.mesh(shapes::box({1.5f, 0.18f, 0.18f}), logMat);
    for (int i = 0; i < 4; ++i) b.place(log, {0, 0.45f + 0.1f * (i % 2), 0}, i * 45.0f + 10.0f);
    // Four braziers: a pedestal, an iron bowl and embers.
    const int pedestal = b.mesh(shapes::cylinder(0.12f, 1.0f, 16), iron);
    const int foot = b.mesh(shapes::cylinder(0.35f, 0.08f, 24), iron);
    const int bowl = b.mesh(shapes::cylinder(0.55f, 0.28f, 32), iron);
    const int coals = b.mesh(shapes::cylinder(0.45f, 0.3f, 32), emberMat);
    const glm::vec3 braziers[] = {{-8.5f, 0, -5.5f}, {8.5f, 0, -5.5f}, {-8.5f, 0, 4.0f}, {8.5f, 0, 4.0f}};
    for (const auto& p : braziers) {
        b.place(foot, p);
        b.place(pedestal, p + glm::vec3(0, 0.08f, 0));
        b.place(bowl, p + glm::vec3(0, 1.05f, 0));
        b.place(coals, p + glm::vec3(0, 1.05f, 0));
    }

    b.light(LightType::Directional, "moon", {}, {0.35f, -1.0f, -0.45f}, {0.006f, 0.008f, 0.016f});
    // 100 particles over the pit, 50 over each brazier.
    s.flames.emitters.push_back({{0.0f, 0.4f, 0.0f}, 0.75f, 2.2f, 2.6f, 100});
    for (const auto& p : braziers) s.flames.emitters.push_back({p + glm::vec3(0, 1.38f, 0), 0.35f, 1.3f, 1.8f, 50});
    s.flames.firstLight = s.lights.size();
    appendFlameLights(s.flames, 0, s.lights);

    s.camera.position = {0.0f, 5.5f, 15.5f};
    s.camera.target = {0.0f, 1.2f, -1.5f};
    s.camera.fovYDegrees = 55.0f;
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 120.0f;
    return s;
}


// Seed 000 section 6.5's "larger scene with hundreds of thousands of
// triangles split into several hundred objects ... with complex transparent
// objects" and "one shadow-casting directional light": an open atrium of two
// storeys (Sponza-like, seed 000 table 6.1's Sponza has 385 objects and
// 285 583 triangles) with finely tessellated urns, columns, crates, glass
// lanterns and glass panes, lit by a shadowed sun only; bench --lights N
// --keep-scene-lights adds the seed's point lights (preset Overall).
Scene atrium() {
    Scene s;
    s.name = "atrium";
    s.ambient = glm::vec3(0.04f, 0.045f, 0.05f);
    s.background = glm::vec3(0.35f, 0.45f, 0.65f);
    s.sky.kind = Sky::Kind::Procedural;  // afternoon
    s.sky.zenith = {0.18f, 0.30f, 0.62f};
    s.sky.horizon = {0.62f, 0.66f, 0.72f};
    s.sky.ground = {0.10f, 0.09f, 0.08f};
    s.sky.sunSizeDegrees = 1.5f;
    Builder b(s);
    BlockTexture tiles = blockTexture("atrium-tiles", 256, 8, 8, false, {0.58f, 0.55f, 0.50f}, {0.72f, 0.68f, 0.60f}, {0.30f, 0.28f, 0.25f}, 51);
    BlockTexture stones = blockTexture("atrium-stones", 256, 3, 6, true, {0.62f, 0.56f, 0.46f}, {0.72f, 0.66f, 0.55f}, {0.45f, 0.42f, 0.38f}, 53);
    const int tilesA = s.addImage(std::move(tiles.albedo)), tilesN = s.addImage(std::move(tiles.normal));
    const int stonesA = s.addImage(std::move(stones.albedo)), stonesN = s.addImage(std::move(stones.normal));
    const int floorMat = b.material("atrium floor", glm::vec3(1.0f), glm::vec3(0.12f), 32.0f, tilesA, tilesN);
    const int wallMat = b.material("atrium wall", glm::vec3(1.0f), glm::vec3(0.04f), 10.0f, stonesA, stonesN);
    const int stoneMat = b.material("limestone", {0.78f, 0.74f, 0.66f}, glm::vec3(0.3f), 50.0f);
    const int urnMat = b.material("glazed urn", {0.16f, 0.30f, 0.42f}, glm::vec3(0.7f), 180.0f);
    const int woodMat = b.material("atrium crate", {0.45f, 0.31f, 0.17f}, glm::vec3(0.06f), 14.0f);

    const float W = 40.0f, D = 18.0f, H = 10.0f, gallery = 4.6f;
    b.place(b.mesh(shapes::plane(W + 4, D + 4, 0.25f), floorMat), {0, 0, 0});
    const int wallX = b.mesh(shapes::box({W, H, 0.6f}, 0.25f), wallMat);
    const int wallZ = b.mesh(shapes::box({0.6f, H, D}, 0.25f), wallMat);
    b.place(wallX, {0, H / 2, -D / 2});
    b.place(wallX, {0, H / 2, D / 2});
    b.place(wallZ, {-W / 2, H / 2, 0});
    b.place(wallZ, {W / 2, H / 2, 0});
    // The galleries: a slab over each aisle, a beam along each arcade.
    const int slab = b.mesh(shapes::box({W, 0.35f, 3.8f}, 0.25f), stoneMat);
    const int beam = b.mesh(shapes::box({W - 2.0f, 0.5f, 0.8f}), stoneMat);
    for (float z : {-7.1f, 7.1f}) b.place(slab, {0, gallery, z});
    for (float z : {-5.0f, 5.0f})
        for (float y : {gallery - 0.3f, 2.0f * gallery - 0.3f}) b.place(beam, {0, y, z});
    // Two storeys of arcades: nine columns a row, plinth, shaft, capital.
    const int column = b.mesh(shapes::cylinder(0.38f, gallery - 0.9f, 48), stoneMat);
    const int plinth = b.mesh(shapes::box({1.0f, 0.3f, 1.0f}), stoneMat);
    const int capital = b.mesh(shapes::box({1.1f, 0.3f, 1.1f}), stoneMat);
    for (int storey = 0; storey < 2; ++storey)
        for (float z : {-5.0f, 5.0f})
            for (int i = 0; i < 9; ++i) {
                const glm::vec3 p(-16.0f + i * 4.0f, storey * gallery, z);
                b.place(plinth, p + glm::vec3(0, 0.15f, 0));
                b.place(column, p + glm::vec3(0, 0.3f, 0));
                b.place(capital, p + glm::vec3(0, gallery - 0.75f, 0));
            }
    // Sixty urns on pedestals along the aisles, on both floors: most of the triangles.
    const int urn = b.mesh(shapes::sphere(0.45f, 64, 32), urnMat);
    const int pedestal = b.mesh(shapes::box({0.6f, 0.8f, 0.6f}), stoneMat);
    for (int storey = 0; storey < 2; ++storey)
        for (float z : {-7.8f, 7.8f})
            for (int i = 0; i < 15; ++i) {
                const glm::vec3 p(-18.2f + i * 2.6f, storey * (gallery + 0.175f), z);
                b.place(pedestal, p + glm::vec3(0, 0.4f, 0));
                b.place(urn, p + glm::vec3(0, 1.25f, 0), 0.0f, {1.0f, 1.2f, 1.0f});
            }
    // Crates stacked in the nave's corners.
    const int crate = b.mesh(shapes::box(glm::vec3(0.8f)), woodMat);
    for (int c = 0; c < 80; ++c) {
        const int corner = c / 20, k = c % 20;
        const float sx = corner % 2 ? 1.0f : -1.0f, sz = corner / 2 ? 1.0f : -1.0f;
        const glm::vec3 p(sx * (17.0f - 0.9f * (k % 4)), 0.4f + 0.8f * (k / 12), sz * (2.6f - 0.9f * ((k / 4) % 3)));
        b.place(crate, p, 7.0f * static_cast<float>(c % 5));
    }
    // Transparency: glass lanterns hanging over the nave and panes between the upper columns.
    for (int i = 0; i < 24; ++i) {
        const int mat = b.glass("lantern " + std::to_string(i), hueColor(std::fmod(i * 0.21f, 1.0f)) * 0.8f + glm::vec3(0.2f), 0.3f);
        b.place(b.mesh(shapes::sphere(0.35f, 32, 16), mat), {-17.25f + i * 1.5f, 3.0f + 0.6f * (i % 3), (i % 2) ? 1.2f : -1.2f});
    }
    const int pane = b.mesh(shapes::box({3.2f, 2.6f, 0.04f}), b.glass("gallery glass", {0.55f, 0.8f, 0.75f}, 0.25f));
    for (float z : {-5.0f, 5.0f})
        for (int i = 0; i < 8; ++i) b.place(pane, {-14.0f + i * 4.0f, gallery + 1.6f, z});
    b.light(LightType::Directional, "sun", {}, {-0.35f, -1.0f, -0.3f}, {2.2f, 2.0f, 1.7f}).castShadows = true;
    s.camera.position = {-17.0f, 6.5f, 3.5f};
    s.camera.target = {4.0f, 2.2f, -1.0f};
    s.camera.fovYDegrees = 60.0f;
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 120.0f;
    return s;
}

}  // namespace

const std::vector<BuiltinSceneInfo>& builtinScenes() {
    static const std::vector<BuiltinSceneInfo> scenes = {
        {"default", "courtyard at dusk: columns, fountain, a sun, 36 coloured point lights, 8 spot lights"},
        {"street", "night road lit by 22 spot-light street lamps (the 9 nearest the camera cast shadows) and a moon (the CMSC 23700 motivating case)"},
        {"spheres", "material grid: 4 specular families x 9 Blinn-Phong exponents, a shadowing key light, a point and a spot light"},
        {"glass", "transparency: intersecting coloured panes, a row of eight panes and a sphere in a box in a sphere (blended materials, depth complexity above 8; issue 21)"},
        {"fire", "night courtyard with a fire pit and four braziers: 300 flame particles, each a small point light, animated per frame (seed 004)"},
        {"atrium", "two-storey open atrium (seed 000 section 6.5's scene, preset Overall): several hundred objects, hundreds of thousands of triangles, glass lanterns and panes, a shadowed sun only"},
    };
    return scenes;
}

bool isBuiltinScene(const std::string& name) {
    for (const auto& s : builtinScenes())
        if (s.name == name) return true;
    return false;
}

Scene makeBuiltinScene(const std::string& name) {
    Scene s;
    if (name == "default") s = courtyard();
    else if (name == "street") s = street();
    else if (name == "spheres") s = spheres();
    else if (name == "fire") s = fire();
    else if (name == "glass") s = glassScene();
    else if (name == "atrium") s = atrium();
    else {
        std::string names;
        for (const auto& b : builtinScenes()) names += (names.empty() ? "" : ", ") + b.name;
        throw Error("unknown built-in scene '" + name + "' (built-in scenes: " + names + ")");
    }
    s.source = "builtin:" + name;
    return s;
}

}  // namespace dw
