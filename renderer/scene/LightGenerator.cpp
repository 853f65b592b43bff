#include "renderer/scene/LightGenerator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "renderer/Error.h"

namespace dw {

namespace {

// [0, 1) from the generator's top 24 bits: exact in a float, the same everywhere.
float unit(std::mt19937& rng) { return static_cast<float>(rng() >> 8) * (1.0f / 16777216.0f); }

glm::vec3 hsvToRgb(float h, float s, float v) {
    const float k[3] = {5.0f, 3.0f, 1.0f};
    glm::vec3 rgb;
    for (int i = 0; i < 3; ++i) {
        const float n = std::fmod(k[i] + h * 6.0f, 6.0f);
        rgb[i] = v - v * s * std::clamp(std::min(n, 4.0f - n), 0.0f, 1.0f);
    }
    return rgb;
}

}  // namespace

Attenuation attenuationForRadius(double radius, double brightness, double threshold) {
    // brightness / (1 + q r^2) = threshold  =>  q = (brightness / threshold - 1) / r^2.
    const double q = (brightness / threshold - 1.0) / (radius * radius);
    return {1.0f, 0.0f, static_cast<float>(q)};
}

std::vector<Light> generateLights(const Bounds& sceneBounds, const LightGeneratorSettings& s) {
    if (s.count < 0) throw Error("the light count must not be negative, got " + std::to_string(s.count));
    if (!(s.radius > 0.0f)) throw Error("the light radius must be positive, got " + std::to_string(s.radius));
    if (!(s.threshold > 0.0) || !(s.brightness > s.threshold))
        throw Error("the light brightness (" + std::to_string(s.brightness) + ") must exceed the threshold (" +
                    std::to_string(s.threshold) + ")");
    Bounds b = sceneBounds;
    if (b.empty()) b = Bounds{glm::vec3(-1.0f), glm::vec3(1.0f)};
    const float lift = std::max(s.minLift, s.liftFraction * (b.max.y - b.min.y));
    const float yLow = b.min.y + lift, yHigh = std::max(b.max.y, yLow);
    const Attenuation att = attenuationForRadius(s.radius, s.brightness, s.threshold);

    std::mt19937 rng(s.seed);
    std::vector<Light> lights;
    lights.reserve(static_cast<size_t>(s.count));
    for (int i = 0; i < s.count; ++i) {
        Light l;
        l.name = "generated" + std::to_string(i);
        l.type = LightType::Point;
        // One draw per coordinate, in a fixed order, so light i does not
        // depend on how the compiler orders the arguments.
        const float x = unit(rng), y = unit(rng), z = unit(rng);
        l.position = {b.min.x + x * (b.max.x - b.min.x), yLow + y * (yHigh - yLow), b.min.z + z * (b.max.z - b.min.z)};
        // Any hue, saturation at least 0.3, the brightest channel at `brightness`.
        const float hue = unit(rng), saturation = 0.3f + 0.7f * unit(rng);
        l.intensity = hsvToRgb(hue, saturation, 1.0f) * s.brightness;
        l.attenuation = att;
        l.castShadows = false;
        lights.push_back(l);
    }
    return lights;
}

}  // namespace dw
