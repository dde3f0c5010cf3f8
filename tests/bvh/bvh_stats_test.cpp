// computeStats on trees small enough to work out by hand.
#include "bvh/bvh_test_util.h"

namespace fp {
namespace {

Aabb box(glm::vec3 lo, glm::vec3 hi) {
    return {lo, hi};
}

// root [0,2]x[0,1]x[0,1]                     area 2 (2 + 1 + 2) = 10
// +- 1: leaf of 2, [0,1]^3                   area 6
// +- 2: interior [1,2]x[0,1]x[0,1]           area 6
//    +- 3: leaf of 1, [1,2]x[0,1]x[0,0.5]    area 2 (1 + 0.5 + 0.5) = 4
//    +- 4: leaf of 3, [1,2]x[0,1]x[0.5,1]    area 4
Bvh handBuiltTree() {
    Bvh bvh;
    bvh.nodes = {
        {box({0, 0, 0}, {2, 1, 1}), 2, 0},    {box({0, 0, 0}, {1, 1, 1}), 0, 2},
        {box({1, 0, 0}, {2, 1, 1}), 4, 0},    {box({1, 0, 0}, {2, 1, 0.5f}), 2, 1},
        {box({1, 0, 0.5f}, {2, 1, 1}), 3, 3},
    };
    bvh.primIndex = {5, 4, 3, 2, 1, 0};
    return bvh;
}

TEST(BvhStats, HandBuiltTree) {
    BvhStats stats = computeStats(handBuiltTree());
    EXPECT_EQ(stats.nodeCount, 5u);
    EXPECT_EQ(stats.leafCount, 3u);
    EXPECT_EQ(stats.maxDepth, 2u);
    EXPECT_EQ(stats.minLeafSize, 1u);
    EXPECT_EQ(stats.maxLeafSize, 3u);
    EXPECT_FLOAT_EQ(stats.meanLeafSize, 2.0f);
    // 1 (root) + 6/10 * 2 + 6/10 * 1 + 4/10 * 1 + 4/10 * 3 = 1 + 1.2 + 0.6 + 0.4 + 1.2
    EXPECT_FLOAT_EQ(stats.sahCost, 4.4f);
}

TEST(BvhStats, CostsWeighInteriorAndLeafTermsSeparately) {
    BvhBuildOptions options;
    options.traversalCost = 2.0f;
    options.intersectCost = 0.5f;
    // 2 + 0.6 * 0.5 * 2 + 0.6 * 2 + 0.4 * 0.5 * 1 + 0.4 * 0.5 * 3 = 2 + 0.6 + 1.2 + 0.2 + 0.6
    EXPECT_FLOAT_EQ(computeStats(handBuiltTree(), options).sahCost, 4.6f);
}

TEST(BvhStats, SingleLeafCostsItsIntersections) {
    Bvh bvh = buildBinnedSah({box({0, 0, 0}, {1, 1, 1})});
    BvhStats stats = computeStats(bvh);
    EXPECT_EQ(stats.nodeCount, 1u);
    EXPECT_EQ(stats.leafCount, 1u);
    EXPECT_EQ(stats.maxDepth, 0u);
    EXPECT_EQ(stats.minLeafSize, 1u);
    EXPECT_EQ(stats.maxLeafSize, 1u);
    EXPECT_FLOAT_EQ(stats.sahCost, 1.0f);
}

TEST(BvhStats, EmptyBvhIsAllZeros) {
    BvhStats stats = computeStats(Bvh{});
    EXPECT_EQ(stats.nodeCount, 0u);
    EXPECT_EQ(stats.leafCount, 0u);
    EXPECT_EQ(stats.maxDepth, 0u);
    EXPECT_EQ(stats.minLeafSize, 0u);
    EXPECT_EQ(stats.maxLeafSize, 0u);
    EXPECT_EQ(stats.meanLeafSize, 0.0f);
    EXPECT_EQ(stats.sahCost, 0.0f);
}

TEST(BvhStats, ZeroAreaRootCountsEveryNodeFully) {
    // Five points on a line: root area 0, so each node weighs 1 (documented in bvh.h).
    AabbArray points;
    for (int i = 0; i < 5; ++i) points.push_back(box({float(i), 0, 0}, {float(i), 0, 0}));
    BvhBuildOptions options;
    options.maxLeafSize = 1;
    Bvh bvh = buildMedianSplit(points, options);
    BvhStats stats = computeStats(bvh, options);
    EXPECT_EQ(stats.nodeCount, 9u);
    EXPECT_FLOAT_EQ(stats.sahCost, 4.0f * options.traversalCost + 5.0f * options.intersectCost);
}

TEST(BvhStats, AgreesWithTheStructureOfBuiltTrees) {
    for (const test::NamedMesh& m : test::testMeshes()) {
        if (m.mesh.empty()) continue;
        const AabbArray bounds = triangleBounds(m.mesh);
        Bvh bvh = buildBinnedSah(bounds);
        BvhStats stats = computeStats(bvh);
        SCOPED_TRACE(m.name);
        EXPECT_EQ(stats.nodeCount, bvh.nodes.size());
        EXPECT_EQ(stats.leafCount, (bvh.nodes.size() + 1) / 2);
        EXPECT_FLOAT_EQ(stats.meanLeafSize, float(m.mesh.size()) / float(stats.leafCount));
        EXPECT_GE(stats.minLeafSize, 1u);
        EXPECT_LE(stats.maxLeafSize, 4u);
        // Every primitive's leaf is reached through at least the root, so the cost is at least 1 + ...
        // and at most one visit per node plus one test per primitive.
        EXPECT_GE(stats.sahCost, stats.leafCount > 1 ? 1.0f : 0.0f);
        EXPECT_LE(stats.sahCost, float(stats.nodeCount - stats.leafCount) + float(m.mesh.size()));
    }
}

}  // namespace
}  // namespace fp
