// Tree statistics, including the SAH cost used to compare builders.
#include <algorithm>
#include <limits>

#include "bvh/bvh.h"

namespace fp {

BvhStats computeStats(const Bvh& bvh, const BvhBuildOptions& options) {
    BvhStats stats;
    if (bvh.nodes.empty()) return stats;

    const float rootArea = bvh.nodes[0].bounds.area();
    stats.minLeafSize = std::numeric_limits<uint32_t>::max();
    uint64_t primsInLeaves = 0;
    double cost = 0.0;  // summed in double: millions of small terms

    struct Entry {
        uint32_t node, depth;
    };
    std::vector<Entry> stack{{0, 0}};
    while (!stack.empty()) {
        const Entry e = stack.back();
        stack.pop_back();
        const BvhNode& node = bvh.nodes[e.node];
        ++stats.nodeCount;
        stats.maxDepth = std::max(stats.maxDepth, e.depth);
        // MacDonald & Booth 1990: a random ray that hits the root hits a node with probability
        // area(node) / area(root).
        const double ratio = rootArea > 0.0f ? double(node.bounds.area()) / rootArea : 1.0;
        if (node.isLeaf()) {
            ++stats.leafCount;
            stats.minLeafSize = std::min(stats.minLeafSize, node.count);
            stats.maxLeafSize = std::max(stats.maxLeafSize, node.count);
            primsInLeaves += node.count;
            cost += ratio * options.intersectCost * node.count;
        } else {
            cost += ratio * options.traversalCost;
            stack.push_back({node.first, e.depth + 1});
            stack.push_back({e.node + 1, e.depth + 1});
        }
    }
    stats.meanLeafSize = float(double(primsInLeaves) / stats.leafCount);
    stats.sahCost = float(cost);
    return stats;
}

}  // namespace fp
