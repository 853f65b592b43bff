#include "renderer/reference/TextureSampler.h"

#include <array>
#include <cmath>

namespace dw::reference {

namespace {

constexpr unsigned kRepeat = 0x2901, kClampToEdge = 0x812F, kMirroredRepeat = 0x8370;
constexpr unsigned kNearest = 0x2600;

const std::array<double, 256>& srgbTable() {
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = srgbToLinear(i / 255.0);
        return t;
    }();
    return table;
}

int wrap(int i, int n, unsigned mode) {
    if (mode == kClampToEdge) return i < 0 ? 0 : (i >= n ? n - 1 : i);
    if (mode == kMirroredRepeat) {
        const int period = 2 * n;
        int m = i % period;
        if (m < 0) m += period;
        return m < n ? m : period - 1 - m;
    }
    int m = i % n;
    return m < 0 ? m + n : m;
}

glm::dvec4 texel(const Image& image, int x, int y, bool srgb) {
    const std::uint8_t* p = &image.rgba[(static_cast<size_t>(y) * image.width + x) * 4];
    if (srgb) {
        const auto& t = srgbTable();
        return {t[p[0]], t[p[1]], t[p[2]], p[3] / 255.0};
    }
    return {p[0] / 255.0, p[1] / 255.0, p[2] / 255.0, p[3] / 255.0};
}

}  // namespace

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double linearToSrgb(double c) {
    return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

glm::dvec2 transformUv(const TextureMapping& mapping, const glm::dvec2& uv) {
    const glm::dvec3 h(uv, 1.0);
    return {glm::dot(glm::dvec3(mapping.row(0)), h), glm::dot(glm::dvec3(mapping.row(1)), h)};
}

glm::dvec4 sampleBilinear(const Image& image, const TextureMapping& mapping, const glm::dvec2& uv, bool srgb) {
    if (image.width <= 0 || image.height <= 0) return glm::dvec4(1.0);
    // The base level's magnification filter: nearest for GL_NEAREST, else
    // linear. (A nearest minification filter applies at the base level only
    // when minifying; the reference takes the magnification filter throughout.)
    const bool nearest = mapping.magFilter == kNearest;
    const double x = uv.x * image.width - 0.5, y = uv.y * image.height - 0.5;
    if (!std::isfinite(x) || !std::isfinite(y)) return texel(image, 0, 0, srgb);
    if (nearest) {
        const int ix = wrap(static_cast<int>(std::floor(x + 0.5)), image.width, mapping.wrapS);
        const int iy = wrap(static_cast<int>(std::floor(y + 0.5)), image.height, mapping.wrapT);
        return texel(image, ix, iy, srgb);
    }
    const double fx = std::floor(x), fy = std::floor(y);
    const double ax = x - fx, ay = y - fy;
    // Texture coordinates far outside [0, 1] stay in int range before wrapping.
    const auto base = [](double f, int n) { return static_cast<int>(std::fmod(f, 2.0 * n)); };
    const int x0 = base(fx, image.width), y0 = base(fy, image.height);
    const int xa = wrap(x0, image.width, mapping.wrapS), xb = wrap(x0 + 1, image.width, mapping.wrapS);
    const int ya = wrap(y0, image.height, mapping.wrapT), yb = wrap(y0 + 1, image.height, mapping.wrapT);
    const glm::dvec4 top = glm::mix(texel(image, xa, ya, srgb), texel(image, xb, ya, srgb), ax);
    const glm::dvec4 bottom = glm::mix(texel(image, xa, yb, srgb), texel(image, xb, yb, srgb), ax);
    return glm::mix(top, bottom, ay);
}

}  // namespace dw::reference
