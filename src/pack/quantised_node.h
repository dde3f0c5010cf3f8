#pragma once
// A 4-wide BVH node (bvh/wide_bvh.h) in 64 bytes, its children's boxes quantised to 8 bits per plane
// on a grid local to the node (Ylitie, Karras & Laine 2017, "Efficient Incoherent Ray Traversal on GPUs
// Through Compressed Wide BVHs", HPG, section 3.1), so that one node visit reads one cache line.
// pack/layout.h says where the texels go; this file says what they hold and how they are made. The
// native reference keeps exact boxes (native/native_scene.h says why).
//
//  texel  contents (4 uints each)
//  0      (origin.x, origin.y, origin.z as float bits, scale exponents): the grid's corner p, and per
//         axis a biased exponent byte b (axis a in bits 8a..8a+7), scale s = 2^(b - 127), i.e. the
//         float whose bits are b << 23
//  1      (lo.x, hi.x, lo.y, hi.y) quantised planes, one uint per plane, child i in byte i (bits 8i..8i+7)
//  2      (lo.z, hi.z, 0, 0)
//  3      the four children's links (layout::encodeChild), 0 for an empty slot
//
// The step s is the smallest power of two whose 255 steps span the node's (widened) box; p is the
// box's corner, or lower by less than a step where that puts a thin child's plane on the grid
// (gridOrigin in quantised_node.cpp). Child i's box is [p + s * lo_i, p + s * hi_i] per axis. lo is
// rounded down and hi up, after widening the exact box by kQuantiseMargin relative to the node's
// coordinates, so the quantised box contains the exact one with a margin that covers the rounding of
// the shader's plane distances t = q * (s / d) + (p - o) / d (boxEntries in intersect.glsl). An empty
// slot has link 0 and the inverted box lo = 255, hi = 0; the traversal tells it by its link.
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "bvh/wide_bvh.h"
#include "core/aabb.h"

namespace fp::layout {

constexpr int kNodeTexels = 4;
constexpr int kNodeLinkTexel = 3;
constexpr int kExponentBias = 127;
// Scale exponents are kept in [kMinScaleExponent, kMaxScaleExponent]: a smaller step than 2^-100 is
// never needed, and with steps up to 2^32 (nodes up to 2^40 across) q * s / d stays finite for the
// smallest direction component the traversal allows (1e-20).
constexpr int kMinScaleExponent = -100;
constexpr int kMaxScaleExponent = 32;
// Widening of the exact box before rounding, relative to the node's largest coordinate magnitude plus
// its extent: 2^-20, about 8 float ulps, which covers the three roundings of the shader's plane
// distance even when (p - o) / d and q * s / d nearly cancel.
constexpr double kQuantiseMargin = 1.0 / (1 << 20);

using QuantisedNode = std::array<glm::uvec4, kNodeTexels>;

// Throws fp::Error if the node is larger than kMaxScaleExponent allows, or a link cannot be encoded.
QuantisedNode quantiseNode(const WideBvhNode& node);

// What quantiseNode stored, decoded exactly (in double precision): child `slot`'s box, empty (lo > hi)
// for an empty slot. For tests and checks, not for tracing.
struct QuantisedBox {
    glm::dvec3 lo, hi;
};
QuantisedBox decodeChildBox(const QuantisedNode& node, int slot);
glm::dvec3 gridStep(const QuantisedNode& node);  // s per axis

}  // namespace fp::layout
