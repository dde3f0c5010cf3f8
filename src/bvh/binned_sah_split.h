#pragma once
// The binned SAH of one node (Wald 2007, "On fast construction of SAH-based bounding volume
// hierarchies"), in the steps that the binned builder runs on one thread for small nodes and spreads
// over threads for large ones (internal to src/bvh): bin, choose a plane, partition.
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "bvh/build_common.h"
#include "bvh/large_prim_planes.h"

namespace fp::detail {

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

// The bin index of a node's primitives along each axis.
struct NodeMapping {
    BinMapping axis[3];
    Lanes origin, scale, lastBin;  // the same, lane by lane, to map all three axes at once

    NodeMapping(const RangeBounds& rb, int binCount);
    // Centroids coincide: no plane separates them.
    bool flat() const { return axis[0].scale == 0.0f && axis[1].scale == 0.0f && axis[2].scale == 0.0f; }
};

// Adds refs[begin, end) to `bins` (axis-major: bins[axis * binCount + bin]), along all three axes in one
// pass (as in Wald 2007). Bins are unions and sums, so ranges binned apart and merged give equal bins.
void binRange(const PrimRef* refs, uint32_t begin, uint32_t end, const NodeMapping& mapping, Bin* bins,
              int binCount);
// Adds `from` to `to`, both axis-major sets of 3 * binCount bins.
void mergeBins(const Bin* from, Bin* to, int binCount);

struct PlaneChoice {
    int axis = -1;  // -1: make a leaf, if allowed
    int plane = 0;  // the left side is bins [0, plane) along `axis` (slots, if `exact`)
    // The plane's A_L N_L + A_R N_R; infinite for none.
    float cost = std::numeric_limits<float>::infinity();
    bool exact = false;  // a plane at a large primitive's centroid (large_prim_planes.h), not between bins
};

// The SAH sweep over one axis's occupied bins (or slots) used[0 .. n), in order: for each plane right
// after used[i] (i + 1 < n), the bracket A_L N_L + A_R N_R of the bins on either side. The cheapest
// replaces best's axis, plane (used[i] + 1) and cost when strictly cheaper, so on equal costs the first
// plane evaluated wins. rightArea and rightCount are scratch of n entries.
void sweepOccupiedBins(const Bin* bins, const int* used, int n, int axis, float* rightArea,
                       uint32_t* rightCount, PlaneChoice& best);

// `exact` if it is strictly cheaper, else `binned`: on equal costs the binned plane wins, so nodes without
// large primitives split as they did before exact planes were added.
inline PlaneChoice cheaperPlane(const PlaneChoice& binned, const PlaneChoice& exact) {
    return exact.cost < binned.cost ? exact : binned;
}
// The SAH leaf rule (preferLeaf) applied to a node's cheapest plane: axis -1 for a leaf.
inline PlaneChoice applyLeafRule(const PlaneChoice& choice, uint32_t count, const RangeBounds& rb,
                                 const BvhBuildOptions& options) {
    if (choice.axis >= 0 && preferLeaf(choice.cost, count, rb, options)) return {};
    return choice;
}

// In-place partition of refs[begin, end) into those binned left of the chosen plane and the rest;
// returns the first index of the rest.
uint32_t partition(PrimRef* refs, uint32_t begin, uint32_t end, const NodeMapping& mapping,
                   const PlaneChoice& choice);

// The binned SAH's state for one thread: bins and sweep scratch, reused from node to node.
class BinnedSah {
  public:
    // rootArea: the area of the whole tree's root box (large_prim_planes.h).
    BinnedSah(const BvhBuildOptions& options, float rootArea);

    int binCount() const { return binCount_; }
    // Empty between calls: binRange() fills them, cheapestPlane() empties them.
    Bin* bins() { return bins_.data(); }

    // The cheapest plane in bins(), with its cost, or axis -1 when no plane has a finite cost. Empties
    // bins().
    PlaneChoice cheapestPlane(const NodeMapping& mapping);

    // The whole split of one node, as detail::buildSubtree wants it: partitions refs[begin, end) and
    // returns the first index of the right side, or `begin` for a leaf.
    uint32_t operator()(PrimRef* refs, uint32_t begin, uint32_t end, const RangeBounds& rb);

  private:
    PlaneChoice choose(const PrimRef* refs, uint32_t begin, uint32_t end, const NodeMapping& mapping,
                       const RangeBounds& rb);
    uint32_t splitPair(PrimRef* refs, uint32_t begin, const RangeBounds& rb,
                       const NodeMapping& mapping) const;

    const BvhBuildOptions& options_;
    float rootArea_;
    int binCount_;
    std::vector<Bin> bins_;                   // axis-major: bins_[axis * binCount + bin]; empty between calls
    std::vector<int> used_;                   // scratch: one axis's occupied bins, in order
    std::vector<float> rightArea_;            // scratch: area of the union of bins used_[i..]
    std::vector<uint32_t> rightCount_;        // scratch: primitives in them
    std::vector<Bin> slots_;                  // large_prim_planes.h: empty between calls
    std::optional<SlotMapping> slotMapping_;  // of the last node that had large primitives
};

}  // namespace fp::detail
