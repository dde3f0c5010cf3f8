#pragma once
// A binary bounding volume hierarchy over primitives given only by their bounds, flattened
// depth-first into one array: an interior node's left child is the next node in the array.
#include <cstdint>
#include <vector>

#include "core/aabb.h"

namespace fp {

struct BvhNode {
    Aabb bounds;
    // Leaf (count > 0): primitives primIndex[first .. first + count).
    // Interior (count == 0): left child at (this index + 1), right child at `first`.
    uint32_t first = 0;
    uint32_t count = 0;
    bool isLeaf() const { return count > 0; }
};

struct Bvh {
    std::vector<BvhNode> nodes;       // nodes[0] is the root
    std::vector<uint32_t> primIndex;  // leaf order -> original primitive index
};

struct BvhBuildOptions {
    int binCount = 16;     // SAH candidate planes per axis in the binned builder
    int maxLeafSize = 4;   // a node with more primitives is always split
    float traversalCost = 1.0f;  // SAH cost of one node visit, relative to...
    float intersectCost = 1.0f;  // ...one primitive test
};

// Binned SAH (Wald 2007, "On fast construction of SAH-based bounding volume hierarchies").
Bvh buildBinnedSah(const std::vector<Aabb>& primBounds, const BvhBuildOptions& options = {});
// Object median split along the longest centroid axis: the baseline the SAH builder must beat.
Bvh buildMedianSplit(const std::vector<Aabb>& primBounds, const BvhBuildOptions& options = {});

struct BvhStats {
    uint32_t nodeCount = 0, leafCount = 0, maxDepth = 0;
    uint32_t minLeafSize = 0, maxLeafSize = 0;
    float meanLeafSize = 0.0f;
    // Expected cost of a random ray (MacDonald & Booth 1990): sum over nodes of
    // area(node)/area(root) * (traversalCost for interior, intersectCost * count for leaves).
    float sahCost = 0.0f;
};
BvhStats computeStats(const Bvh& bvh, const BvhBuildOptions& options = {});

}  // namespace fp
