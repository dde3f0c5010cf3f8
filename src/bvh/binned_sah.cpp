// Binned SAH builder after Wald 2007, "On fast construction of SAH-based bounding volume hierarchies".
#include <algorithm>
#include <cmath>

#include "bvh/build_common.h"

namespace fp {
namespace {

using detail::LaneBox;
using detail::PrimRef;
using detail::RangeBounds;

struct Bin {
    LaneBox bounds;
    uint32_t count = 0;
};

// Maps a doubled centroid coordinate to its bin along one axis. Binning and partitioning both call
// this, so a primitive always lands on the side of the plane that the bin counts said it would.
struct BinMapping {
    float origin = 0.0f;  // lowest centroid2 coordinate of the node
    float scale = 0.0f;   // bins per unit; 0 for an axis with no centroid extent (all land in bin 0)
    int lastBin = 0;

    int operator()(float c) const {
        const float f = (c - origin) * scale;
        // f >= 0 since c >= origin; the clamp catches c at the top of the range, where f == binCount.
        // In this form it is a branch-free min, and a NaN (from non-finite input) also clamps instead
        // of converting to int undefinedly.
        return int(f < float(lastBin) ? f : float(lastBin));
    }
};

// In-place partition of refs[begin, end) into those binned below `plane` and the rest; returns the
// first index of the rest. Lomuto's scheme with an unconditional swap: no branch on the (unpredictable)
// side, which matters more than the extra moves.
uint32_t partition(PrimRef* refs, uint32_t begin, uint32_t end, const BinMapping& mapping, int axis,
                   int plane) {
    uint32_t store = begin;  // [begin, store) is left, [store, i) is right
    for (uint32_t i = begin; i < end; ++i) {
        const PrimRef r = refs[i];
        const bool isLeft = mapping(r.lo[axis] + r.hi[axis]) < plane;
        refs[i] = refs[store];
        refs[store] = r;
        store += isLeft;
    }
    return store;
}

class BinnedSahSplitter {
  public:
    explicit BinnedSahSplitter(const BvhBuildOptions& options)
        : options_(options),
          binCount_(options.binCount),
          bins_(3 * size_t(binCount_)),
          used_(binCount_),
          rightArea_(binCount_),
          rightCount_(binCount_) {}

    uint32_t operator()(PrimRef* refs, uint32_t begin, uint32_t end, const RangeBounds& rb) {
        BinMapping mapping[3];
        for (int axis = 0; axis < 3; ++axis) {
            const float extent = rb.centroids.hi[axis] - rb.centroids.lo[axis];
            const float scale = float(binCount_) / extent;
            mapping[axis].origin = rb.centroids.lo[axis];
            // Skips flat axes, and extents so small that the scale overflows.
            mapping[axis].scale = extent > 0.0f && std::isfinite(scale) ? scale : 0.0f;
            mapping[axis].lastBin = binCount_ - 1;
        }
        if (mapping[0].scale == 0.0f && mapping[1].scale == 0.0f && mapping[2].scale == 0.0f)
            return begin;  // centroids coincide: no plane separates them
        if (end - begin == 2) return splitPair(refs, begin, rb, mapping);

        // One pass bins every primitive along all three axes at once (as in Wald 2007).
        for (uint32_t i = begin; i < end; ++i) {
            const glm::vec3 c = refs[i].centroid2();
            for (int axis = 0; axis < 3; ++axis) {
                const int k = mapping[axis](c[axis]);
                Bin& bin = bins_[size_t(axis) * binCount_ + k];
                bin.bounds.grow(refs[i].lo, refs[i].hi);
                ++bin.count;
            }
        }

        // A plane between bins p - 1 and p splits them into [0, p) and [p, binCount). Its SAH cost is
        // traversalCost + intersectCost * (A_L N_L + A_R N_R) / A; only the bracket is compared here.
        // Only planes right after an occupied bin are evaluated: the others repeat the split of the
        // plane before them, and on equal costs the first plane (lowest axis, then lowest p) wins.
        float bestCost = std::numeric_limits<float>::infinity();
        int bestAxis = -1, bestPlane = 0;
        for (int axis = 0; axis < 3; ++axis) {
            Bin* bins = &bins_[size_t(axis) * binCount_];
            // The sweeps and the reset touch only occupied bins: small nodes, which are most nodes,
            // leave most bins empty. (Branch-free: occupancy is unpredictable.)
            int used = 0;
            for (int k = 0; k < binCount_; ++k) {
                used_[used] = k;
                used += bins[k].count != 0;
            }
            if (mapping[axis].scale != 0.0f) {
                LaneBox acc;
                uint32_t count = 0;
                for (int i = used - 1; i > 0; --i) {  // sweep from the right...
                    acc.grow(bins[used_[i]].bounds);
                    count += bins[used_[i]].count;
                    rightArea_[i] = acc.area();
                    rightCount_[i] = count;
                }
                acc = LaneBox{};
                count = 0;
                for (int i = 0; i + 1 < used; ++i) {  // ...then from the left, evaluating each plane
                    acc.grow(bins[used_[i]].bounds);
                    count += bins[used_[i]].count;
                    const float cost =
                        acc.area() * float(count) + rightArea_[i + 1] * float(rightCount_[i + 1]);
                    if (cost < bestCost) {
                        bestCost = cost;
                        bestAxis = axis;
                        bestPlane = used_[i] + 1;
                    }
                }
            }
            for (int i = 0; i < used; ++i) bins[used_[i]] = Bin{};
        }
        if (bestAxis < 0) return begin;  // only when every cost overflowed to inf

        if (preferLeaf(bestCost, end - begin, rb)) return begin;
        return partition(refs, begin, end, mapping[bestAxis], bestAxis, bestPlane);
    }

  private:
    // Whether a leaf is strictly cheaper than the best split (bracket cost as above), and allowed.
    bool preferLeaf(float bestCost, uint32_t count, const RangeBounds& rb) const {
        const float area = rb.bounds.area();
        const float splitCost =
            options_.traversalCost + options_.intersectCost * (area > 0.0f ? bestCost / area : 0.0f);
        const float leafCost = options_.intersectCost * float(count);
        return leafCost < splitCost && count <= uint32_t(options_.maxLeafSize);
    }

    // Two primitives (a large share of all nodes): every candidate plane on every axis splits them the
    // same way, so the bin search above would pick the first axis along which their centroids differ,
    // at cost area(a) + area(b). Same decision and order, without touching the bins.
    uint32_t splitPair(PrimRef* refs, uint32_t begin, const RangeBounds& rb,
                       const BinMapping* mapping) const {
        PrimRef& a = refs[begin];
        PrimRef& b = refs[begin + 1];
        const int axis = mapping[0].scale != 0.0f ? 0 : (mapping[1].scale != 0.0f ? 1 : 2);
        const float cost = LaneBox{a.lo, a.hi}.area() + LaneBox{b.lo, b.hi}.area();
        if (preferLeaf(cost, 2, rb)) return begin;
        if (a.lo[axis] + a.hi[axis] > b.lo[axis] + b.hi[axis]) std::swap(a, b);
        return begin + 1;
    }

    const BvhBuildOptions& options_;
    int binCount_;
    std::vector<Bin> bins_;             // axis-major: bins_[axis * binCount + bin]; empty between calls
    std::vector<int> used_;             // scratch: one axis's occupied bins, in order
    std::vector<float> rightArea_;      // scratch: area of the union of bins used_[i..]
    std::vector<uint32_t> rightCount_;  // scratch: primitives in them
};

}  // namespace

Bvh buildBinnedSah(const std::vector<Aabb>& primBounds, const BvhBuildOptions& options) {
    detail::validateOptions(options, primBounds.size());  // before binCount sizes anything
    BinnedSahSplitter splitter(options);
    return detail::buildTopDown(primBounds, options, splitter);
}

}  // namespace fp
