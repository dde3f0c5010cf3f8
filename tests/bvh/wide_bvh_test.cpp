// The 4-wide collapse (bvh/wide_bvh.h): every leaf of the binary tree reached exactly once, boxes that
// are the binary tree's own, depth-first order, and nodes as full as the binary tree allows.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "bvh/wide_bvh.h"
#include "bvh_test_util.h"

namespace fp {
namespace {

struct Walk {
    const WideBvh& wide;
    std::vector<int> primVisits;
    uint32_t nodesSeen = 0, maxDepth = 0;

    void node(uint32_t index, uint32_t depth) {
        ASSERT_LT(index, wide.nodes.size());
        ++nodesSeen;
        maxDepth = std::max(maxDepth, depth);
        const WideBvhNode& n = wide.nodes[index];
        ASSERT_GE(n.childCount, 1);
        ASSERT_LE(n.childCount, kWideBvhWidth);
        bool anyInterior = false;
        for (int i = 0; i < n.childCount; ++i) {
            if (n.count[i] > 0) {
                for (uint32_t p = n.first[i]; p < n.first[i] + n.count[i]; ++p) {
                    ASSERT_LT(p, primVisits.size());
                    ++primVisits[p];
                }
                continue;
            }
            anyInterior = true;
            ASSERT_GT(n.first[i], index) << "children come after their parent";
            const WideBvhNode& c = wide.nodes[n.first[i]];
            for (int k = 0; k < c.childCount; ++k) EXPECT_TRUE(test::contains(n.bounds[i], c.bounds[k]));
            node(n.first[i], depth + 1);
        }
        // A node is only less than full when nothing is left to open: all its children are leaves.
        if (n.childCount < kWideBvhWidth && index != 0) {
            EXPECT_FALSE(anyInterior) << "node " << index << " has " << n.childCount << " children";
        }
    }
};

TEST(WideBvh, CollapseKeepsEveryLeafOnceAndFillsNodes) {
    for (const test::NamedMesh& m : test::testMeshes()) {
        const AabbArray bounds = triangleBounds(m.mesh);
        Bvh bvh = buildBinnedSah(bounds);
        WideBvh wide = collapseToWide(bvh);
        if (bounds.empty()) {
            EXPECT_TRUE(wide.nodes.empty());
            continue;
        }
        Walk walk{wide, std::vector<int>(bounds.size(), 0)};
        walk.node(0, 0);
        EXPECT_EQ(walk.nodesSeen, wide.nodes.size()) << m.name;
        EXPECT_EQ(walk.maxDepth, wide.depth) << m.name;
        for (int v : walk.primVisits) EXPECT_EQ(v, 1) << m.name;
        // The root holds the binary root's children (or, for a one-leaf tree, that leaf), so its boxes
        // together cover the scene.
        Aabb root;
        for (int i = 0; i < wide.nodes[0].childCount; ++i) root.grow(wide.nodes[0].bounds[i]);
        EXPECT_TRUE(test::sameBox(root, bvh.nodes[0].bounds)) << m.name;
        // A wide node of k children stands for k - 1 binary interior nodes, and each binary interior
        // node is in exactly one wide node.
        size_t binaryInterior = 0, absorbed = 0;
        for (const BvhNode& n : bvh.nodes) binaryInterior += n.isLeaf() ? 0 : 1;
        for (const WideBvhNode& n : wide.nodes) absorbed += size_t(n.childCount - 1);
        EXPECT_EQ(absorbed, binaryInterior) << m.name;
    }
}

// The most entries the stack of glsl/common/intersect.glsl's traversal holds when every box is hit: at each
// node the interior children in a random order, the first descended into and the others pushed, the
// leaves tested in place; each pop visits the top entry.
uint32_t deepestStackOfAFullTraversal(const WideBvh& wide, std::mt19937& rng) {
    std::vector<uint32_t> stack;
    uint32_t node = 0, deepest = 0;
    while (true) {
        const WideBvhNode& n = wide.nodes[node];
        std::vector<uint32_t> interior;
        for (int i = 0; i < n.childCount; ++i)
            if (n.count[i] == 0) interior.push_back(n.first[i]);
        std::shuffle(interior.begin(), interior.end(), rng);
        if (interior.empty()) {
            if (stack.empty()) return deepest;
            node = stack.back();
            stack.pop_back();
            continue;
        }
        for (size_t i = 1; i < interior.size(); ++i) stack.push_back(interior[i]);
        deepest = std::max(deepest, uint32_t(stack.size()));
        node = interior[0];
    }
}

TEST(WideBvh, StackEntriesBoundEveryTraversalAndAreReachedByOne) {
    // stackEntries sizes the shader's stack (pack.h): a traversal that needs more would lose subtrees,
    // so no order of visits may exceed it; and it is no larger than some order needs, since every entry
    // costs the shader a shift at every node visit.
    std::mt19937 rng(7);
    for (const test::NamedMesh& m : test::testMeshes()) {
        const AabbArray bounds = triangleBounds(m.mesh);
        if (bounds.empty()) continue;
        WideBvh wide = collapseToWide(buildBinnedSah(bounds));
        uint32_t deepest = 0;
        for (int k = 0; k < 20; ++k) {
            uint32_t d = deepestStackOfAFullTraversal(wide, rng);
            EXPECT_LE(d, wide.stackEntries) << m.name;
            deepest = std::max(deepest, d);
        }
        EXPECT_LE(wide.stackEntries, 3 * wide.depth) << m.name;
        // Reached: the path that descends, at every level, into the child whose subtree needs the most.
        std::vector<uint32_t> need(wide.nodes.size(), 0);  // the most entries below a node, its own included
        for (size_t i = wide.nodes.size(); i-- > 0;) {
            const WideBvhNode& n = wide.nodes[i];
            uint32_t interior = 0, most = 0;
            for (int c = 0; c < n.childCount; ++c)
                if (n.count[c] == 0) {
                    ++interior;
                    most = std::max(most, need[n.first[c]]);
                }
            need[i] = interior == 0 ? 0 : interior - 1 + most;
        }
        EXPECT_EQ(need[0], wide.stackEntries) << m.name;
        if (wide.stackEntries > 0) {
            EXPECT_GE(deepest, 1u) << m.name;
        }
    }
}

TEST(WideBvh, OpensTheLargestInteriorChildFirst) {
    // Binary tree: root -> (A, B), A -> (a1, a2), B -> (b1, b2), all four grandchildren interior; A's box
    // is larger, so A is opened first, then the larger of B and A's children.
    AabbArray bounds;
    auto cube = [](glm::vec3 c, float r) { return Aabb{c - glm::vec3(r), c + glm::vec3(r)}; };
    for (int i = 0; i < 64; ++i) bounds.push_back(cube(glm::vec3(float(i % 8), float(i / 8), 0.0f), 0.3f));
    Bvh bvh = buildBinnedSah(bounds);
    WideBvh wide = collapseToWide(bvh);
    ASSERT_FALSE(wide.nodes.empty());
    EXPECT_EQ(wide.nodes[0].childCount, kWideBvhWidth);
    // Brute force the rule at the root: the children must be a frontier of the binary tree reached by
    // opening, each time, the interior node of largest area.
    std::vector<uint32_t> frontier = {1, bvh.nodes[0].first};
    while (frontier.size() < size_t(kWideBvhWidth)) {
        auto widest = std::max_element(frontier.begin(), frontier.end(), [&](uint32_t a, uint32_t b) {
            float aa = bvh.nodes[a].isLeaf() ? -1.0f : bvh.nodes[a].bounds.area();
            float bb = bvh.nodes[b].isLeaf() ? -1.0f : bvh.nodes[b].bounds.area();
            return aa < bb;
        });
        ASSERT_FALSE(bvh.nodes[*widest].isLeaf());
        uint32_t opened = *widest;
        widest = frontier.erase(widest);
        frontier.insert(widest, {opened + 1, bvh.nodes[opened].first});
    }
    for (int i = 0; i < kWideBvhWidth; ++i)
        EXPECT_TRUE(test::sameBox(wide.nodes[0].bounds[i], bvh.nodes[frontier[size_t(i)]].bounds)) << i;
}

}  // namespace
}  // namespace fp
