#include "gpu/quantised_node.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "gpu/layout.h"

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
        // The grid's corner: a float at or below the widened box.
        double wanted = lo[a] - margin;
        float p = float(wanted);
        if (double(p) > wanted) p = std::nextafter(p, -INFINITY);
        int e = scaleExponent(hi[a] + margin - double(p));
        origin[a] = p;
        step[a] = std::ldexp(1.0, e);
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
