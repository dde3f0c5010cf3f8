// Quantised wide BVH nodes (src/pack/quantised_node.h): every child's quantised box contains its exact
// box, is at most the margin plus one grid step larger per side, and empty slots are inverted boxes
// with link 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/error.h"
#include "pack/layout.h"
#include "pack/quantised_node.h"

namespace fp {
namespace {

// A node of `children` random boxes around `centre`, `size` across.
WideBvhNode randomNode(std::mt19937& rng, int children, glm::vec3 centre, float size) {
    std::uniform_real_distribution<float> u(-0.5f, 0.5f);
    WideBvhNode n;
    n.childCount = children;
    for (int i = 0; i < children; ++i) {
        glm::vec3 a = centre + size * glm::vec3(u(rng), u(rng), u(rng));
        glm::vec3 b = centre + size * glm::vec3(u(rng), u(rng), u(rng));
        n.bounds[i].lo = glm::min(a, b);
        n.bounds[i].hi = glm::max(a, b);
        if (i == 1) n.bounds[i].hi.y = n.bounds[i].lo.y;  // a flat box, as a wall's
        n.first[i] = uint32_t(10 * i + 1);
        n.count[i] = uint32_t(i % 2 == 0 ? 0 : 3);
    }
    return n;
}

void expectTightAndConservative(const WideBvhNode& n) {
    layout::QuantisedNode q = layout::quantiseNode(n);
    const glm::dvec3 step = layout::gridStep(q);
    Aabb node;
    for (int i = 0; i < n.childCount; ++i) node.grow(n.bounds[i]);
    double magnitude = 0.0, extent = 0.0;
    for (int a = 0; a < 3; ++a) {
        magnitude = std::max({magnitude, std::abs(double(node.lo[a])), std::abs(double(node.hi[a]))});
        extent = std::max(extent, double(node.hi[a]) - double(node.lo[a]));
    }
    const double margin = layout::kQuantiseMargin * (magnitude + extent);
    for (int a = 0; a < 3; ++a) {
        // The smallest power-of-two step whose 255 steps span the widened node, or the smallest allowed.
        double span = double(node.hi[a]) - double(node.lo[a]) + 2.0 * margin;
        EXPECT_GE(255.0 * step[a], span);
        if (step[a] > std::ldexp(1.0, layout::kMinScaleExponent)) {
            EXPECT_LT(255.0 * step[a], 2.0 * span);
        }
    }
    for (int i = 0; i < 4; ++i) {
        layout::QuantisedBox b = layout::decodeChildBox(q, i);
        uint32_t link = q[layout::kNodeLinkTexel][i];
        if (i >= n.childCount) {
            EXPECT_EQ(link, 0u) << "slot " << i;
            for (int a = 0; a < 3; ++a) EXPECT_GT(b.lo[a], b.hi[a]) << "slot " << i << " is inverted";
            continue;
        }
        layout::ChildLink c = layout::decodeChild(link);
        EXPECT_EQ(c.first, n.first[i]);
        EXPECT_EQ(c.count, n.count[i]);
        for (int a = 0; a < 3; ++a) {
            const double lo = n.bounds[i].lo[a], hi = n.bounds[i].hi[a];
            // Contains the exact box with the margin (which covers the shader's rounding) ...
            EXPECT_LE(b.lo[a], lo - margin) << "slot " << i << " axis " << a;
            EXPECT_GE(b.hi[a], hi + margin) << "slot " << i << " axis " << a;
            // ... and is at most one grid step larger than that per side.
            EXPECT_GT(b.lo[a], lo - margin - step[a]) << "slot " << i << " axis " << a;
            EXPECT_LT(b.hi[a], hi + margin + step[a]) << "slot " << i << " axis " << a;
        }
    }
}

TEST(QuantisedNode, BoxesContainTheExactOnesAndAreAtMostOneStepLarger) {
    std::mt19937 rng(11);
    const glm::vec3 centres[] = {glm::vec3(0.0f), glm::vec3(1e4f, -3e3f, 7.0f),
                                 glm::vec3(-0.01f, 0.02f, 0.0f)};
    for (const glm::vec3& c : centres)
        for (float size : {1e-4f, 0.3f, 1.0f, 555.0f, 1e5f})
            for (int children = 1; children <= 4; ++children)
                for (int k = 0; k < 20; ++k) expectTightAndConservative(randomNode(rng, children, c, size));
}

TEST(QuantisedNode, TheGridIsAlignedToKeepAFlatChildsSlackOutsideTheNode) {
    // The Cornell box's root: a room and the leaf of the ceiling and the light 0.1 below it, at the
    // top of the node. On the default grid (steps of 4 from y = 0) that leaf would reach down to 548,
    // past the light, and shadow rays would enter it; aligned, its slack lies above the node.
    WideBvhNode n;
    n.childCount = 2;
    n.bounds[0].lo = glm::vec3(0.0f);
    n.bounds[0].hi = glm::vec3(556.0f, 548.8f, 559.2f);
    n.bounds[1].lo = glm::vec3(0.0f, 548.7f, 0.0f);
    n.bounds[1].hi = glm::vec3(556.0f, 548.8f, 559.2f);
    n.first[0] = 1;
    n.first[1] = 2;
    n.count[0] = n.count[1] = 2;
    expectTightAndConservative(n);
    layout::QuantisedNode q = layout::quantiseNode(n);
    ASSERT_EQ(layout::gridStep(q).y, 4.0);
    EXPECT_GT(layout::decodeChildBox(q, 1).lo.y, 548.69);
}

TEST(QuantisedNode, DegenerateNodesStayFinite) {
    // Every child the same point, at the origin and away from it: a grid of the smallest step.
    for (glm::vec3 p : {glm::vec3(0.0f), glm::vec3(2.0f, -1.0f, 0.5f)}) {
        WideBvhNode n;
        n.childCount = 2;
        n.bounds[0].lo = n.bounds[0].hi = n.bounds[1].lo = n.bounds[1].hi = p;
        n.first[0] = n.first[1] = 1;
        n.count[0] = n.count[1] = 1;
        expectTightAndConservative(n);
    }
}

TEST(QuantisedNode, RefusesWhatItCannotHold) {
    WideBvhNode n;
    n.childCount = 1;
    n.bounds[0].lo = glm::vec3(-1e30f);
    n.bounds[0].hi = glm::vec3(1e30f);
    n.count[0] = 1;
    EXPECT_THROW(layout::quantiseNode(n), Error);
    n.bounds[0].hi = glm::vec3(INFINITY);
    EXPECT_THROW(layout::quantiseNode(n), Error);
}

}  // namespace
}  // namespace fp
