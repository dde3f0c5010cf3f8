// Ray queries against the scene's BVH (layout in src/gpu/layout.h): closest hit and any hit.
#ifndef BVH_STACK_SIZE
#define BVH_STACK_SIZE 32
#endif
const float INF = 1e30;
float gRayCount = 0.0;  // rays traced by this pixel, for the rays/s figure
int gNodesVisited = 0;  // BVH nodes and triangles the last traversal looked at, for the cost views
int gTrianglesTested = 0;
int gPathNodes = 0;  // the same, summed over every ray of a path (camera, bounce, shadow), for the cost view
int gPathTriangles = 0;

struct Ray {
    vec3 origin;
    vec3 dir;
};

struct Hit {
    float t;
    int triangle;  // -1: nothing hit
    vec2 uv;       // barycentrics of v1 and v2
};

// Moller & Trumbore 1997, "Fast, minimum storage ray-triangle intersection"; two-sided.
bool intersectTriangle(Ray ray, vec3 v0, vec3 e1, vec3 e2, float tMax, out float t, out vec2 uv) {
    vec3 p = cross(ray.dir, e2);
    float det = dot(e1, p);
    if (det == 0.0) return false;
    float invDet = 1.0 / det;
    vec3 s = ray.origin - v0;
    uv.x = dot(s, p) * invDet;
    vec3 q = cross(s, e1);
    uv.y = dot(ray.dir, q) * invDet;
    t = dot(e2, q) * invDet;
    return uv.x >= 0.0 && uv.y >= 0.0 && uv.x + uv.y <= 1.0 && t > 0.0 && t < tMax;
}

// Slab test (Kay & Kajiya 1986): entry distance, or INF when the box is missed within (0, tMax).
// The exit distance is widened by a few ulps (Ize 2013, "Robust BVH Ray Traversal") so that rounding
// never culls a box the ray grazes.
float boxEntry(vec3 origin, vec3 invDir, vec3 lo, vec3 hi, float tMax) {
    vec3 t0 = (lo - origin) * invDir, t1 = (hi - origin) * invDir;
    vec3 tNear = min(t0, t1), tFar = max(t0, t1);
    float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
    float exit = min(min(min(tFar.x, tFar.y), tFar.z) * 1.0000004, tMax);
    return enter <= exit ? enter : INF;
}

// Tests the triangles of two leaf ranges, [firstA, firstA + countA) then [firstB, firstB + countB), in
// one loop, shrinking hit.t; returns true as soon as one is hit when anyHit is set. One loop for both
// children of a node, not one call per child: llvmpipe runs every inlined copy of this loop whenever
// any pixel of its SIMD group needs it, and the second copy cost 15 % of a Cornell box render
// (BENCHMARKS.md, optimisation log).
bool intersectLeaves(Ray ray, uint firstA, uint countA, uint firstB, uint countB, bool anyHit, inout Hit hit) {
    uint count = countA + countB;
    gTrianglesTested += int(count);
    for (uint k = 0u; k < count; ++k) {
        uint i = k < countA ? firstA + k : firstB + (k - countA);
        TriangleData tri = fetchTriangle(int(i));
        float t;
        vec2 uv;
        if (intersectTriangle(ray, tri.v0, tri.e1, tri.e2, hit.t, t, uv)) {
            hit = Hit(t, int(i), uv);
            if (anyHit) return true;
        }
    }
    return false;
}

// Stack traversal with both child boxes stored in the parent: one node fetch tests two boxes, leaves
// are intersected at once, and the nearer interior child is visited first.
bool traverse(Ray ray, float tMax, bool anyHit, out Hit hit) {
    hit = Hit(tMax, -1, vec2(0.0));
    gRayCount += 1.0;
    gNodesVisited = 0;
    gTrianglesTested = 0;
    // Tiny direction components become tiny numbers instead of zeros, so that no 0 * inf = NaN
    // reaches the slab test.
    vec3 safeDir = mix(ray.dir, vec3(1e-20), lessThan(abs(ray.dir), vec3(1e-20)));
    vec3 invDir = 1.0 / safeDir;
    uint stack[BVH_STACK_SIZE];
    int size = 0;
    uint node = 0u;
    while (true) {
        ++gNodesVisited;
        vec4 b0 = texelFetch(uNodeBounds, int(node) * NODE_BOUNDS_TEXELS);
        vec4 b1 = texelFetch(uNodeBounds, int(node) * NODE_BOUNDS_TEXELS + 1);
        vec4 b2 = texelFetch(uNodeBounds, int(node) * NODE_BOUNDS_TEXELS + 2);
        uvec2 link = texelFetch(uNodeLinks, int(node)).xy;  // child links, encoded as layout.h says
        float tLeft = boxEntry(ray.origin, invDir, b0.xyz, vec3(b0.w, b1.xy), hit.t);
        float tRight = boxEntry(ray.origin, invDir, vec3(b1.zw, b2.x), b2.yzw, hit.t);
        bool leftLeaf = (link.x & LEAF_BIT) != 0u, rightLeaf = (link.y & LEAF_BIT) != 0u;
        // Leaf children are tested at once, left then right; only interior children remain.
        uint leftCount = tLeft < INF && leftLeaf ? ((link.x >> LEAF_COUNT_SHIFT) & 15u) + 1u : 0u;
        uint rightCount = tRight < INF && rightLeaf ? ((link.y >> LEAF_COUNT_SHIFT) & 15u) + 1u : 0u;
        if (leftCount + rightCount > 0u &&
            intersectLeaves(ray, link.x & LEAF_FIRST_MASK, leftCount, link.y & LEAF_FIRST_MASK, rightCount, anyHit, hit))
            return true;
        if (leftLeaf) tLeft = INF;
        if (rightLeaf) tRight = INF;
        if (tLeft < INF && tRight < INF) {
            bool leftFirst = tLeft <= tRight;
            stack[size++] = leftFirst ? link.y : link.x;
            node = leftFirst ? link.x : link.y;
        } else if (tLeft < INF) {
            node = link.x;
        } else if (tRight < INF) {
            node = link.y;
        } else {
            if (size == 0) break;
            node = stack[--size];
        }
    }
    return hit.triangle >= 0;
}

void countPathCost() {
    gPathNodes += gNodesVisited;
    gPathTriangles += gTrianglesTested;
}

bool traceClosest(Ray ray, out Hit hit) {
    bool found = traverse(ray, INF, false, hit);
    countPathCost();
    return found;
}

bool occluded(Ray ray, float tMax) {
    Hit hit;
    bool found = traverse(ray, tMax, true, hit);
    countPathCost();
    return found;
}
