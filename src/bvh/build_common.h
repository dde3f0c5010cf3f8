#pragma once
// What the top-down builders share (internal to src/bvh): primitive references that are partitioned in
// place, the SAH leaf rule, and the depth-first flattening into Bvh::nodes.
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "bvh/bvh.h"

namespace fp::detail {

// Four floats with lane-wise min/max in one SIMD instruction each (GCC and Clang vector extensions,
// on any target); glm::vec3 operations stay scalar. Binning is bound by these read-modify-writes.
// Only min/max ever touch the fourth lane, so whatever bits it holds are harmless.
#if !defined(__GNUC__)
#error "src/bvh needs the GCC/Clang vector extensions"
#endif
typedef float Lanes __attribute__((vector_size(16)));
// Same operand order, so the same NaN handling, as glm::min/max.
inline Lanes min(Lanes a, Lanes b) {
    return b < a ? b : a;
}
inline Lanes max(Lanes a, Lanes b) {
    return a < b ? b : a;
}

// A box as lanes x, y, z; the fourth lane carries nothing that is ever read back.
struct LaneBox {
    Lanes lo = Lanes{} + std::numeric_limits<float>::infinity();
    Lanes hi = Lanes{} - std::numeric_limits<float>::infinity();

    void grow(const Lanes& boxLo, const Lanes& boxHi) {
        lo = detail::min(lo, boxLo);
        hi = detail::max(hi, boxHi);
    }
    void grow(const LaneBox& b) { grow(b.lo, b.hi); }
    Aabb aabb() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
    // Aabb::area() of a non-empty box, with the same operations in the same order.
    float area() const {
        const float ex = hi[0] - lo[0], ey = hi[1] - lo[1], ez = hi[2] - lo[2];
        return 2.0f * (ex * ey + ey * ez + ez * ex);
    }
};

// A primitive's bounds and original index. The builders move these rather than primIndex entries so
// that a node's primitives are contiguous in memory while it is binned and partitioned.
struct PrimRef {
    Lanes lo;  // x, y, z and 0
    Lanes hi;  // x, y, z and the primitive index's bits, which fill what would be padding

    PrimRef() = default;
    PrimRef(const Aabb& b, uint32_t index)
        : lo{b.lo.x, b.lo.y, b.lo.z, 0.0f}, hi{b.hi.x, b.hi.y, b.hi.z, 0.0f} {
        std::memcpy(reinterpret_cast<char*>(&hi) + 12, &index, sizeof index);
    }
    uint32_t index() const {
        uint32_t i;
        std::memcpy(&i, reinterpret_cast<const char*>(&hi) + 12, sizeof i);
        return i;
    }
    // Twice the centroid: the builders only compare and bin centroids, so the 0.5 is never needed.
    glm::vec3 centroid2() const { return {lo[0] + hi[0], lo[1] + hi[1], lo[2] + hi[2]}; }
    // The same in lanes x, y, z, and 0 in the fourth: the index bits read as a float are mostly
    // denormal, and arithmetic on denormals takes a slow microcode path on x86 (25 % of the whole
    // build's time when they were added in).
    Lanes centroid2Lanes() const {
        typedef uint32_t Bits __attribute__((vector_size(16)));
        const Bits xyz{~0u, ~0u, ~0u, 0u};
        return lo + Lanes(Bits(hi) & xyz);
    }
};

// Bounds of a node's primitives, and of their (doubled) centroids.
struct RangeBounds {
    Aabb bounds;
    Aabb centroids;
};

// Lane-wise, with the operand order of Aabb::grow, so the same bits as growing Aabbs one by one.
inline RangeBounds rangeBounds(const PrimRef* refs, uint32_t begin, uint32_t end) {
    LaneBox bounds, centroids;
    for (uint32_t i = begin; i < end; ++i) {
        bounds.grow(refs[i].lo, refs[i].hi);
        const Lanes c = refs[i].centroid2Lanes();
        centroids.grow(c, c);
    }
    return {bounds.aabb(), centroids.aabb()};
}

inline void validateOptions(const BvhBuildOptions& options, size_t primCount) {
    if (options.binCount < 2) throw std::invalid_argument("BvhBuildOptions::binCount must be at least 2");
    if (options.maxLeafSize < 1)
        throw std::invalid_argument("BvhBuildOptions::maxLeafSize must be at least 1");
    if (options.threadCount < 0)
        throw std::invalid_argument("BvhBuildOptions::threadCount must not be negative");
    // Node indices (up to 2n - 1) must fit the 32-bit node fields.
    if (primCount > std::numeric_limits<uint32_t>::max() / 2)
        throw std::length_error("too many primitives for a 32-bit BVH");
}

// The SAH builders' leaf rule. `bracketCost` is A_L N_L + A_R N_R of the best split found; the split's
// SAH cost is traversalCost + intersectCost * bracketCost / A (MacDonald & Booth 1990), a leaf's is
// intersectCost * count. A leaf is chosen when it is strictly cheaper and allowed (count <= maxLeafSize).
inline bool preferLeaf(float bracketCost, uint32_t count, const RangeBounds& rb,
                       const BvhBuildOptions& options) {
    const float area = rb.bounds.area();
    const float splitCost =
        options.traversalCost + options.intersectCost * (area > 0.0f ? bracketCost / area : 0.0f);
    const float leafCost = options.intersectCost * float(count);
    return leafCost < splitCost && count <= uint32_t(options.maxLeafSize);
}

// PrimRefs for primBounds, in input order.
inline HugePageVector<PrimRef> makePrimRefs(const AabbArray& primBounds) {
    HugePageVector<PrimRef> refs(primBounds.size());
    for (size_t i = 0; i < refs.size(); ++i) refs[i] = PrimRef(primBounds[i], uint32_t(i));
    return refs;
}

// Builds the subtree over refs[begin, end) top-down, appending its nodes to `nodes` in depth-first order
// so that a left child directly follows its parent; the right child's index is patched into its parent
// when the right child is emitted. Node indices count from the subtree's root, which is nodes[0] only if
// `nodes` starts empty; leaf ranges are positions in refs.
// `split(refs, begin, end, rangeBounds)` partitions refs[begin, end) and returns the split position
// mid with begin < mid < end, or any other value to ask for a leaf. It is only called for two or more
// primitives; a refused split of more than maxLeafSize primitives is overridden by halving the range.
template <class Split>
void buildSubtree(PrimRef* refs, uint32_t begin, uint32_t end, const BvhBuildOptions& options, Split&& split,
                  HugePageVector<BvhNode>& nodes) {
    const auto maxLeafSize = static_cast<uint32_t>(options.maxLeafSize);
    const auto base = static_cast<uint32_t>(nodes.size());
    constexpr uint32_t kNoParent = std::numeric_limits<uint32_t>::max();
    struct Task {
        uint32_t begin, end;
        uint32_t parent;  // for a right child: the interior node whose `first` must point here
    };
    std::vector<Task> stack;
    stack.reserve(64);
    stack.push_back({begin, end, kNoParent});
    nodes.reserve(nodes.size() + 2 * size_t(end - begin) - 1);  // the most a binary tree with n leaves has

    while (!stack.empty()) {
        const Task task = stack.back();
        stack.pop_back();
        const auto index = static_cast<uint32_t>(nodes.size());
        if (task.parent != kNoParent) nodes[task.parent].first = index - base;

        // One streaming pass per node; cheap next to binning and partitioning.
        const RangeBounds rb = rangeBounds(refs, task.begin, task.end);
        const uint32_t count = task.end - task.begin;
        uint32_t mid = count > 1 ? split(refs, task.begin, task.end, rb) : task.begin;
        if (mid <= task.begin || mid >= task.end) {
            if (count <= maxLeafSize) {
                nodes.push_back({rb.bounds, task.begin, count});
                continue;
            }
            mid = task.begin + count / 2;
        }
        nodes.push_back({rb.bounds, 0, 0});
        stack.push_back({mid, task.end, index});        // popped after the whole left subtree
        stack.push_back({task.begin, mid, kNoParent});  // popped next: becomes node index + 1
    }
}

// The primitive order the builders leave in refs, as Bvh::primIndex.
inline HugePageVector<uint32_t> primIndexOf(const HugePageVector<PrimRef>& refs) {
    HugePageVector<uint32_t> primIndex(refs.size());
    for (size_t i = 0; i < refs.size(); ++i) primIndex[i] = refs[i].index();
    return primIndex;
}

// A whole single-threaded build with `split` (see buildSubtree).
template <class Split>
Bvh buildTopDown(const AabbArray& primBounds, const BvhBuildOptions& options, Split&& split) {
    validateOptions(options, primBounds.size());
    Bvh bvh;
    if (primBounds.empty()) return bvh;
    HugePageVector<PrimRef> refs = makePrimRefs(primBounds);
    buildSubtree(refs.data(), 0, uint32_t(refs.size()), options, split, bvh.nodes);
    bvh.primIndex = primIndexOf(refs);
    return bvh;
}

}  // namespace fp::detail
