#include "bvh/wide_bvh.h"

#include <algorithm>

namespace fp {

namespace {

struct Collapser {
    const Bvh& bvh;
    WideBvh& out;

    // Appends the wide node for binary interior node `binary` and, depth first, its descendants;
    // `waiting`: the stack entries its ancestors can leave behind (WideBvh::stackEntries).
    uint32_t node(uint32_t binary, uint32_t depth, uint32_t waiting) {
        out.depth = std::max(out.depth, depth);
        out.stackEntries = std::max(out.stackEntries, waiting);
        uint32_t index = uint32_t(out.nodes.size());
        out.nodes.emplace_back();
        const BvhNode& b = bvh.nodes[binary];
        uint32_t children[kWideBvhWidth] = {binary + 1, b.first};  // binary node indices
        int count = 2;
        while (count < kWideBvhWidth) {
            int widest = -1;
            float widestArea = -1.0f;
            for (int i = 0; i < count; ++i) {
                const BvhNode& c = bvh.nodes[children[i]];
                if (!c.isLeaf() && c.bounds.area() > widestArea) {
                    widest = i;
                    widestArea = c.bounds.area();
                }
            }
            if (widest < 0) break;
            uint32_t expanded = children[widest];
            std::copy_backward(children + widest + 1, children + count, children + count + 1);
            children[widest] = expanded + 1;
            children[widest + 1] = bvh.nodes[expanded].first;
            ++count;
        }
        WideBvhNode wide;
        wide.childCount = count;
        uint32_t interior = 0;
        for (int i = 0; i < count; ++i) interior += bvh.nodes[children[i]].isLeaf() ? 0 : 1;
        for (int i = 0; i < count; ++i) {
            const BvhNode& c = bvh.nodes[children[i]];
            wide.bounds[i] = c.bounds;
            wide.count[i] = c.count;
            wide.first[i] = c.isLeaf() ? c.first : node(children[i], depth + 1, waiting + interior - 1);
        }
        out.nodes[index] = wide;  // after the recursion, which may reallocate
        return index;
    }
};

}  // namespace

WideBvh collapseToWide(const Bvh& bvh) {
    WideBvh out;
    if (bvh.nodes.empty()) return out;
    const BvhNode& root = bvh.nodes[0];
    if (root.isLeaf()) {
        WideBvhNode wide;
        wide.childCount = 1;
        wide.bounds[0] = root.bounds;
        wide.first[0] = root.first;
        wide.count[0] = root.count;
        out.nodes.push_back(wide);
        return out;
    }
    Collapser{bvh, out}.node(0, 0, 0);
    return out;
}

}  // namespace fp
