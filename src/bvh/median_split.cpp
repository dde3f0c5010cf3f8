// Object-median builder: the simple baseline that the binned SAH builder is measured against.
#include <algorithm>

#include "bvh/build_common.h"

namespace fp {

Bvh buildMedianSplit(const AabbArray& primBounds, const BvhBuildOptions& options) {
    const auto maxLeafSize = static_cast<uint32_t>(std::max(options.maxLeafSize, 1));
    auto split = [maxLeafSize](detail::PrimRef* refs, uint32_t begin, uint32_t end,
                               const detail::RangeBounds& rb) {
        if (end - begin <= maxLeafSize) return begin;
        const glm::vec3 extent = rb.centroids.extent();
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        const uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(refs + begin, refs + mid, refs + end,
                         [axis](const detail::PrimRef& a, const detail::PrimRef& b) {
                             return a.lo[axis] + a.hi[axis] < b.lo[axis] + b.hi[axis];  // doubled centroids
                         });
        return mid;
    };
    return detail::buildTopDown(primBounds, options, split);
}

}  // namespace fp
