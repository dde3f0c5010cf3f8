// Full-sweep SAH builder: the exhaustive reference that the binned builder's trees are measured against.
// Every node sorts its centroids along each axis and evaluates the SAH (MacDonald & Booth 1990) at every
// plane between two distinct consecutive centroids, as in the sweep builder of Wald 2007, section 3.
#include <algorithm>

#include "bvh/build_common.h"

namespace fp {
namespace {

using detail::LaneBox;
using detail::PrimRef;
using detail::RangeBounds;

class SweepSahSplitter {
  public:
    explicit SweepSahSplitter(const BvhBuildOptions& options) : options_(options) {}

    uint32_t operator()(PrimRef* refs, uint32_t begin, uint32_t end, const RangeBounds& rb) {
        const uint32_t n = end - begin;
        rightArea_.resize(n);
        // As in the binned builder: only the bracket A_L N_L + A_R N_R is compared, and on equal costs
        // the first plane (lowest axis, then leftmost) wins.
        float bestCost = std::numeric_limits<float>::infinity();
        int bestAxis = -1;
        uint32_t bestLeftCount = 0;
        for (int axis = 0; axis < 3; ++axis) {
            if (!(rb.centroids.lo[axis] < rb.centroids.hi[axis])) continue;  // no plane separates them
            HugePageVector<PrimRef>& sorted = sorted_[axis];
            sorted.assign(refs + begin, refs + end);
            auto key = [axis](const PrimRef& r) { return r.lo[axis] + r.hi[axis]; };  // doubled centroid
            // Ties broken by the primitive index, so the order (and the tree) is fully determined.
            std::sort(sorted.begin(), sorted.end(), [&key](const PrimRef& a, const PrimRef& b) {
                return key(a) < key(b) || (key(a) == key(b) && a.index() < b.index());
            });
            LaneBox acc;
            for (uint32_t i = n - 1; i > 0; --i) {  // rightArea_[i]: the area of sorted[i, n)
                acc.grow(sorted[i].lo, sorted[i].hi);
                rightArea_[i] = acc.area();
            }
            acc = LaneBox{};
            for (uint32_t left = 1; left < n;
                 ++left) {  // the plane between sorted[left - 1] and sorted[left]
                acc.grow(sorted[left - 1].lo, sorted[left - 1].hi);
                if (!(key(sorted[left - 1]) < key(sorted[left]))) continue;  // equal centroids: no plane
                const float cost = acc.area() * float(left) + rightArea_[left] * float(n - left);
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestLeftCount = left;
                }
            }
        }
        if (bestAxis < 0 || detail::preferLeaf(bestCost, n, rb, options_)) return begin;
        std::copy(sorted_[bestAxis].begin(), sorted_[bestAxis].end(), refs + begin);
        return begin + bestLeftCount;
    }

  private:
    const BvhBuildOptions& options_;
    HugePageVector<PrimRef> sorted_[3];  // scratch: the node's references sorted along each axis
    std::vector<float> rightArea_;       // scratch
};

}  // namespace

Bvh buildSweepSah(const AabbArray& primBounds, const BvhBuildOptions& options) {
    SweepSahSplitter splitter(options);
    return detail::buildTopDown(primBounds, options, splitter);
}

}  // namespace fp
