#pragma once
// CPU ray queries against triangles through a Bvh: the reference for tests (and a native renderer),
// and the conventions the GLSL traversal must share so that both answer alike:
// - Möller–Trumbore triangle test, two-sided, edges and vertices inclusive, hits with tMin < t < tMax,
//   kept only if the ray reaches the triangle's bounding box by then (intersectTriangleConfirmed);
// - slab box test with a precomputed 1/dir, where zero direction components become IEEE infinities
//   and a NaN slab distance (0 * inf: origin exactly on a slab plane) constrains nothing; written
//   with explicit comparisons, since GLSL min/max leave NaN handling undefined;
// - the box's far distance widened by 1 + 2 gamma(3) (Ize 2013) so that rounding never culls a box
//   the ray touches;
// - stack traversal visiting the nearer child first.
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "bvh/bvh.h"
#include "core/aabb.h"

namespace fp {

struct Ray {
    glm::vec3 origin{0.0f}, dir{0.0f};  // dir need not be normalized; t is in units of dir
    float tMin = 0.0f, tMax = std::numeric_limits<float>::infinity();
};

struct TriangleVerts {
    glm::vec3 p0, p1, p2;

    Aabb bounds() const {
        Aabb b;
        b.grow(p0);
        b.grow(p1);
        b.grow(p2);
        return b;
    }
};

AabbArray triangleBounds(const std::vector<TriangleVerts>& triangles);

struct RayHit {
    float t = std::numeric_limits<float>::infinity();
    uint32_t prim = std::numeric_limits<uint32_t>::max();  // index into the triangle list
    float u = 0.0f, v = 0.0f;  // barycentrics of p1 and p2: p = (1-u-v) p0 + u p1 + v p2
    bool hit() const { return prim != std::numeric_limits<uint32_t>::max(); }
};

// Work done by one closestHit call, for tests and profiling.
struct TraversalCounters {
    uint64_t nodesVisited = 0, trianglesTested = 0;
};

// Möller & Trumbore 1997, "Fast, minimum storage ray-triangle intersection". Two-sided; a hit needs
// u >= 0, v >= 0, u + v <= 1 and ray.tMin < t < ray.tMax. t, u, v are written only on a hit.
// Rays parallel to the triangle's plane (and degenerate triangles) miss.
bool intersectTriangle(const Ray& ray, const TriangleVerts& tri, float& t, float& u, float& v);

// An intersectTriangle hit that is also confirmed by slabTest(tri.bounds(), ray, invDir, t): the ray
// reaches the triangle's box no later than the hit. On sliver triangles det is mostly rounding error
// and Möller–Trumbore can report hits arbitrarily far from the triangle; this drops them. Both closest
// hit functions use it, which is what makes them agree exactly: the slab test is monotone in the box
// and in tMax, so every ancestor box of a confirmed hit passes the test made with a larger tMax.
bool intersectTriangleConfirmed(const Ray& ray, const glm::vec3& invDir, const TriangleVerts& tri, float& t,
                                float& u, float& v);

// Whether the ray meets the closed box for some t in [ray.tMin, tMax] (tMax widened, see above);
// tEnter is then where it enters, clamped to ray.tMin. invDir = 1.0f / ray.dir componentwise.
bool slabTest(const Aabb& box, const Ray& ray, const glm::vec3& invDir, float tMax, float& tEnter);
bool slabTest(const Aabb& box, const Ray& ray, const glm::vec3& invDir, float tMax);

// Nearest confirmed hit (intersectTriangleConfirmed) with tMin < t < tMax. Same t as closestHitBruteForce for
// every ray; on an exact tie in t the two may name different primitives. bvh must be built over
// triangleBounds(triangles).
RayHit closestHit(const Bvh& bvh, const std::vector<TriangleVerts>& triangles, const Ray& ray,
                  TraversalCounters* counters = nullptr);
// Tests every triangle in order; on a tie the lowest index wins.
RayHit closestHitBruteForce(const std::vector<TriangleVerts>& triangles, const Ray& ray);

}  // namespace fp
