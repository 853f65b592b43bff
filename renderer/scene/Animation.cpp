#include "renderer/scene/Animation.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace dw {

double SceneAnimation::duration() const {
    double d = 0.0;
    for (int c : playing)
        if (c >= 0 && c < static_cast<int>(clips.size())) d = std::max(d, static_cast<double>(clips[c].end));
    return d;
}

namespace {

// Shorter-arc slerp of two unit quaternions (xyzw), glTF 2.0 Appendix C:
// a = acos(|dot|), s = sign(dot), v = sin(a(1-u))/sin(a) v0 + s sin(a u)/sin(a) v1.
void slerp(const float* a, const float* b, double u, float* out) {
    double d = 0.0;
    for (int i = 0; i < 4; ++i) d += static_cast<double>(a[i]) * b[i];
    const double s = d < 0.0 ? -1.0 : 1.0;
    const double ad = std::min(1.0, std::abs(d));
    double wa = 1.0 - u, wb = u;
    const double angle = std::acos(ad);
    if (std::sin(angle) > 1e-6) {
        wa = std::sin(angle * (1.0 - u)) / std::sin(angle);
        wb = std::sin(angle * u) / std::sin(angle);
    }
    double len = 0.0;
    double v[4];
    for (int i = 0; i < 4; ++i) {
        v[i] = wa * a[i] + s * wb * b[i];
        len += v[i] * v[i];
    }
    len = std::sqrt(len);
    for (int i = 0; i < 4; ++i) out[i] = static_cast<float>(len > 0.0 ? v[i] / len : v[i]);
}

void normalise4(std::vector<float>& q) {
    double len = 0.0;
    for (float f : q) len += static_cast<double>(f) * f;
    len = std::sqrt(len);
    if (len > 0.0)
        for (float& f : q) f = static_cast<float>(f / len);
}

// Keyframe k with times[k] <= t < times[k+1] (t inside the range) and u in [0, 1).
std::size_t keyframeBefore(const std::vector<float>& times, double t) {
    const auto it = std::upper_bound(times.begin(), times.end(), static_cast<float>(t));
    return static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (it - times.begin()) - 1));
}

// Hermite spline between keyframes k and k+1 (Appendix C, "Cubic Spline Interpolation").
void cubic(const AnimationSampler& s, std::size_t k, double u, double td, float* out) {
    const int n = s.components;
    const float* v0 = &s.values[(3 * k + 1) * n];
    const float* b0 = &s.values[(3 * k + 2) * n];
    const float* a1 = &s.values[(3 * (k + 1)) * n];
    const float* v1 = &s.values[(3 * (k + 1) + 1) * n];
    const double u2 = u * u, u3 = u2 * u;
    for (int i = 0; i < n; ++i)
        out[i] = static_cast<float>((2 * u3 - 3 * u2 + 1) * v0[i] + td * (u3 - 2 * u2 + u) * b0[i] +
                                    (-2 * u3 + 3 * u2) * v1[i] + td * (u3 - u2) * a1[i]);
}

}  // namespace

std::vector<float> sampleAnimation(const AnimationSampler& s, double t, bool rotation) {
    const int n = s.components;
    const std::size_t keys = s.times.size();
    const bool spline = s.interpolation == Interpolation::CubicSpline;
    // The value (not a tangent) of keyframe k.
    auto value = [&](std::size_t k) { return &s.values[(spline ? 3 * k + 1 : k) * n]; };
    std::vector<float> out(static_cast<std::size_t>(n), 0.0f);
    if (keys == 0) return out;
    if (keys == 1 || t <= s.times.front() || t >= s.times.back()) {
        const float* v = value(t >= s.times.back() ? keys - 1 : 0);
        out.assign(v, v + n);
        return out;
    }
    const std::size_t k = keyframeBefore(s.times, t);
    const double td = static_cast<double>(s.times[k + 1]) - s.times[k];
    const double u = td > 0.0 ? (t - s.times[k]) / td : 0.0;
    if (s.interpolation == Interpolation::Step) {
        out.assign(value(k), value(k) + n);
    } else if (spline) {
        cubic(s, k, u, td, out.data());
        if (rotation) normalise4(out);
    } else if (rotation && n == 4) {
        slerp(value(k), value(k + 1), u, out.data());
    } else {
        for (int i = 0; i < n; ++i) out[i] = static_cast<float>((1.0 - u) * value(k)[i] + u * value(k + 1)[i]);
    }
    return out;
}

namespace {

glm::mat4 localMatrix(const AnimationNode& n) {
    if (n.hasMatrix) return n.matrix;
    return glm::translate(glm::mat4(1.0f), n.translation) * glm::mat4_cast(n.rotation) * glm::scale(glm::mat4(1.0f), n.scale);
}

void applyChannel(const AnimationClip& clip, const AnimationChannel& c, double t, std::vector<AnimationNode>& nodes) {
    AnimationNode& n = nodes[static_cast<std::size_t>(c.node)];
    const AnimationSampler& s = clip.samplers[static_cast<std::size_t>(c.sampler)];
    const std::vector<float> v = sampleAnimation(s, t, c.path == AnimationPath::Rotation);
    switch (c.path) {
        case AnimationPath::Translation: n.translation = glm::vec3(v[0], v[1], v[2]); break;
        case AnimationPath::Scale: n.scale = glm::vec3(v[0], v[1], v[2]); break;
        case AnimationPath::Rotation: n.rotation = glm::normalize(glm::quat(v[3], v[0], v[1], v[2])); break;
        case AnimationPath::Weights: n.weights = v; break;
    }
    if (c.path != AnimationPath::Weights) n.hasMatrix = false;
}

}  // namespace

NodePose evaluateNodes(const SceneAnimation& anim, double t) {
    std::vector<AnimationNode> nodes = anim.nodes;
    for (int c : anim.playing) {
        if (c < 0 || c >= static_cast<int>(anim.clips.size())) continue;
        const AnimationClip& clip = anim.clips[static_cast<std::size_t>(c)];
        for (const AnimationChannel& ch : clip.channels) applyChannel(clip, ch, t, nodes);
    }
    NodePose pose;
    pose.world.assign(nodes.size(), glm::mat4(1.0f));
    std::vector<char> done(nodes.size(), 0);
    // Parents first, whatever the order of the list (the importer refuses cycles).
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        std::vector<std::size_t> chain;
        for (std::size_t j = i; !done[j]; ) {
            chain.push_back(j);
            if (nodes[j].parent < 0) break;
            j = static_cast<std::size_t>(nodes[j].parent);
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const AnimationNode& n = nodes[*it];
            const glm::mat4 parent = n.parent < 0 ? n.root : pose.world[static_cast<std::size_t>(n.parent)];
            pose.world[*it] = parent * localMatrix(n);
            done[*it] = 1;
        }
    }
    pose.weights.reserve(nodes.size());
    for (auto& n : nodes) pose.weights.push_back(std::move(n.weights));
    return pose;
}

std::vector<glm::mat4> jointMatrices(const SceneAnimation& anim, const Skin& skin, const NodePose& pose) {
    std::vector<glm::mat4> out(skin.joints.size(), glm::mat4(1.0f));
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
        const auto node = static_cast<std::size_t>(skin.joints[j]);
        // The import's root is under the joint's world; the skinned vertices
        // come out in the root's frame, which the instance's transform adds back.
        const glm::mat4 rootInverse = glm::inverse(anim.nodes[node].root);
        out[j] = rootInverse * pose.world[node] * skin.inverseBind[j];
    }
    return out;
}

namespace {

// Rest vertex plus the weighted deltas of the morph targets; normal and tangent renormalised.
Vertex morphed(const Deformer& d, std::size_t i, const std::vector<float>& weights) {
    Vertex v = d.rest[i];
    glm::vec3 n = v.normal, t = glm::vec3(v.tangent);
    const std::size_t count = std::min(weights.size(), d.targets.size());
    for (std::size_t k = 0; k < count; ++k) {
        const MorphTarget& m = d.targets[k];
        const float w = weights[k];
        if (w == 0.0f) continue;
        if (!m.position.empty()) v.position += w * m.position[i];
        if (!m.normal.empty()) n += w * m.normal[i];
        if (!m.tangent.empty()) t += w * m.tangent[i];
    }
    if (glm::dot(n, n) > 0.0f) v.normal = glm::normalize(n);
    if (glm::dot(t, t) > 0.0f) v.tangent = glm::vec4(glm::normalize(t), v.tangent.w);
    return v;
}

// sum_i w_i * joints[j_i] over both joint/weight sets; false when the weights sum to zero.
bool skinMatrix(const Deformer& d, std::size_t i, const std::vector<glm::mat4>& joints, glm::mat4& m) {
    m = glm::mat4(0.0f);
    float total = 0.0f;
    for (int set = 0; set < 2; ++set) {
        if (d.joints[set].empty()) continue;
        const glm::uvec4 j = d.joints[set][i];
        const glm::vec4 w = d.weights[set][i];
        for (int c = 0; c < 4; ++c)
            if (w[c] != 0.0f && j[c] < joints.size()) {
                m += w[c] * joints[j[c]];
                total += w[c];
            }
    }
    return total > 0.0f;
}

}  // namespace

void poseVertices(const Deformer& d, const std::vector<float>& weights, const std::vector<glm::mat4>& joints,
                  std::vector<Vertex>& out) {
    out.resize(d.rest.size());
    const bool skinned = !joints.empty() && !d.joints[0].empty();
    for (std::size_t i = 0; i < d.rest.size(); ++i) {
        Vertex v = d.targets.empty() ? d.rest[i] : morphed(d, i, weights);
        glm::mat4 m;
        if (skinned && skinMatrix(d, i, joints, m)) {
            // The cofactor matrix: det * inverse transpose, defined for a singular
            // matrix too (a joint scaled to 0); its sign follows det's so a mirror keeps the side.
            const glm::mat3 a(m);
            const float sign = glm::determinant(a) < 0.0f ? -1.0f : 1.0f;
            const glm::mat3 normalMatrix =
                sign * glm::mat3(glm::cross(a[1], a[2]), glm::cross(a[2], a[0]), glm::cross(a[0], a[1]));
            v.position = glm::vec3(m * glm::vec4(v.position, 1.0f));
            const glm::vec3 n = normalMatrix * v.normal, t = glm::mat3(m) * glm::vec3(v.tangent);
            if (glm::dot(n, n) > 0.0f) v.normal = glm::normalize(n);
            if (glm::dot(t, t) > 0.0f) v.tangent = glm::vec4(glm::normalize(t), v.tangent.w);
        }
        out[i] = v;
    }
}

}  // namespace dw
