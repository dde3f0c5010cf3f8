// Structure of the trees both builders produce, and the binned SAH builder's split decisions.
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "bvh/bvh_test_util.h"

namespace fp {
namespace {

using test::builders;
using test::checkStructure;

TEST(BvhBuild, StructureHoldsOnEveryMeshBuilderAndLeafSize) {
    for (const test::NamedMesh& m : test::testMeshes()) {
        const AabbArray bounds = triangleBounds(m.mesh);
        for (const test::NamedBuilder& b : builders())
            for (int maxLeafSize : {1, 2, 4, 8})
                for (int binCount : {2, 16, 32}) {
                    SCOPED_TRACE(m.name + " " + b.name + " maxLeafSize=" + std::to_string(maxLeafSize) +
                                 " binCount=" + std::to_string(binCount));
                    BvhBuildOptions options;
                    options.maxLeafSize = maxLeafSize;
                    options.binCount = binCount;
                    EXPECT_TRUE(checkStructure(b.build(bounds, options), bounds, options));
                }
    }
}

TEST(BvhBuild, EmptyInputGivesEmptyBvh) {
    for (const test::NamedBuilder& b : builders()) {
        Bvh bvh = b.build({}, {});
        EXPECT_TRUE(bvh.nodes.empty()) << b.name;
        EXPECT_TRUE(bvh.primIndex.empty()) << b.name;
    }
}

TEST(BvhBuild, OnePrimitiveIsOneLeaf) {
    const Aabb box{{1.0f, 2.0f, 3.0f}, {4.0f, 5.0f, 6.0f}};
    for (const test::NamedBuilder& b : builders()) {
        Bvh bvh = b.build({box}, {});
        ASSERT_EQ(bvh.nodes.size(), 1u) << b.name;
        EXPECT_EQ(bvh.nodes[0].count, 1u);
        EXPECT_EQ(bvh.nodes[0].first, 0u);
        EXPECT_TRUE(test::sameBox(bvh.nodes[0].bounds, box));
        EXPECT_EQ(bvh.primIndex, HugePageVector<uint32_t>{0});
    }
}

TEST(BvhBuild, TwoDistantPrimitivesAreSplitTwoOverlappingOnesShareALeaf) {
    const Aabb a{glm::vec3(0.0f), glm::vec3(1.0f)}, far{glm::vec3(100.0f), glm::vec3(101.0f)};
    // Split: 1 + (6 + 6) / area(root) ~ 1.0002 < leaf cost 2.
    Bvh split = buildBinnedSah({far, a});
    ASSERT_EQ(split.nodes.size(), 3u);
    EXPECT_EQ(split.nodes[0].count, 0u);
    EXPECT_EQ(split.nodes[0].first, 2u);
    EXPECT_EQ(split.primIndex, (HugePageVector<uint32_t>{1, 0}));  // the lower centroid goes left
    EXPECT_TRUE(test::sameBox(split.nodes[1].bounds, a));
    EXPECT_TRUE(test::sameBox(split.nodes[2].bounds, far));
    // Overlapping boxes with distinct centroids: split costs 1 + (6 + 6) / 7.26 ~ 2.65 > leaf cost 2.
    const Aabb b{glm::vec3(0.1f), glm::vec3(1.1f)};
    Bvh leaf = buildBinnedSah({a, b});
    ASSERT_EQ(leaf.nodes.size(), 1u);
    EXPECT_EQ(leaf.nodes[0].count, 2u);
    // The median builder splits only above maxLeafSize.
    BvhBuildOptions one;
    one.maxLeafSize = 1;
    EXPECT_EQ(buildMedianSplit({a, b}, one).nodes.size(), 3u);
    EXPECT_EQ(buildMedianSplit({a, b}).nodes.size(), 1u);
}

TEST(BvhBuild, CoincidentCentroidsAreSplitInHalves) {
    // 1000 identical boxes: no plane separates them, so each oversized node halves its range and the
    // depth is exactly ceil(log2(1000 / 4)) = 8.
    const AabbArray bounds = triangleBounds(test::identicalTriangles(1000));
    for (const test::NamedBuilder& b : builders()) {
        SCOPED_TRACE(b.name);
        BvhBuildOptions options;
        Bvh bvh = b.build(bounds, options);
        ASSERT_TRUE(checkStructure(bvh, bounds, options));
        BvhStats stats = computeStats(bvh, options);
        EXPECT_EQ(stats.maxDepth, 8u);
        EXPECT_EQ(stats.minLeafSize, 3u);  // 1000 -> ... -> 125 -> 62|63 -> ... -> 7|8 -> 3|4
        EXPECT_EQ(stats.maxLeafSize, 4u);
    }
}

TEST(BvhBuild, SmallNodeBecomesLeafWhenTraversalIsExpensive) {
    const AabbArray bounds = triangleBounds(test::randomSoup(8, 5));
    BvhBuildOptions options;
    options.maxLeafSize = 8;
    options.traversalCost = 100.0f;  // any split costs > 100 > 8 intersections
    Bvh bvh = buildBinnedSah(bounds, options);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_EQ(bvh.nodes[0].count, 8u);
    // With cheap traversal the same primitives are split: the SAH decides, not maxLeafSize.
    options.traversalCost = 0.01f;
    EXPECT_GT(buildBinnedSah(bounds, options).nodes.size(), 1u);
}

TEST(BvhBuild, OversizedNodeIsSplitEvenWhenALeafIsCheaper) {
    const AabbArray bounds = triangleBounds(test::randomSoup(9, 6));
    BvhBuildOptions options;
    options.maxLeafSize = 8;
    options.traversalCost = 100.0f;
    Bvh bvh = buildBinnedSah(bounds, options);
    EXPECT_TRUE(checkStructure(bvh, bounds, options));
    EXPECT_EQ(bvh.nodes.size(), 3u);  // the root must split; its children then stay leaves
}

TEST(BvhBuild, SahSeparatesADistantSmallClusterAtTheRoot) {
    // 100 primitives near the origin and 4 far away: the median would cut the big cluster, the SAH
    // must cut between the clusters.
    test::Mesh mesh = test::randomSoup(100, 7, 0.1f);
    for (TriangleVerts& t : test::randomSoup(4, 8, 0.1f)) {
        t.p0 += glm::vec3(1000.0f);
        t.p1 += glm::vec3(1000.0f);
        t.p2 += glm::vec3(1000.0f);
        mesh.push_back(t);
    }
    const AabbArray bounds = triangleBounds(mesh);
    Bvh bvh = buildBinnedSah(bounds);
    ASSERT_TRUE(checkStructure(bvh, bounds, {}));
    const BvhNode& root = bvh.nodes[0];
    ASSERT_FALSE(root.isLeaf());
    // The left subtree is nodes [1, root.first) and its primitives come first in primIndex.
    uint32_t leftPrims = 0;
    for (uint32_t i = 1; i < root.first; ++i) leftPrims += bvh.nodes[i].count;
    EXPECT_EQ(leftPrims, 100u);
    std::set<uint32_t> left(bvh.primIndex.begin(), bvh.primIndex.begin() + leftPrims);
    EXPECT_EQ(*left.rbegin(), 99u);  // exactly the primitives 0..99

    Bvh median = buildMedianSplit(bounds);
    EXPECT_EQ(median.nodes[0].first - 1, median.nodes.size() - median.nodes[0].first);  // balanced halves
}

TEST(BvhBuild, OnePlaneSeparatesLargePrimitivesWhoseCentroidsShareABinWithSmallOnes) {
    // 2000 small boxes with centroids spread over x in [0, 1], and two huge slabs with centroids at
    // x = 1.01: with 16 bins over [0, 1.01] the last bin also holds about 30 small boxes, so no bin
    // boundary separates the slabs from them. The exact plane at a slab's centroid does
    // (large_prim_planes.h), and the sweep agrees: at the root, one child is exactly the two slabs.
    std::mt19937 rng(41);
    AabbArray bounds;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 c = test::uniformIn(rng, Aabb{{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}});
        bounds.push_back({c - glm::vec3(0.005f), c + glm::vec3(0.005f)});
    }
    bounds.push_back({{1.0f, -5.0f, -5.0f}, {1.02f, 5.0f, 5.0f}});
    bounds.push_back({{1.0f, -5.0f, -4.0f}, {1.02f, 5.0f, 6.0f}});
    for (const test::NamedBuilder& b : {builders()[0], builders()[1]}) {  // binned, sweep
        Bvh bvh = b.build(bounds, {});
        ASSERT_TRUE(checkStructure(bvh, bounds, {})) << b.name;
        const BvhNode& root = bvh.nodes[0];
        ASSERT_FALSE(root.isLeaf()) << b.name;
        const BvhNode& right = bvh.nodes[root.first];
        ASSERT_TRUE(right.isLeaf()) << b.name;
        ASSERT_EQ(right.count, 2u) << b.name;
        EXPECT_EQ(
            std::set<uint32_t>(bvh.primIndex.begin() + right.first, bvh.primIndex.begin() + right.first + 2),
            (std::set<uint32_t>{2000, 2001}))
            << b.name;
    }
}

TEST(BvhBuild, SameInputGivesSameTree) {
    const AabbArray bounds = triangleBounds(test::randomSoup(5000, 9));
    for (const test::NamedBuilder& b : builders()) {
        Bvh first = b.build(bounds, {}), second = b.build(bounds, {});
        EXPECT_EQ(first.primIndex, second.primIndex) << b.name;
        ASSERT_EQ(first.nodes.size(), second.nodes.size()) << b.name;
        for (size_t i = 0; i < first.nodes.size(); ++i) {
            EXPECT_TRUE(test::sameBox(first.nodes[i].bounds, second.nodes[i].bounds));
            EXPECT_EQ(first.nodes[i].first, second.nodes[i].first);
            EXPECT_EQ(first.nodes[i].count, second.nodes[i].count);
        }
    }
}

TEST(BvhBuild, WidelySpreadCentroidsArePeeledOneLevelAtATime) {
    // Centroids at 32^i: relative to each node's centroid range, all but the top one fall into the
    // first of 16 bins, so the only plane peels off one primitive per level: depth n - 1, with areas
    // up to 2^116 that must not overflow.
    AabbArray bounds;
    for (int i = 0; i < 24; ++i) {
        const float x = std::ldexp(1.0f, 5 * i);
        bounds.push_back({glm::vec3(x, 0.0f, 0.0f), glm::vec3(1.5f * x, 1.0f, 1.0f)});
    }
    BvhBuildOptions options;
    options.maxLeafSize = 1;
    Bvh bvh = buildBinnedSah(bounds, options);
    EXPECT_TRUE(checkStructure(bvh, bounds, options));
    EXPECT_EQ(computeStats(bvh, options).maxDepth, 23u);
    // Each right child is the largest primitive of its node: the peeled order is 23, 22, ..., 1, 0
    // from the root's right child down.
    uint32_t node = 0;
    for (uint32_t expected = 23; expected > 0; --expected) {
        ASSERT_FALSE(bvh.nodes[node].isLeaf());
        const BvhNode& right = bvh.nodes[bvh.nodes[node].first];
        ASSERT_TRUE(right.isLeaf());
        EXPECT_EQ(bvh.primIndex[right.first], expected);
        ++node;  // the left child, which holds the rest
    }
}

TEST(BvhBuild, InvalidOptionsThrow) {
    const AabbArray bounds = triangleBounds(test::randomSoup(10, 10));
    for (const test::NamedBuilder& b : builders()) {
        BvhBuildOptions bins;
        bins.binCount = 1;
        EXPECT_THROW(b.build(bounds, bins), std::invalid_argument) << b.name;
        BvhBuildOptions leaf;
        leaf.maxLeafSize = 0;
        EXPECT_THROW(b.build(bounds, leaf), std::invalid_argument) << b.name;
    }
}

}  // namespace
}  // namespace fp
