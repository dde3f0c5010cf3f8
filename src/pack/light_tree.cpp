#include "pack/light_tree.h"

#include <algorithm>
#include <cmath>

namespace fp {

namespace {

constexpr float kPi = 3.14159265358979324f;

// The angle between unit vectors, accurate near 0 and pi (where acos of the dot product is not).
float angleBetween(const glm::vec3& a, const glm::vec3& b) {
    if (glm::dot(a, b) < 0.0f) return kPi - 2.0f * std::asin(std::min(1.0f, glm::length(a + b) / 2.0f));
    return 2.0f * std::asin(std::min(1.0f, glm::length(b - a) / 2.0f));
}

glm::vec3 anyPerpendicular(const glm::vec3& a) {
    glm::vec3 other = std::abs(a.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(glm::cross(a, other));
}

// Float rounding in the shader's importance (which compares cosines) must not make a bound exclude
// what it holds: cones are widened by this much.
constexpr float kConeSlack = 1e-4f;

}  // namespace

LightBounds unionOf(const LightBounds& a, const LightBounds& b) {
    if (!(a.power > 0.0f)) return b;
    if (!(b.power > 0.0f)) return a;
    LightBounds u;
    u.lo = glm::min(a.lo, b.lo);
    u.hi = glm::max(a.hi, b.hi);
    u.power = a.power + b.power;
    const LightBounds& wide = a.thetaO >= b.thetaO ? a : b;
    const LightBounds& narrow = a.thetaO >= b.thetaO ? b : a;
    float thetaD = angleBetween(wide.axis, narrow.axis);
    u.axis = wide.axis;
    u.thetaO = wide.thetaO;
    if (std::min(thetaD + narrow.thetaO, kPi) <= wide.thetaO) return u;  // the wide cone holds both
    float thetaO = 0.5f * (wide.thetaO + thetaD + narrow.thetaO);
    if (thetaO >= kPi) {
        u.thetaO = kPi;
        return u;
    }
    // Turn the wide cone's axis toward the narrow one's by the growth of the half-angle, in their plane.
    glm::vec3 toward = narrow.axis - glm::dot(narrow.axis, wide.axis) * wide.axis;
    toward = glm::dot(toward, toward) > 1e-12f ? glm::normalize(toward) : anyPerpendicular(wide.axis);
    float thetaR = thetaO - wide.thetaO;
    u.axis = glm::normalize(std::cos(thetaR) * wide.axis + std::sin(thetaR) * toward);
    u.thetaO = thetaO;
    return u;
}

LightTree buildLightTree(const std::vector<LightTreeEmitter>& emitters) {
    LightTree tree;
    while ((size_t(1) << tree.depth) < emitters.size()) ++tree.depth;
    const size_t leaves = size_t(1) << tree.depth;
    tree.nodes.resize(2 * leaves - 1);
    for (size_t e = 0; e < emitters.size(); ++e) {
        const LightTreeEmitter& t = emitters[e];
        glm::vec3 n = glm::cross(t.p1 - t.p0, t.p2 - t.p0);
        if (!(t.power > 0.0f) || !(glm::dot(n, n) > 0.0f)) continue;  // never picked: an empty leaf
        LightBounds& leaf = tree.nodes[leaves - 1 + e];
        leaf.lo = glm::min(t.p0, glm::min(t.p1, t.p2));
        leaf.hi = glm::max(t.p0, glm::max(t.p1, t.p2));
        leaf.power = t.power;
        leaf.axis = glm::normalize(n);  // emitters emit on the side their winding faces (surface.glsl)
    }
    for (size_t k = leaves - 1; k-- > 0;)
        tree.nodes[k] = unionOf(tree.nodes[2 * k + 1], tree.nodes[2 * k + 2]);
    return tree;
}

std::vector<glm::vec4> lightTreeTexels(const LightTree& tree) {
    std::vector<glm::vec4> texels;
    texels.reserve(3 * tree.nodes.size());
    for (const LightBounds& b : tree.nodes) {
        texels.emplace_back(b.lo, b.power);
        texels.emplace_back(b.hi, std::cos(std::min(b.thetaO + kConeSlack, kPi)));
        texels.emplace_back(b.axis, 0.0f);
    }
    return texels;
}

}  // namespace fp
