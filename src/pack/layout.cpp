#include "pack/layout.h"

#include <string>

#include "core/error.h"

namespace fp::layout {

BvhBuildOptions bvhOptions(int threads) {
    BvhBuildOptions options;
    options.threadCount = threads;
    options.maxLeafSize = 8;
    options.traversalCost = 3.0f;
    return options;
}

uint32_t encodeChild(const ChildLink& child) {
    if (child.count == 0) {
        if (child.first >= kLeafBit) throw Error("internal: BVH node index too large for the GPU layout");
        return child.first;
    }
    if (child.first > kMaxLeafFirst || child.count > kMaxLeafCount)
        throw Error("the GPU layout cannot address a BVH leaf of " + std::to_string(child.count) +
                    " triangles from triangle " + std::to_string(child.first) + " (at most " +
                    std::to_string(kMaxLeafCount) + " triangles, from below " +
                    std::to_string(kMaxLeafFirst + 1) + ")");
    return kLeafBit | ((child.count - 1) << kLeafCountShift) | child.first;
}

ChildLink decodeChild(uint32_t link) {
    if (!(link & kLeafBit)) return {link, 0};
    return {link & kMaxLeafFirst, ((link >> kLeafCountShift) & 15u) + 1};
}

}  // namespace fp::layout
