#pragma once
// Exact SAH planes at the centroids of the few primitives that are large relative to their node (internal
// to src/bvh), evaluated next to the binned builder's planes.
//
// Why: a few huge triangles (a room's walls around a finely tessellated object) have centroids that share
// equal-width bins with thousands of small ones, so no bin boundary separates them, and the binned builder
// peels them off one level at a time, each level with the root's area. A full sweep separates them with one
// plane between the last small centroid and the first large one (docs/optimisation-log.md, "Tree quality: why
// the binned builder fell short, and the fix"). Such a plane is always "centroid < c" or "centroid <= c" for
// the centroid c of one large primitive along one axis, so evaluating those few planes exactly recovers it,
// at the cost of one pass to find the large primitives and one to evaluate their planes, and only in nodes
// that have any.
#include <cstdint>

#include "bvh/build_common.h"

namespace fp::detail {

struct Bin;          // binned_sah_split.h
struct PlaneChoice;  // binned_sah_split.h

// A node is searched when it has at least kLargeMinNodeCount primitives and at least kLargeMinRootAreaRatio
// of the root's area, for at most kMaxLargePrims of its largest primitives among those whose box has at least
// kLargeAreaRatio of the node's area. Measured on the room scenes (docs/optimisation-log.md, "BVH builder:
// profile and changes"): the Cornell box needs nodes down to 16 primitives; root-area ratios from 0 to 1/4
// give the same costs within 0.2 %, but deep in a soup almost every node has a large primitive, so searching
// there cost +56 % instructions on soup-100k; a node-area ratio of 1/2 misses the walls (a flat wall's box
// has at most 1/3 of a cube's area).
constexpr uint32_t kLargeMinNodeCount = 16;
constexpr float kLargeMinRootAreaRatio = 0.25f;
constexpr int kMaxLargePrims = 8;
constexpr float kLargeAreaRatio = 0.25f;

// The largest primitives of a range (area, then lower index first), at most kMaxLargePrims of them. The
// order is total, so sets found over chunks and merged give the same set as one pass.
struct LargePrims {
    int count = 0;
    float area[kMaxLargePrims];
    uint32_t index[kMaxLargePrims];
    Lanes centroid2[kMaxLargePrims];

    // Adds a primitive if it is among the largest so far.
    void insert(float boxArea, uint32_t primIndex, const Lanes& primCentroid2);
    void merge(const LargePrims& other);
};

// Whether to look for large primitives in a node (then mayHoldLargePrim, once it is binned).
inline bool searchLargePrims(uint32_t count, float nodeArea, float rootArea) {
    return count >= kLargeMinNodeCount && nodeArea >= kLargeMinRootAreaRatio * rootArea;
}

// The area from which a primitive is large in the node.
inline float largePrimMinArea(const RangeBounds& rb) {
    return kLargeAreaRatio * rb.bounds.area();
}

// Whether binned primitives may include one of area >= minArea: such a primitive lies in one bin per axis,
// and that bin's box holds it. Reads the bins without emptying them.
bool mayHoldLargePrim(const Bin* bins, int binCount, float minArea);

// Adds the primitives of refs[begin, end) whose box area is at least minArea to `large`.
void findLargePrims(const PrimRef* refs, uint32_t begin, uint32_t end, float minArea, LargePrims& large);

// Along each axis, the distinct centroids v_0 < ... < v_{m-1} of the large primitives cut the line into
// 2m + 1 slots: below v_0, at v_0, between v_0 and v_1, ... A centroid's slot is the number of v_j it is
// above plus the number it is at or above; the plane between slots p - 1 and p sends slots [0, p) left.
constexpr int kMaxSlots = 2 * kMaxLargePrims + 1;
struct SlotMapping {
    typedef int32_t Ints __attribute__((vector_size(16)));
    // value[j]: the j-th value along x, y and z in lanes 0-2, padded with +inf (which no finite centroid
    // is above or at) where an axis has fewer distinct values; the fourth lane is unused.
    Lanes value[kMaxLargePrims];
    int valueCount = 0;  // the most along any axis

    explicit SlotMapping(const LargePrims& large);
    // The slots of doubled centroid lanes x, y, z, in lanes 0-2.
    Ints slots(const Lanes& c2) const {
        Ints s{};
        // Each comparison is -1 where true.
        for (int j = 0; j < valueCount; ++j) s -= (c2 > value[j]) + (c2 >= value[j]);
        return s;
    }
};

// Adds refs[begin, end) to `slots` (axis-major, kMaxSlots per axis), as binRange does to bins; merged
// with mergeBins(from, to, kMaxSlots).
void slotRange(const PrimRef* refs, uint32_t begin, uint32_t end, const SlotMapping& mapping, Bin* slots);

// The cheapest slot plane (PlaneChoice::exact set), or axis -1 if none has a finite cost. Empties `slots`.
PlaneChoice chooseSlotPlane(Bin* slots);

// As partition(), for a slot plane.
uint32_t partitionSlots(PrimRef* refs, uint32_t begin, uint32_t end, const SlotMapping& mapping,
                        const PlaneChoice& choice);

}  // namespace fp::detail
