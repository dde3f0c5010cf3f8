#pragma once
// A 4-wide BVH collapsed from a binary one: each node holds the boxes and links of up to four
// children, so a ray decides four children per node visit and a traversal needs about half the visits
// of the binary tree's (docs/optimisation-log.md, entry 11). The GPU layout (pack/layout.h) and the native
// reference (native/native_scene.h) both store this tree, so they trace it in the same order (the GPU
// with quantised child boxes, which let a ray into a few more nodes).
#include <cstdint>
#include <vector>

#include "bvh/bvh.h"

namespace fp {

constexpr int kWideBvhWidth = 4;

struct WideBvhNode {
    int childCount = 0;  // 1 to 4; slots from childCount on are empty
    Aabb bounds[kWideBvhWidth];
    // Leaf child (count > 0): primitives primIndex[first .. first + count) of the binary tree.
    // Interior child (count == 0): the wide node `first`.
    uint32_t first[kWideBvhWidth] = {};
    uint32_t count[kWideBvhWidth] = {};
};

struct WideBvh {
    std::vector<WideBvhNode> nodes;  // nodes[0] is the root; depth first, a node before its children
    uint32_t depth = 0;              // deepest node (root = 0)
    // The most entries a stack traversal that pushes a node's other interior children and descends into
    // one (glsl/common/intersect.glsl) can hold: its stack holds only the waiting siblings of the nodes
    // on the path from the root, so the most, over the interior nodes, of the sum over their ancestors of
    // each one's interior children but one. At most 3 a level, fewer where children are leaves.
    uint32_t stackEntries = 0;
};

// Collapses `bvh` (greedily, as Wald, Benthin & Boulos 2008, "Getting rid of packets", build 4-wide trees): a
// node starts from its binary node's two children, and the interior child of largest surface area is
// replaced by its own two children until there are four or no interior child is left. Children keep
// the binary tree's left-to-right order. A binary tree that is one leaf gives a root with that one
// leaf child. An empty Bvh gives an empty WideBvh.
WideBvh collapseToWide(const Bvh& bvh);

}  // namespace fp
