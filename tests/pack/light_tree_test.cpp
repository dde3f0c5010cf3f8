// The light tree's nodes (src/pack/light_tree.h) bound what is below them: the shader may skip a node
// whose bound says its emitters cannot light a point, so a bound that leaves out an emitter's box,
// power or normal would darken the image (tests/render/light_tree_test.cpp checks the image).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pack/light_tree.h"

namespace fp {
namespace {

constexpr float kPi = 3.14159265358979324f;

// In double: acos of a float dot product is off by 3e-4 next to 1.
float angle(const glm::vec3& a, const glm::vec3& b) {
    glm::dvec3 x = glm::normalize(glm::dvec3(a)), y = glm::normalize(glm::dvec3(b));
    return float(std::acos(glm::clamp(glm::dot(x, y), -1.0, 1.0)));
}

// Whether cone `outer` holds every direction of cone (axis, theta).
bool holds(const LightBounds& outer, const glm::vec3& axis, float theta) {
    return outer.thetaO >= kPi - 1e-6f || angle(outer.axis, axis) + theta <= outer.thetaO + 1e-4f;
}

std::vector<LightTreeEmitter> randomEmitters(int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<LightTreeEmitter> emitters;
    for (int i = 0; i < count; ++i) {
        glm::vec3 c(5.0f * u(rng), 5.0f * u(rng), 5.0f * u(rng));
        LightTreeEmitter e;
        e.p0 = c + 0.3f * glm::vec3(u(rng), u(rng), u(rng));
        e.p1 = c + 0.3f * glm::vec3(u(rng), u(rng), u(rng));
        e.p2 = c + 0.3f * glm::vec3(u(rng), u(rng), u(rng));
        e.power = i % 7 == 3 ? 0.0f : 0.5f + u(rng) * 0.4f;  // some never picked
        emitters.push_back(e);
    }
    return emitters;
}

TEST(LightTree, EveryNodeBoundsItsEmitters) {
    for (int count : {1, 2, 3, 37, 64}) {
        std::vector<LightTreeEmitter> emitters = randomEmitters(count, uint32_t(count));
        LightTree tree = buildLightTree(emitters);
        const size_t leaves = size_t(1) << tree.depth;
        ASSERT_GE(leaves, emitters.size());
        ASSERT_LT(leaves / 2, std::max<size_t>(emitters.size(), 1)) << "no deeper than it needs";
        ASSERT_EQ(tree.nodes.size(), 2 * leaves - 1);
        // Each emitter, from its leaf up to the root: inside every box, its normal in every cone, its
        // power counted in every total.
        double total = 0.0;
        for (size_t e = 0; e < emitters.size(); ++e) {
            const LightTreeEmitter& t = emitters[e];
            total += t.power;
            glm::vec3 normal = glm::normalize(glm::cross(t.p1 - t.p0, t.p2 - t.p0));
            size_t k = leaves - 1 + e;
            EXPECT_EQ(tree.nodes[k].power, t.power) << count << " emitters, leaf " << e;
            while (true) {
                const LightBounds& b = tree.nodes[k];
                if (t.power > 0.0f) {
                    for (const glm::vec3& p : {t.p0, t.p1, t.p2})
                        EXPECT_TRUE(glm::all(glm::lessThanEqual(b.lo, p)) &&
                                    glm::all(glm::lessThanEqual(p, b.hi)))
                            << count << " emitters: emitter " << e << " outside node " << k;
                    EXPECT_TRUE(holds(b, normal, 0.0f))
                        << count << " emitters: emitter " << e << "'s normal outside node " << k << "'s cone";
                }
                if (k == 0) break;
                k = (k - 1) / 2;
            }
        }
        EXPECT_NEAR(tree.nodes[0].power, total, 1e-4 * total) << count << " emitters";
        // Interior nodes: the sum of their children's power, cones that hold their children's.
        for (size_t k = 0; k + 1 < leaves; ++k) {
            const LightBounds &a = tree.nodes[2 * k + 1], &b = tree.nodes[2 * k + 2], &n = tree.nodes[k];
            EXPECT_NEAR(n.power, a.power + b.power, 1e-5f * n.power);
            for (const LightBounds* child : {&a, &b}) {
                if (child->power > 0.0f) {
                    EXPECT_TRUE(holds(n, child->axis, child->thetaO)) << "node " << k;
                }
            }
        }
    }
}

TEST(LightTree, ConeUnionIsTheSmallestThatHoldsBoth) {
    LightBounds up, side, down;
    up.power = side.power = down.power = 1.0f;
    up.axis = {0, 1, 0};
    side.axis = {1, 0, 0};
    down.axis = {0, -1, 0};
    LightBounds a = unionOf(up, side);  // two normals 90 degrees apart: a 45-degree cone between them
    EXPECT_NEAR(a.thetaO, kPi / 4, 1e-5f);
    EXPECT_NEAR(angle(a.axis, glm::vec3(1, 1, 0)), 0.0f, 1e-3f);
    LightBounds b = unionOf(up, down);  // opposite normals: a half-space cone about some perpendicular
    EXPECT_NEAR(b.thetaO, kPi / 2, 1e-5f);
    EXPECT_NEAR(glm::dot(b.axis, glm::vec3(0, 1, 0)), 0.0f, 1e-5f);
    LightBounds wide = up;
    wide.thetaO = 1.0f;
    LightBounds inside = up;
    inside.axis = glm::normalize(glm::vec3(0.2f, 1.0f, 0.0f));
    EXPECT_EQ(unionOf(wide, inside).thetaO, 1.0f) << "a cone that holds the other is the union";
    LightBounds empty;
    EXPECT_EQ(unionOf(empty, side).axis, side.axis) << "an empty node adds nothing";
    EXPECT_EQ(unionOf(a, b).thetaO >= b.thetaO, true);
}

}  // namespace
}  // namespace fp
