#include "bvh/ray_query.h"

#include <cmath>

namespace fp {
namespace {

// gamma(n) = n u / (1 - n u) with unit roundoff u = 2^-24 bounds the relative error of n rounded float
// operations (Higham; as used by Ize 2013, "Robust BVH ray traversal", and PBRT for slab tests).
constexpr float kUnitRoundoff = 0.5f * std::numeric_limits<float>::epsilon();
constexpr float kGamma3 = 3.0f * kUnitRoundoff / (1.0f - 3.0f * kUnitRoundoff);

// Traversal stack: deep enough for any sensible tree without allocating, but never overflows.
class NodeStack {
  public:
    bool empty() const { return size_ == 0 && overflow_.empty(); }
    void push(uint32_t node) {
        if (size_ < kInline)
            inline_[size_++] = node;
        else
            overflow_.push_back(node);
    }
    uint32_t pop() {
        if (!overflow_.empty()) {
            const uint32_t node = overflow_.back();
            overflow_.pop_back();
            return node;
        }
        return inline_[--size_];
    }

  private:
    static constexpr int kInline = 64;
    uint32_t inline_[kInline];
    int size_ = 0;
    std::vector<uint32_t> overflow_;
};

}  // namespace

AabbArray triangleBounds(const std::vector<TriangleVerts>& triangles) {
    AabbArray bounds;
    bounds.reserve(triangles.size());
    for (const TriangleVerts& tri : triangles) bounds.push_back(tri.bounds());
    return bounds;
}

bool intersectTriangle(const Ray& ray, const TriangleVerts& tri, float& t, float& u, float& v) {
    const glm::vec3 e1 = tri.p1 - tri.p0;
    const glm::vec3 e2 = tri.p2 - tri.p0;
    const glm::vec3 pvec = glm::cross(ray.dir, e2);
    const float det = glm::dot(e1, pvec);
    if (det == 0.0f) return false;  // ray in the triangle's plane, or a degenerate triangle
    const float invDet = 1.0f / det;
    const glm::vec3 tvec = ray.origin - tri.p0;
    // The tests are negated so that NaN (from non-finite input) misses rather than hits.
    const float uu = glm::dot(tvec, pvec) * invDet;
    if (!(uu >= 0.0f && uu <= 1.0f)) return false;
    const glm::vec3 qvec = glm::cross(tvec, e1);
    const float vv = glm::dot(ray.dir, qvec) * invDet;
    if (!(vv >= 0.0f && uu + vv <= 1.0f)) return false;
    const float tt = glm::dot(e2, qvec) * invDet;
    if (!(tt > ray.tMin && tt < ray.tMax)) return false;
    t = tt;
    u = uu;
    v = vv;
    return true;
}

bool intersectTriangleConfirmed(const Ray& ray, const glm::vec3& invDir, const TriangleVerts& tri, float& t,
                                float& u, float& v) {
    float tt, uu, vv;
    if (!intersectTriangle(ray, tri, tt, uu, vv)) return false;
    if (!slabTest(tri.bounds(), ray, invDir, tt)) return false;
    t = tt;
    u = uu;
    v = vv;
    return true;
}

bool slabTest(const Aabb& box, const Ray& ray, const glm::vec3& invDir, float tMax, float& tEnter) {
    float tNear = ray.tMin, tFar = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        // Choose the entry plane by the sign bit of 1/dir (Williams et al. 2005, "An efficient and
        // robust ray-box intersection algorithm"), which also tells -0 from +0.
        const bool negative = std::signbit(invDir[axis]);
        const float t0 = ((negative ? box.hi[axis] : box.lo[axis]) - ray.origin[axis]) * invDir[axis];
        const float t1 = ((negative ? box.lo[axis] : box.hi[axis]) - ray.origin[axis]) * invDir[axis];
        // With dir[axis] == 0 these are -inf/+inf inside the slab and both +inf or both -inf outside
        // it (culled below). With the origin on a slab plane, one (both, for a flat box) is 0 * inf =
        // NaN. A NaN loses the comparisons below, which keep the running value: no constraint, so
        // the ray counts as inside the closed slab.
        tNear = t0 > tNear ? t0 : tNear;
        tFar = t1 < tFar ? t1 : tFar;
    }
    // Widen the far end for the rounding in the operations above (Ize 2013).
    tFar *= tFar > 0.0f ? 1.0f + 2.0f * kGamma3 : 1.0f - 2.0f * kGamma3;
    tEnter = tNear;
    // tNear == +inf only for a zero direction outside the box, which tFar == +inf would let pass.
    return tNear <= tFar && tNear < std::numeric_limits<float>::infinity();
}

bool slabTest(const Aabb& box, const Ray& ray, const glm::vec3& invDir, float tMax) {
    float tEnter;
    return slabTest(box, ray, invDir, tMax, tEnter);
}

RayHit closestHit(const Bvh& bvh, const std::vector<TriangleVerts>& triangles, const Ray& ray,
                  TraversalCounters* counters) {
    RayHit best;
    if (bvh.nodes.empty()) return best;
    const glm::vec3 invDir = 1.0f / ray.dir;
    Ray clipped = ray;  // tMax shrinks to the nearest hit so far
    TraversalCounters local;
    TraversalCounters& count = counters ? *counters : local;

    NodeStack stack;
    if (slabTest(bvh.nodes[0].bounds, clipped, invDir, clipped.tMax)) stack.push(0);
    while (!stack.empty()) {
        uint32_t index = stack.pop();
        // Descend towards the nearer child, leaving the farther one on the stack.
        for (;;) {
            const BvhNode& node = bvh.nodes[index];
            ++count.nodesVisited;
            if (node.isLeaf()) {
                for (uint32_t i = node.first; i < node.first + node.count; ++i) {
                    const uint32_t prim = bvh.primIndex[i];
                    ++count.trianglesTested;
                    float t, u, v;
                    if (intersectTriangleConfirmed(clipped, invDir, triangles[prim], t, u, v)) {
                        clipped.tMax = t;
                        best = {t, prim, u, v};
                    }
                }
                break;
            }
            const uint32_t left = index + 1, right = node.first;
            float tLeft, tRight;
            const bool hitLeft = slabTest(bvh.nodes[left].bounds, clipped, invDir, clipped.tMax, tLeft);
            const bool hitRight = slabTest(bvh.nodes[right].bounds, clipped, invDir, clipped.tMax, tRight);
            if (hitLeft && hitRight) {
                const bool leftFirst = tLeft <= tRight;
                stack.push(leftFirst ? right : left);
                index = leftFirst ? left : right;
            } else if (hitLeft || hitRight) {
                index = hitLeft ? left : right;
            } else {
                break;
            }
        }
    }
    return best;
}

RayHit closestHitBruteForce(const std::vector<TriangleVerts>& triangles, const Ray& ray) {
    RayHit best;
    const glm::vec3 invDir = 1.0f / ray.dir;
    Ray clipped = ray;
    for (uint32_t prim = 0; prim < triangles.size(); ++prim) {
        float t, u, v;
        if (intersectTriangleConfirmed(clipped, invDir, triangles[prim], t, u, v)) {
            clipped.tMax = t;
            best = {t, prim, u, v};
        }
    }
    return best;
}

}  // namespace fp
