// Exact planes at the centroids of a node's large primitives (see large_prim_planes.h).
#include "bvh/large_prim_planes.h"

#include <algorithm>
#include <limits>

#include "bvh/binned_sah_split.h"

namespace fp::detail {

namespace {

// The order of LargePrims: larger area first, then lower index (a total order on distinct primitives).
bool before(float areaA, uint32_t indexA, float areaB, uint32_t indexB) {
    return areaA > areaB || (areaA == areaB && indexA < indexB);
}

}  // namespace

void LargePrims::insert(float boxArea, uint32_t idx, const Lanes& c) {
    if (count == kMaxLargePrims && !before(boxArea, idx, area[count - 1], index[count - 1])) return;
    int i = count < kMaxLargePrims ? count++ : count - 1;  // insertion sort from the end
    for (; i > 0 && before(boxArea, idx, area[i - 1], index[i - 1]); --i) {
        area[i] = area[i - 1];
        index[i] = index[i - 1];
        centroid2[i] = centroid2[i - 1];
    }
    area[i] = boxArea;
    index[i] = idx;
    centroid2[i] = c;
}

void LargePrims::merge(const LargePrims& other) {
    for (int i = 0; i < other.count; ++i) insert(other.area[i], other.index[i], other.centroid2[i]);
}

bool mayHoldLargePrim(const Bin* bins, int binCount, float minArea) {
    for (int axis = 0; axis < 3; ++axis) {
        bool any = false;
        for (int k = 0; k < binCount; ++k) {
            const Bin& b = bins[axis * binCount + k];
            any = any || (b.count != 0 && b.bounds.area() >= minArea);
        }
        if (!any) return false;
    }
    return true;
}

void findLargePrims(const PrimRef* refs, uint32_t begin, uint32_t end, float minArea, LargePrims& large) {
    for (uint32_t i = begin; i < end; ++i) {
        const float a = LaneBox{refs[i].lo, refs[i].hi}.area();
        if (a >= minArea) large.insert(a, refs[i].index(), refs[i].centroid2Lanes());
    }
}

SlotMapping::SlotMapping(const LargePrims& large) {
    for (int j = 0; j < kMaxLargePrims; ++j) value[j] = Lanes{} + std::numeric_limits<float>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        float v[kMaxLargePrims];
        int n = 0;
        for (int i = 0; i < large.count; ++i) {        // insertion sort, dropping repeats: equal values would
            const float c = large.centroid2[i][axis];  // count twice and leave an empty slot
            int k = n;
            while (k > 0 && v[k - 1] > c) --k;
            if (k > 0 && v[k - 1] == c) continue;
            for (int m = n; m > k; --m) v[m] = v[m - 1];
            v[k] = c;
            ++n;
        }
        for (int j = 0; j < n; ++j) value[j][axis] = v[j];
        valueCount = std::max(valueCount, n);
    }
}

void slotRange(const PrimRef* refs, uint32_t begin, uint32_t end, const SlotMapping& mapping, Bin* slots) {
    for (uint32_t i = begin; i < end; ++i) {
        const PrimRef& r = refs[i];
        const SlotMapping::Ints s = mapping.slots(r.centroid2Lanes());
        for (int axis = 0; axis < 3; ++axis) {
            Bin& slot = slots[axis * kMaxSlots + s[axis]];
            slot.bounds.grow(r.lo, r.hi);
            ++slot.count;
        }
    }
}

PlaneChoice chooseSlotPlane(Bin* slots) {
    // As BinnedSah::choosePlane: planes right after an occupied slot, first of equal costs wins.
    PlaneChoice best;
    best.exact = true;
    for (int axis = 0; axis < 3; ++axis) {
        Bin* s = &slots[axis * kMaxSlots];
        int used[kMaxSlots], n = 0;
        for (int k = 0; k < kMaxSlots; ++k)
            if (s[k].count != 0) used[n++] = k;
        float rightArea[kMaxSlots];
        uint32_t rightCount[kMaxSlots];
        sweepOccupiedBins(s, used, n, axis, rightArea, rightCount, best);
        for (int k = 0; k < kMaxSlots; ++k) s[k] = Bin{};
    }
    return best;
}

uint32_t partitionSlots(PrimRef* refs, uint32_t begin, uint32_t end, const SlotMapping& mapping,
                        const PlaneChoice& choice) {
    // Slots [0, 2j + 1) are the centroids below v_j, and slots [0, 2j + 2) those at or below it: one
    // comparison instead of the slot.
    const int axis = choice.axis, j = (choice.plane - 1) / 2;
    const bool orEqual = choice.plane % 2 == 0;
    const float v = mapping.value[j][axis];
    uint32_t store = begin;  // Lomuto's scheme, as partition()
    for (uint32_t i = begin; i < end; ++i) {
        const PrimRef r = refs[i];
        const float c = r.lo[axis] + r.hi[axis];
        const bool isLeft = orEqual ? c <= v : c < v;
        refs[i] = refs[store];
        refs[store] = r;
        store += isLeft;
    }
    return store;
}

}  // namespace fp::detail
