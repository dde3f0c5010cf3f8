// Ray queries against the scene's BVH (layout in src/pack/layout.h): closest hit and any hit.
#include "common/ray.glsl"
#include "common/scene_data.glsl"
#include "common/camera.glsl"
#ifndef BVH_STACK_SIZE
#error "BVH_STACK_SIZE is set by the renderer (src/render/renderer.cpp), from the tree"
#endif
#if BVH_STACK_SIZE < 4 || BVH_STACK_SIZE > 259
#error "BVH_STACK_SIZE must be 4 to 259 (shiftStack)"
#endif
const float INF = 1e30;
float gRayCount = 0.0;  // rays traced by this pixel, for the rays/s figure
int gNodesVisited = 0;  // BVH nodes and triangles the last traversal looked at, for the cost views
int gTrianglesTested = 0;
int gPathNodes = 0;  // the same, summed over every ray of a path (camera, bounce, shadow), for the cost view
int gPathTriangles = 0;

// The instance the traversal is in (INSTANCE_NODES_START scenes), for the hits it records.
int gInstance = -1;

#include "common/opacity.glsl"

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

// Child i's quantised planes, q = byte i of a plane's uint (pack/quantised_node.h), as floats.
vec4 planeSteps(uint plane) { return vec4((uvec4(plane) >> uvec4(0u, 8u, 16u, 24u)) & 255u); }

// Slab test (Kay & Kajiya 1986) of the four children of a wide node at once, channel i for child i:
// entry distances, INF where a box is missed within (0, tMax) or the slot is empty (link 0). The boxes
// are quantised to the node's grid (Ylitie, Karras & Laine 2017): a plane at p + s q along an axis is
// reached at t = q (s / d) + (p - o) / d, one multiply-add per plane once the node's two per-axis
// terms are known. The sign of the direction picks each axis' near and far plane, so no min and max
// per plane; the quantiser's margin keeps near <= far for every used slot. The exit distance is
// widened by a few ulps (Ize 2013, "Robust BVH Ray Traversal") so that rounding never culls a box the
// ray grazes; the quantiser's margin covers the rest of this form's rounding.
vec4 boxEntries(vec3 origin, vec3 invDir, uvec4 grid, uvec4 planesXY, uvec4 planesZ, uvec4 link, float tMax) {
    vec3 scale = uintBitsToFloat(((uvec3(grid.w) >> uvec3(0u, 8u, 16u)) & 255u) << 23u) * invDir;
    vec3 offset = (uintBitsToFloat(grid.xyz) - origin) * invDir;
    bvec3 back = lessThan(invDir, vec3(0.0));
    vec4 x0 = planeSteps(back.x ? planesXY.y : planesXY.x) * scale.x + offset.x;
    vec4 x1 = planeSteps(back.x ? planesXY.x : planesXY.y) * scale.x + offset.x;
    vec4 y0 = planeSteps(back.y ? planesXY.w : planesXY.z) * scale.y + offset.y;
    vec4 y1 = planeSteps(back.y ? planesXY.z : planesXY.w) * scale.y + offset.y;
    vec4 z0 = planeSteps(back.z ? planesZ.y : planesZ.x) * scale.z + offset.z;
    vec4 z1 = planeSteps(back.z ? planesZ.x : planesZ.y) * scale.z + offset.z;
    vec4 enter = max(max(x0, y0), max(z0, vec4(0.0)));
    vec4 exit = min(min(x1, y1), z1) * 1.0000004;
    bvec4 hit = bvec4(uvec4(lessThanEqual(enter, min(exit, vec4(tMax)))) & uvec4(notEqual(link, uvec4(0u))));
    return mix(vec4(INF), enter, hit);
}

// Tests the triangles of up to four leaf ranges, [first.i, first.i + count.i) for i = x, y, z, w, in
// one loop, shrinking hit.t; returns true as soon as one is hit when anyHit is set. One loop for all the
// leaf children of a node, not one per child: llvmpipe runs every inlined copy of this loop whenever
// any pixel of its SIMD group needs it, and a second copy cost 15 % of a Cornell box render
// (docs/optimisation-log.md, entry 3).
bool intersectLeaves(Ray ray, uvec4 first, uvec4 count, bool anyHit, inout Hit hit) {
    // Where each range starts in the loop's count, and what turns the loop index into a triangle index.
    uint end0 = count.x, end1 = end0 + count.y, end2 = end1 + count.z, total = end2 + count.w;
    uvec4 offset = first - uvec4(0u, end0, end1, end2);  // modulo 2^32, as uint arithmetic is
    gTrianglesTested += int(total);
    for (uint k = 0u; k < total; ++k) {
        uint i = k + (k < end0 ? offset.x : k < end1 ? offset.y : k < end2 ? offset.z : offset.w);
        // A pixel with no triangle left still runs this iteration (masked: llvmpipe runs a loop's body
        // while any pixel of its SIMD group needs it, and every node visit enters the loop once), and
        // its fetches still read memory: at a stray index (an interior child's link, a range's end)
        // each is a cache miss on a large scene. Triangle 0 is always in the cache (docs/optimisation-log.md,
        // entry 25: "Stray fetches").
        i = k < total ? i : 0u;
        TriangleData tri = fetchTriangle(int(i));
        float t;
        vec2 uv;
        if (intersectTriangle(ray, tri.v0, tri.e1, tri.e2, hit.t, t, uv)) {
#ifdef SURFACE_OPACITY
            // Alpha and back-face culling: a hit the surface does not cover is no hit at all.
            if (tri.flags != 0.0 && !coversHit(ray, tri, int(i), uv)) continue;
#endif
            hit = Hit(t, int(i), uv, gInstance);
            if (anyHit) return true;
        }
    }
    return false;
}

// Orders two (distance, link) pairs by distance: one compare-exchange of a sorting network.
void orderPair(inout float ta, inout uint la, inout float tb, inout uint lb) {
    bool swap = tb < ta;
    float t = ta;
    uint l = la;
    ta = swap ? tb : ta;
    la = swap ? lb : la;
    tb = swap ? t : tb;
    lb = swap ? l : lb;
}

// Stack traversal of the 4-wide BVH (Wald, Benthin & Boulos 2008), the children's boxes stored in the
// parent: one node visit tests four boxes, the leaf children hit are intersected at once, and the
// interior children hit are visited nearest first (a five-comparison sorting network, no branches:
// on llvmpipe every branch costs the whole SIMD group).
// 1 / d per axis, tiny components made tiny numbers instead of zeros, so that no 0 * inf = NaN reaches
// the slab test.
vec3 safeInverse(vec3 d) { return 1.0 / mix(d, vec3(1e-20), lessThan(abs(d), vec3(1e-20))); }

// The traversal stack is a shift register, its top in stack[0]: every entry is read and written at a
// constant index, so llvmpipe keeps the stack in vector registers. An array indexed by each pixel's own
// stack size is written one SIMD lane at a time, each lane's store behind a branch on its mask, and
// those stores held a quarter of the glass scene's samples (docs/optimisation-log.md, "The traversal
// stack as a shift register"): shifting all BVH_STACK_SIZE entries (the renderer sizes the stack to the
// entries its tree can hold: WideBvh::stackEntries) takes more instructions and 13-29 %
// less time.
// Moves the stack by d entries: pushes l1 .. ld (d = 1, 2, 3; l1 ends on top), pops the top (d = -1) or
// keeps it (d = 0).
void shiftStack(inout uint stack[BVH_STACK_SIZE], int d, uint l1, uint l2, uint l3) {
    uint old[BVH_STACK_SIZE] = stack;
    // In runs of 16 entries, each a loop of a constant count: the compiler unrolls a loop only up to
    // about 32 iterations (Mesa's NIR), and a loop it keeps indexes the array at run time, one lane at a
    // time. Sixteen runs: at most 259 entries (layout::kMaxTraversalStack).
#define SHIFT_STACK_RUN(first)                                                     \
    for (int i = first; i < min(first + 16, BVH_STACK_SIZE); ++i)                  \
        stack[i] = d == 3   ? old[i - 3]                                           \
                   : d == 2 ? old[i - 2]                                           \
                   : d == 1 ? old[i - 1]                                           \
                   : d == 0 ? old[i]                                               \
                            : old[min(i + 1, BVH_STACK_SIZE - 1)];
    SHIFT_STACK_RUN(3)
    SHIFT_STACK_RUN(19)
    SHIFT_STACK_RUN(35)
    SHIFT_STACK_RUN(51)
    SHIFT_STACK_RUN(67)
    SHIFT_STACK_RUN(83)
    SHIFT_STACK_RUN(99)
    SHIFT_STACK_RUN(115)
    SHIFT_STACK_RUN(131)
    SHIFT_STACK_RUN(147)
    SHIFT_STACK_RUN(163)
    SHIFT_STACK_RUN(179)
    SHIFT_STACK_RUN(195)
    SHIFT_STACK_RUN(211)
    SHIFT_STACK_RUN(227)
    SHIFT_STACK_RUN(243)
#undef SHIFT_STACK_RUN
    stack[2] = d == 3 ? l3 : d == 2 ? old[0] : d == 1 ? old[1] : d == 0 ? old[2] : old[3];
    stack[1] = d >= 2 ? l2 : d == 1 ? old[0] : d == 0 ? old[1] : old[2];
    stack[0] = d >= 1 ? l1 : d == 0 ? old[0] : old[1];
}

bool traverse(Ray worldRay, float tMax, bool anyHit, out Hit hit) {
    hit = Hit(tMax, -1, vec2(0.0), -1);
    gRayCount += 1.0;
    gNodesVisited = 0;
    gTrianglesTested = 0;
#ifdef SURFACE_OPACITY
    gCameraTrace = isCameraRay(worldRay);
#endif
    Ray ray = worldRay;
    vec3 invDir = safeInverse(ray.dir);
    uint stack[BVH_STACK_SIZE];  // its top in stack[0] (shiftStack)
    int size = 0;
    uint node = 0u;
#ifdef INSTANCE_NODES_START
    // Two levels (pack/layout.h): a link to an instance's node pair moves the ray into the instance's
    // space (the direction not renormalised, so that t means the same in both) until the traversal has
    // popped the instance's subtree off the stack, down to the size it had on entering.
    vec3 worldInvDir = invDir;
    gInstance = -1;
    int instanceBase = -1;  // the stack's size when the ray entered its instance; -1: in the world
#endif
    while (true) {
#ifdef INSTANCE_NODES_START
        if (node >= INSTANCE_NODES_START) {
            int base = int(node) * NODE_TEXELS;
            vec4 r0 = uintBitsToFloat(nodeTexel(base)), r1 = uintBitsToFloat(nodeTexel(base + 1)),
                 r2 = uintBitsToFloat(nodeTexel(base + 2));  // world-to-object, row by row
            vec3 o = worldRay.origin, d = worldRay.dir;
            ray = Ray(vec3(dot(r0.xyz, o) + r0.w, dot(r1.xyz, o) + r1.w, dot(r2.xyz, o) + r2.w),
                      vec3(dot(r0.xyz, d), dot(r1.xyz, d), dot(r2.xyz, d)));
            invDir = safeInverse(ray.dir);
            gInstance = int(node);
            instanceBase = size;
            node = nodeTexel(base + 3).x;  // the root of its mesh's BVH
        }
#endif
        ++gNodesVisited;
        int base = int(node) * NODE_TEXELS;  // one 64-byte node, laid out as layout.h says
        uvec4 link = nodeTexel(base + NODE_LINK_TEXEL);  // child links
        vec4 t = boxEntries(ray.origin, invDir, nodeTexel(base), nodeTexel(base + 1),
                            nodeTexel(base + 2), link, hit.t);
        bvec4 leaf = notEqual(link & LEAF_BIT, uvec4(0u));
        // The leaf children that were hit: their triangle counts, zero for the others.
        uvec4 count = (((link >> LEAF_COUNT_SHIFT) & 15u) + 1u) * uvec4(leaf) * uvec4(lessThan(t, vec4(INF)));
        if (count != uvec4(0u) && intersectLeaves(ray, link & LEAF_FIRST_MASK, count, anyHit, hit)) return true;
        // Only interior children remain, nearest first; those beyond a hit the leaves found are culled.
        t = mix(t, vec4(INF), bvec4(uvec4(leaf) | uvec4(greaterThan(t, vec4(hit.t)))));
        float t0 = t.x, t1 = t.y, t2 = t.z, t3 = t.w;
        uint l0 = link.x, l1 = link.y, l2 = link.z, l3 = link.w;
        orderPair(t0, l0, t1, l1);
        orderPair(t2, l2, t3, l3);
        orderPair(t0, l0, t2, l2);
        orderPair(t1, l1, t3, l3);
        orderPair(t1, l1, t2, l2);
        // The nearest is visited next and the farther ones wait on the stack, farthest deepest (the hit
        // ones come first in the sorted order); with none hit, the top of the stack is next.
        if (t0 == INF && size == 0) break;
#ifdef INSTANCE_NODES_START
        if (t0 == INF && size == instanceBase) {  // the instance is done: back to the world's entries
            ray = worldRay;
            invDir = worldInvDir;
            gInstance = -1;
            instanceBase = -1;
        }
#endif
        node = t0 < INF ? l0 : stack[0];
        int d = t0 < INF ? (t1 < INF ? 1 : 0) + (t2 < INF ? 1 : 0) + (t3 < INF ? 1 : 0) : -1;
        shiftStack(stack, d, l1, l2, l3);
        size += d;
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
