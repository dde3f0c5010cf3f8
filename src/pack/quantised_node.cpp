#include "pack/quantised_node.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "pack/layout.h"

namespace fp::layout {

namespace {

// Where plane `side` (0: lo, 1: hi) of `axis` lives: texel 1 + k / 4, channel k % 4, k = 2 axis + side.
uint32_t& planeWord(QuantisedNode& node, int axis, int side) {
    int k = 2 * axis + side;
    return node[size_t(1 + k / 4)][k % 4];
}

uint32_t planeWord(const QuantisedNode& node, int axis, int side) {
    int k = 2 * axis + side;
    return node[size_t(1 + k / 4)][k % 4];
}

// floor and ceil of x >= 0 below 2^62, without a libm call (the quantiser runs once per node, and the
// x86-64 baseline has no rounding instruction).
double floorNonNegative(double x) {
    return double(int64_t(x));
}
double ceilNonNegative(double x) {
    double f = double(int64_t(x));
    return f < x ? f + 1.0 : f;
}

// The largest float at or below x.
float floatAtOrBelow(double x) {
    float f = float(x);
    if (double(f) <= x) return f;
    if (f == 0.0f) return -std::numeric_limits<float>::denorm_min();
    uint32_t bits = glm::floatBitsToUint(f);
    return glm::uintBitsToFloat(f > 0.0f ? bits - 1 : bits + 1);
}

// The smallest exponent e with 255 * 2^e >= extent (at least kMinScaleExponent), so that the node's
// widened box fits in 8-bit steps of 2^e.
int scaleExponent(double extent) {
    if (!(extent >= 0.0) || !std::isfinite(extent))
        throw Error("a BVH node has non-finite bounds; the scene's coordinates must be finite");
    int e = kMinScaleExponent;
    if (extent > std::ldexp(255.0, e)) e = std::max(e, int(std::ceil(std::log2(extent / 255.0))) - 1);
    while (e <= kMaxScaleExponent && std::ldexp(255.0, e) < extent) ++e;
    if (e > kMaxScaleExponent)
        throw Error("a BVH node is " + std::to_string(extent) +
                    " units across; the quantised BVH layout holds nodes up to 2^40");
    return e;
}

// What a grid costs on one axis: each child's slack (how far its quantised planes lie beyond its
// widened exact ones) inside the node's own box, weighted by the child's extent on the other two axes,
// so as the slack adds to the child's surface area (the SAH's hit probability). Slack outside the
// node's box costs nothing, as a ray there has been culled by the node's own box (up to its
// quantisation). Infinite when the widened node does not fit in 255 steps from origin p.
double gridCost(const WideBvhNode& node, int axis, double margin, double p, double s, double lo, double hi) {
    if (p > lo - margin || hi + margin - p > 255.0 * s) return INFINITY;
    const double invStep = 1.0 / s;
    double total = 0.0;
    for (int i = 0; i < node.childCount; ++i) {
        const Aabb& b = node.bounds[i];
        double l = double(b.lo[axis]) - margin, h = double(b.hi[axis]) + margin;
        // l - p and h - p are >= 0 as p is at or below the widened box; 1 / s is exact.
        double ql = p + floorNonNegative((l - p) * invStep) * s,
               qh = p + ceilNonNegative((h - p) * invStep) * s;
        double inside = std::max(0.0, l - std::max(ql, lo)) + std::max(0.0, std::min(qh, hi) - h);
        glm::vec3 e = b.extent();
        total += inside * (double(e[(axis + 1) % 3]) + double(e[(axis + 2) % 3]));
    }
    return total;
}

// The grid's corner on one axis: a float at or below the widened box; of the box's corner and the
// corners that put a plane of a child thinner than a step exactly on the grid, the one of least
// gridCost. The
// default grid starts at the box's corner, which leaves a flat child (a wall, a light) one step thick
// wherever its plane falls; aligning puts the slack where it costs least. On the Cornell box the
// default grid thickens the leaf of the ceiling and the light downwards past the light, so every
// shadow ray would test it (docs/optimisation-log.md, entry 21).
float gridOrigin(const WideBvhNode& node, int axis, double margin, double s, double lo, double hi) {
    float best = floatAtOrBelow(lo - margin);
    const double p0 = best;
    // Only a child thinner than a step has slack of a step or more whichever grid is used, so only
    // its planes are worth aligning to; in deep trees most children are many steps thick, and the
    // search is skipped (it would cost a node as much as the BVH build does per node).
    auto thin = [&](int i) { return double(node.bounds[i].hi[axis]) - double(node.bounds[i].lo[axis]) < s; };
    bool anyThin = false;
    for (int i = 0; i < node.childCount; ++i) anyThin = anyThin || thin(i);
    if (!anyThin) return best;
    double bestCost = gridCost(node, axis, margin, p0, s, lo, hi);
    for (int i = 0; i < node.childCount && bestCost > 0.0; ++i) {
        if (!thin(i)) continue;
        for (double plane :
             {double(node.bounds[i].lo[axis]) - margin, double(node.bounds[i].hi[axis]) + margin}) {
            // On the plane's grid, at or below p0; the float below it, and the one above if it is
            // not exact (which may still be at or below the box).
            double p = plane - s * ceilNonNegative((plane - p0) / s);
            float down = floatAtOrBelow(p);
            const uint32_t bits = glm::floatBitsToUint(down);
            const float up = down == 0.0f ? std::numeric_limits<float>::denorm_min()
                                          : glm::uintBitsToFloat(down > 0.0f ? bits + 1u : bits - 1u);
            for (float candidate : {down, up}) {
                if (candidate == up && double(down) == p) break;
                double cost = gridCost(node, axis, margin, candidate, s, lo, hi);
                if (cost < bestCost) {
                    bestCost = cost;
                    best = candidate;
                }
            }
        }
    }
    return best;
}

}  // namespace

QuantisedNode quantiseNode(const WideBvhNode& node) {
    QuantisedNode out{};
    Aabb box;
    for (int i = 0; i < node.childCount; ++i) box.grow(node.bounds[i]);
    const glm::dvec3 lo(box.lo), hi(box.hi);
    double magnitude = 0.0, extent = 0.0;
    for (int a = 0; a < 3; ++a) {
        magnitude = std::max({magnitude, std::abs(lo[a]), std::abs(hi[a])});
        extent = std::max(extent, hi[a] - lo[a]);
    }
    const double margin = kQuantiseMargin * (magnitude + extent);

    glm::dvec3 origin(0.0), step(1.0);
    for (int a = 0; a < 3; ++a) {
        // The step fits the widened box from the float at or below its corner; the origin may then
        // move down by less than a step to put a child's plane on the grid (gridOrigin).
        float p = floatAtOrBelow(lo[a] - margin);
        int e = scaleExponent(hi[a] + margin - double(p));
        step[a] = std::ldexp(1.0, e);
        p = gridOrigin(node, a, margin, step[a], lo[a], hi[a]);
        origin[a] = p;
        out[0][a] = glm::floatBitsToUint(p);
        out[0].w |= uint32_t(e + kExponentBias) << (8 * a);
    }
    for (int i = 0; i < kWideBvhWidth; ++i) {
        const bool used = i < node.childCount;
        for (int a = 0; a < 3; ++a) {
            // Exact in double: the differences of floats and a margin, divided by a power of two.
            double qlo = std::floor((double(node.bounds[i].lo[a]) - margin - origin[a]) / step[a]);
            double qhi = std::ceil((double(node.bounds[i].hi[a]) + margin - origin[a]) / step[a]);
            uint32_t l = used ? uint32_t(std::clamp(qlo, 0.0, 255.0)) : 255u;
            uint32_t h = used ? uint32_t(std::clamp(qhi, 0.0, 255.0)) : 0u;
            planeWord(out, a, 0) |= l << (8 * i);
            planeWord(out, a, 1) |= h << (8 * i);
        }
        out[kNodeLinkTexel][i] = used ? encodeChild({node.first[i], node.count[i]}) : 0u;
    }
    return out;
}

glm::dvec3 gridStep(const QuantisedNode& node) {
    glm::dvec3 s;
    for (int a = 0; a < 3; ++a) s[a] = std::ldexp(1.0, int((node[0].w >> (8 * a)) & 255u) - kExponentBias);
    return s;
}

QuantisedBox decodeChildBox(const QuantisedNode& node, int slot) {
    const glm::dvec3 s = gridStep(node);
    QuantisedBox b;
    for (int a = 0; a < 3; ++a) {
        double p = glm::uintBitsToFloat(node[0][a]);
        b.lo[a] = p + s[a] * double((planeWord(node, a, 0) >> (8 * slot)) & 255u);
        b.hi[a] = p + s[a] * double((planeWord(node, a, 1) >> (8 * slot)) & 255u);
    }
    return b;
}

}  // namespace fp::layout
