#pragma once
// Shared by the tests/bvh suites: deterministic random numbers, test meshes and the structural checks
// every built Bvh must pass.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "bvh/bvh.h"
#include "bvh/ray_query.h"

namespace fp::test {

// Uniform in [0, 1) from the top 24 bits: unlike std::uniform_real_distribution, the same numbers
// on every standard library.
inline float uniform01(std::mt19937& rng) {
    return float(rng() >> 8) * 0x1p-24f;
}
inline float uniform(std::mt19937& rng, float lo, float hi) {
    return lo + (hi - lo) * uniform01(rng);
}
inline uint32_t uniformIndex(std::mt19937& rng, size_t n) {
    return uint32_t(uint64_t(rng()) * n >> 32);
}
inline glm::vec3 uniformIn(std::mt19937& rng, const Aabb& box) {
    return {uniform(rng, box.lo.x, box.hi.x), uniform(rng, box.lo.y, box.hi.y),
            uniform(rng, box.lo.z, box.hi.z)};
}
// Rejection sampling of the unit ball, then normalized: uniform on the sphere.
inline glm::vec3 unitVector(std::mt19937& rng) {
    for (;;) {
        glm::vec3 p{uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)};
        float len2 = glm::dot(p, p);
        if (len2 > 1e-4f && len2 <= 1.0f) return p / std::sqrt(len2);
    }
}

using Mesh = std::vector<TriangleVerts>;

// `count` triangles with vertices within `size` of centers uniform in [0, 10]^3.
inline Mesh randomSoup(size_t count, uint32_t seed, float size = 0.5f) {
    std::mt19937 rng(seed);
    Mesh mesh(count);
    const Aabb centers{glm::vec3(0.0f), glm::vec3(10.0f)};
    for (TriangleVerts& tri : mesh) {
        glm::vec3 c = uniformIn(rng, centers);
        tri = {c + size * unitVector(rng), c + size * unitVector(rng), c + size * unitVector(rng)};
    }
    return mesh;
}

// Latitude-longitude sphere: 2 * stacks * slices triangles (the polar ones degenerate to zero area).
inline Mesh tessellatedSphere(int stacks, int slices, float radius = 1.0f,
                              glm::vec3 center = glm::vec3(0.0f)) {
    auto point = [&](int i, int j) {
        float theta = 3.14159265f * float(i) / float(stacks);
        float phi = 2.0f * 3.14159265f * float(j % slices) / float(slices);
        return center + radius * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                           std::sin(theta) * std::sin(phi));
    };
    Mesh mesh;
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            mesh.push_back({point(i, j), point(i + 1, j), point(i + 1, j + 1)});
            mesh.push_back({point(i, j), point(i + 1, j + 1), point(i, j + 1)});
        }
    return mesh;
}

// `layers` horizontal n x n grids of unit cells on integer coordinates (z = 0, 1, ...). Each cell holds
// the four triangles of both diagonal splits, which share the cell as their bounds: groups of four
// coincident centroids, and vertices and edges exactly on node box planes.
inline Mesh coincidentGrid(int n, int layers) {
    Mesh mesh;
    for (int k = 0; k < layers; ++k)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                glm::vec3 a(i, j, k), b(i + 1, j, k), c(i + 1, j + 1, k), d(i, j + 1, k);
                mesh.push_back({a, b, c});
                mesh.push_back({a, c, d});
                mesh.push_back({a, b, d});
                mesh.push_back({b, c, d});
            }
    return mesh;
}

inline Mesh identicalTriangles(size_t count) {
    return Mesh(count, TriangleVerts{{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.5f}});
}

// Uneven density, where the object median does badly: a dense cluster of tiny triangles in a corner
// plus a sparse scattering of large ones across a much bigger volume.
inline Mesh unevenDensity(size_t denseCount, size_t sparseCount, uint32_t seed) {
    std::mt19937 rng(seed);
    Mesh mesh;
    const Aabb cluster{glm::vec3(0.0f), glm::vec3(1.0f)};
    const Aabb world{glm::vec3(0.0f), glm::vec3(100.0f)};
    for (size_t i = 0; i < denseCount; ++i) {
        glm::vec3 c = uniformIn(rng, cluster);
        mesh.push_back(
            {c + 0.02f * unitVector(rng), c + 0.02f * unitVector(rng), c + 0.02f * unitVector(rng)});
    }
    for (size_t i = 0; i < sparseCount; ++i) {
        glm::vec3 c = uniformIn(rng, world);
        mesh.push_back({c + 5.0f * unitVector(rng), c + 5.0f * unitVector(rng), c + 5.0f * unitVector(rng)});
    }
    return mesh;
}

// Needles and slivers, where Möller–Trumbore's determinant is mostly rounding error: two vertices a
// rounding step apart, or three nearly on a line.
inline Mesh sliverSoup(size_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    Mesh mesh;
    const Aabb centers{glm::vec3(0.0f), glm::vec3(4.0f)};
    for (size_t i = 0; i < count; ++i) {
        glm::vec3 a = uniformIn(rng, centers), b = a + unitVector(rng);
        glm::vec3 c = i % 2 ? b + 1e-6f * unitVector(rng) : 0.5f * (a + b) + 1e-6f * unitVector(rng);
        mesh.push_back({a, b, c});
    }
    return mesh;
}

// Long thin triangles in random directions: 4 units long and 0.02 wide in a 10-unit cube, so that their
// bounds are large and overlap though their centroids are spread.
inline Mesh longThinTriangles(size_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    Mesh mesh;
    const Aabb starts{glm::vec3(0.0f), glm::vec3(10.0f)};
    for (size_t i = 0; i < count; ++i) {
        glm::vec3 a = uniformIn(rng, starts), along = 4.0f * unitVector(rng);
        mesh.push_back({a, a + along, a + 0.5f * along + 0.02f * unitVector(rng)});
    }
    return mesh;
}

inline Mesh translated(Mesh mesh, glm::vec3 offset) {
    for (TriangleVerts& t : mesh) {
        t.p0 += offset;
        t.p1 += offset;
        t.p2 += offset;
    }
    return mesh;
}

struct NamedMesh {
    std::string name;
    Mesh mesh;
};

// The meshes every structural and ray test runs on.
inline std::vector<NamedMesh> testMeshes() {
    return {
        {"randomSoup", randomSoup(3000, 1)},
        {"sphere", tessellatedSphere(32, 48)},
        {"coincidentGrid", coincidentGrid(12, 3)},
        {"identical", identicalTriangles(200)},
        {"uneven", unevenDensity(2000, 200, 2)},
        {"slivers", sliverSoup(1000, 5)},
        {"farFromOrigin", translated(randomSoup(1000, 6), {3000.0f, -2000.0f, 1000.0f})},
        {"one", randomSoup(1, 3)},
        {"two", randomSoup(2, 4)},
        {"empty", {}},
    };
}

struct NamedBuilder {
    std::string name;
    std::function<Bvh(const AabbArray&, const BvhBuildOptions&)> build;
};

inline std::vector<NamedBuilder> builders() {
    return {{"binnedSah", [](auto& b, auto& o) { return buildBinnedSah(b, o); }},
            {"sweepSah", [](auto& b, auto& o) { return buildSweepSah(b, o); }},
            {"medianSplit", [](auto& b, auto& o) { return buildMedianSplit(b, o); }}};
}

inline bool contains(const Aabb& outer, const Aabb& inner) {
    return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) &&
           glm::all(glm::greaterThanEqual(outer.hi, inner.hi));
}
inline bool sameBox(const Aabb& a, const Aabb& b) {
    return a.lo == b.lo && a.hi == b.hi;
}

// The layout documented in bvh/bvh.h, checked exactly:
// - no primitives <=> no nodes; primIndex is a permutation of 0..n-1;
// - every node is reached exactly once from the root and nodes.size() == 2 * leaves - 1;
// - an interior node's left child is the next node and its right child (`first`) follows the whole
//   left subtree (depth-first order);
// - every leaf holds 1..maxLeafSize primitives, and the leaves, in depth-first order, cover primIndex
//   in consecutive ranges;
// - every node's bounds contain, and equal, the union of its children's bounds (interior) or of its
//   primitives' bounds (leaf).
inline ::testing::AssertionResult checkStructure(const Bvh& bvh, const AabbArray& primBounds,
                                                 const BvhBuildOptions& options) {
    const size_t n = primBounds.size();
    if (n == 0) {
        if (bvh.nodes.empty() && bvh.primIndex.empty()) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "an empty input must give an empty Bvh";
    }
    if (bvh.primIndex.size() != n)
        return ::testing::AssertionFailure()
               << "primIndex has " << bvh.primIndex.size() << " entries for " << n;
    std::vector<int> seen(n, 0);
    for (uint32_t p : bvh.primIndex) {
        if (p >= n) return ::testing::AssertionFailure() << "primIndex entry " << p << " out of range";
        if (seen[p]++) return ::testing::AssertionFailure() << "primitive " << p << " appears twice";
    }
    if (bvh.nodes.empty()) return ::testing::AssertionFailure() << "no nodes";

    std::vector<int> visits(bvh.nodes.size(), 0);
    uint32_t nextPrim = 0, leaves = 0;
    // Returns the index one past the subtree rooted at `index`, or 0 on failure (with `error` set).
    std::string error;
    auto fail = [&error](const std::string& message) {
        error = message;
        return 0u;
    };
    std::function<uint32_t(uint32_t)> walk = [&](uint32_t index) -> uint32_t {
        if (index >= bvh.nodes.size()) return fail("node index " + std::to_string(index) + " out of range");
        if (visits[index]++) return fail("node " + std::to_string(index) + " reached twice");
        const BvhNode& node = bvh.nodes[index];
        const std::string where = "node " + std::to_string(index) + ": ";
        if (node.isLeaf()) {
            ++leaves;
            if (node.count > uint32_t(options.maxLeafSize))
                return fail(where + "leaf of " + std::to_string(node.count) + " primitives");
            if (node.first != nextPrim) return fail(where + "leaf range does not follow the previous");
            if (size_t(node.first) + node.count > n) return fail(where + "leaf range past primIndex");
            Aabb u;
            for (uint32_t i = node.first; i < node.first + node.count; ++i)
                u.grow(primBounds[bvh.primIndex[i]]);
            if (!sameBox(u, node.bounds)) return fail(where + "leaf bounds differ from its primitives'");
            nextPrim += node.count;
            return index + 1;
        }
        const uint32_t afterLeft = walk(index + 1);
        if (afterLeft == 0) return 0;
        if (node.first != afterLeft)
            return fail(where + "right child " + std::to_string(node.first) +
                        " does not follow the left subtree");
        const uint32_t afterRight = walk(node.first);
        if (afterRight == 0) return 0;
        const Aabb& l = bvh.nodes[index + 1].bounds;
        const Aabb& r = bvh.nodes[node.first].bounds;
        if (!contains(node.bounds, l) || !contains(node.bounds, r))
            return fail(where + "bounds do not contain a child's");
        Aabb u = l;
        u.grow(r);
        if (!sameBox(u, node.bounds)) return fail(where + "bounds are not the union of its children's");
        return afterRight;
    };
    const uint32_t end = walk(0);
    if (end == 0) return ::testing::AssertionFailure() << error;
    if (end != bvh.nodes.size())
        return ::testing::AssertionFailure()
               << "tree ends at " << end << " of " << bvh.nodes.size() << " nodes";
    if (nextPrim != n) return ::testing::AssertionFailure() << "leaves cover " << nextPrim << " of " << n;
    if (bvh.nodes.size() != 2 * size_t(leaves) - 1)
        return ::testing::AssertionFailure() << bvh.nodes.size() << " nodes for " << leaves << " leaves";
    return ::testing::AssertionSuccess();
}

}  // namespace fp::test
