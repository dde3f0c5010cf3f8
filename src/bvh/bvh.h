#pragma once
// A binary bounding volume hierarchy over primitives given only by their bounds, flattened
// depth-first into one array: an interior node's left child is the next node in the array.
#include <cstdint>
#include <vector>

#include "core/aabb.h"
#include "core/huge_page_allocator.h"

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
    // Large arrays, written right after allocation: see core/huge_page_allocator.h for why.
    HugePageVector<BvhNode> nodes;       // nodes[0] is the root
    HugePageVector<uint32_t> primIndex;  // leaf order -> original primitive index
};

struct BvhBuildOptions {
    int binCount = 16;           // SAH candidate planes per axis in the binned builder
    int maxLeafSize = 4;         // a node with more primitives is always split
    float traversalCost = 1.0f;  // SAH cost of one node visit, relative to...
    float intersectCost = 1.0f;  // ...one primitive test
    // Threads the binned builder may use, the caller's included; 0: std::thread::hardware_concurrency().
    // The tree does not depend on it.
    int threadCount = 0;
};

// The builders share these rules:
// - primBounds must be non-empty, finite boxes (one per primitive); nodes store exact unions of them.
// - No primitives gives an empty Bvh (no nodes, no primIndex); one primitive gives a single leaf.
// - Every leaf holds 1..maxLeafSize primitives, without exception: a larger node whose centroids all
//   coincide (no plane separates them) is split into the two halves of its index range.
// - The output depends only on the input and options, never on threadCount (same input, same tree).
// - binCount < 2, maxLeafSize < 1 or threadCount < 0 throws std::invalid_argument.

// Binned SAH (Wald 2007, "On fast construction of SAH-based bounding volume hierarchies"): each node
// is split at the lowest-cost of the binCount - 1 planes per axis between equal-width bins over its
// centroid bounds, or made a leaf when that is strictly cheaper and it holds at most maxLeafSize. Near
// the top of the tree, planes at the centroids of the node's few largest primitives are also evaluated
// exactly, so that huge triangles among many small ones (walls around an object) are split off with one
// plane, as a full sweep would (src/bvh/large_prim_planes.h).
Bvh buildBinnedSah(const AabbArray& primBounds, const BvhBuildOptions& options = {});
// The threads buildBinnedSah may use with these options (threadCount, or the hardware's if 0).
int buildThreadCount(const BvhBuildOptions& options);
// Full-sweep SAH: the quality reference for the binned builder (O(n log n) per level; not for rendering).
// Each node is split at the lowest-cost of all planes between consecutive distinct centroids along each
// axis (centroids sorted per axis), with the binned builder's costs and leaf rule; binCount is not used.
Bvh buildSweepSah(const AabbArray& primBounds, const BvhBuildOptions& options = {});
// Object median split along the longest centroid axis: the baseline the SAH builder must beat.
// Nodes with at most maxLeafSize primitives become leaves; binCount and the costs are not used.
Bvh buildMedianSplit(const AabbArray& primBounds, const BvhBuildOptions& options = {});

struct BvhStats {
    uint32_t nodeCount = 0, leafCount = 0, maxDepth = 0;
    uint32_t minLeafSize = 0, maxLeafSize = 0;
    float meanLeafSize = 0.0f;
    // Expected cost of a random ray (MacDonald & Booth 1990): sum over nodes of
    // area(node)/area(root) * (traversalCost for interior, intersectCost * count for leaves).
    // A root of zero area (all primitives on one line or point) counts every node with ratio 1.
    float sahCost = 0.0f;
};
// All zeros for an empty Bvh.
BvhStats computeStats(const Bvh& bvh, const BvhBuildOptions& options = {});

}  // namespace fp
