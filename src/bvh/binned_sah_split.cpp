// The binned SAH of one node, step by step (see binned_sah_split.h).
#include "bvh/binned_sah_split.h"

#include <algorithm>
#include <cmath>

namespace fp::detail {

// Lomuto's scheme with an unconditional swap: no branch on the (unpredictable) side, which matters more
// than the extra moves. The order it leaves is part of the tree (primIndex), so every build partitions
// a node this way, whichever thread runs it.
uint32_t partition(PrimRef* refs, uint32_t begin, uint32_t end, const NodeMapping& nodeMapping,
                   const PlaneChoice& choice) {
    const int axis = choice.axis, plane = choice.plane;
    const BinMapping mapping = nodeMapping.axis[axis];
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

NodeMapping::NodeMapping(const RangeBounds& rb, int binCount) {
    for (int a = 0; a < 3; ++a) {
        const float extent = rb.centroids.hi[a] - rb.centroids.lo[a];
        const float binsPerUnit = float(binCount) / extent;
        axis[a].origin = rb.centroids.lo[a];
        // Skips flat axes, and extents so small that the scale overflows.
        axis[a].scale = extent > 0.0f && std::isfinite(binsPerUnit) ? binsPerUnit : 0.0f;
        axis[a].lastBin = binCount - 1;
        origin[a] = axis[a].origin;
        scale[a] = axis[a].scale;
        lastBin[a] = float(axis[a].lastBin);
    }
    origin[3] = scale[3] = lastBin[3] = 0.0f;
}

void binRange(const PrimRef* refs, uint32_t begin, uint32_t end, const NodeMapping& mapping, Bin* bins,
              int binCount) {
    typedef int32_t Ints __attribute__((vector_size(16)));
    for (uint32_t i = begin; i < end; ++i) {
        const PrimRef& r = refs[i];
        // BinMapping::operator() on all lanes at once, with the same operations in the same order. The
        // fourth lane is 0 and maps to bin 0, unread.
        const Lanes f = (r.centroid2Lanes() - mapping.origin) * mapping.scale;
        const Ints k = __builtin_convertvector(f < mapping.lastBin ? f : mapping.lastBin, Ints);
        for (int axis = 0; axis < 3; ++axis) {
            Bin& bin = bins[axis * binCount + k[axis]];
            bin.bounds.grow(r.lo, r.hi);
            ++bin.count;
        }
    }
}

void mergeBins(const Bin* from, Bin* to, int binCount) {
    for (int k = 0; k < 3 * binCount; ++k) {
        to[k].bounds.grow(from[k].bounds);
        to[k].count += from[k].count;
    }
}

BinnedSah::BinnedSah(const BvhBuildOptions& options, float rootArea)
    : options_(options),
      rootArea_(rootArea),
      binCount_(options.binCount),
      bins_(3 * size_t(binCount_)),
      used_(binCount_),
      rightArea_(binCount_),
      rightCount_(binCount_),
      slots_(3 * size_t(kMaxSlots)) {}

void sweepOccupiedBins(const Bin* bins, const int* used, int n, int axis, float* rightArea,
                       uint32_t* rightCount, PlaneChoice& best) {
    LaneBox acc;
    uint32_t count = 0;
    for (int i = n - 1; i > 0; --i) {  // sweep from the right...
        acc.grow(bins[used[i]].bounds);
        count += bins[used[i]].count;
        rightArea[i] = acc.area();
        rightCount[i] = count;
    }
    acc = LaneBox{};
    count = 0;
    for (int i = 0; i + 1 < n; ++i) {  // ...then from the left, evaluating each plane
        acc.grow(bins[used[i]].bounds);
        count += bins[used[i]].count;
        const float cost = acc.area() * float(count) + rightArea[i + 1] * float(rightCount[i + 1]);
        if (cost < best.cost) {
            best.axis = axis;
            best.plane = used[i] + 1;
            best.cost = cost;
        }
    }
}

PlaneChoice BinnedSah::cheapestPlane(const NodeMapping& mapping) {
    // A plane between bins p - 1 and p splits them into [0, p) and [p, binCount). Its SAH cost is
    // traversalCost + intersectCost * (A_L N_L + A_R N_R) / A; only the bracket is compared here.
    // Only planes right after an occupied bin are evaluated: the others repeat the split of the
    // plane before them, and on equal costs the first plane (lowest axis, then lowest p) wins.
    PlaneChoice best;
    for (int axis = 0; axis < 3; ++axis) {
        Bin* bins = &bins_[size_t(axis) * binCount_];
        // The sweeps and the reset touch only occupied bins: small nodes, which are most nodes,
        // leave most bins empty. (Branch-free: occupancy is unpredictable.)
        int used = 0;
        for (int k = 0; k < binCount_; ++k) {
            used_[used] = k;
            used += bins[k].count != 0;
        }
        if (mapping.axis[axis].scale != 0.0f)
            sweepOccupiedBins(bins, used_.data(), used, axis, rightArea_.data(), rightCount_.data(), best);
        for (int i = 0; i < used; ++i) bins[used_[i]] = Bin{};
    }
    return best;  // no axis: only when every cost overflowed to inf
}

// The binned plane, or the exact plane of a large primitive when that is strictly cheaper; then the leaf
// rule. The steps and their order are those of the threaded top of the build (binned_sah.cpp).
PlaneChoice BinnedSah::choose(const PrimRef* refs, uint32_t begin, uint32_t end, const NodeMapping& mapping,
                              const RangeBounds& rb) {
    const uint32_t count = end - begin;
    const float minArea = largePrimMinArea(rb);
    const bool search =
        searchLargePrims(count, rb.bounds.area(), rootArea_) && mayHoldLargePrim(bins(), binCount_, minArea);
    PlaneChoice choice = cheapestPlane(mapping);
    if (search) {
        LargePrims large;
        findLargePrims(refs, begin, end, minArea, large);
        if (large.count > 0) {
            slotMapping_.emplace(large);
            slotRange(refs, begin, end, *slotMapping_, slots_.data());
            choice = cheaperPlane(choice, chooseSlotPlane(slots_.data()));
        }
    }
    return applyLeafRule(choice, count, rb, options_);
}

uint32_t BinnedSah::operator()(PrimRef* refs, uint32_t begin, uint32_t end, const RangeBounds& rb) {
    const NodeMapping mapping(rb, binCount_);
    if (mapping.flat()) return begin;
    if (end - begin == 2) return splitPair(refs, begin, rb, mapping);
    binRange(refs, begin, end, mapping, bins(), binCount_);
    const PlaneChoice choice = choose(refs, begin, end, mapping, rb);
    if (choice.axis < 0) return begin;
    if (choice.exact) return partitionSlots(refs, begin, end, *slotMapping_, choice);
    return partition(refs, begin, end, mapping, choice);
}

// Two primitives (a large share of all nodes): every candidate plane on every axis splits them the
// same way, so the bin search above would pick the first axis along which their centroids differ,
// at cost area(a) + area(b). Same decision and order, without touching the bins.
uint32_t BinnedSah::splitPair(PrimRef* refs, uint32_t begin, const RangeBounds& rb,
                              const NodeMapping& mapping) const {
    PrimRef& a = refs[begin];
    PrimRef& b = refs[begin + 1];
    const int axis = mapping.axis[0].scale != 0.0f ? 0 : (mapping.axis[1].scale != 0.0f ? 1 : 2);
    const float cost = LaneBox{a.lo, a.hi}.area() + LaneBox{b.lo, b.hi}.area();
    if (preferLeaf(cost, 2, rb, options_)) return begin;
    if (a.lo[axis] + a.hi[axis] > b.lo[axis] + b.hi[axis]) std::swap(a, b);
    return begin + 1;
}

}  // namespace fp::detail
