// The packed GPU layout (src/gpu/layout.h) read back on the CPU: every triangle reachable exactly
// once through the node links, boxes that contain what they point to, and a light CDF that ends at 1.
#include <gtest/gtest.h>

#include <random>

#include "core/error.h"
#include "gpu/layout.h"
#include "gpu/pack.h"

namespace fp {
namespace {

Scene randomScene(int triangles, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-10.0f, 10.0f);
    Scene s;
    s.materials.resize(3);
    s.materials[1].emission = glm::vec3(4.0f, 2.0f, 1.0f);
    s.materials[2].emission = glm::vec3(1.0f);
    for (int i = 0; i < triangles; ++i) {
        Triangle t;
        glm::vec3 c(u(rng), u(rng), u(rng));
        for (auto& p : t.p) p = c + 0.1f * glm::vec3(u(rng), u(rng), u(rng));
        glm::vec3 n = glm::normalize(t.geometricNormal());
        t.n = {n, n, n};
        t.material = uint32_t(i % 3);
        s.triangles.push_back(t);
    }
    return s;
}

Bvh buildFor(const Scene& s) {
    std::vector<Aabb> bounds;
    for (const Triangle& t : s.triangles) bounds.push_back(t.bounds());
    return buildBinnedSah(bounds);
}

// Unpacks child `side` (0 left, 1 right) of node `i`.
Aabb childBounds(const PackedScene& p, uint32_t i, int side) {
    const float* f = &p.nodeBounds[size_t(i) * layout::kNodeBoundsTexels].x;
    Aabb b;
    b.lo = glm::vec3(f[6 * side], f[6 * side + 1], f[6 * side + 2]);
    b.hi = glm::vec3(f[6 * side + 3], f[6 * side + 4], f[6 * side + 5]);
    return b;
}

bool contains(const Aabb& outer, const Aabb& inner) {
    return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) &&
           glm::all(glm::greaterThanEqual(outer.hi, inner.hi));
}

Aabb packedTriangleBounds(const PackedScene& p, uint32_t i) {
    const glm::vec4* t = &p.triangles[size_t(i) * layout::kTriangleTexels];
    glm::vec3 v0(t[0]);
    Aabb b;
    b.grow(v0);
    b.grow(v0 + glm::vec3(t[1]));
    b.grow(v0 + glm::vec3(t[2]));
    return b;
}

void walk(const PackedScene& p, uint32_t node, std::vector<int>& visits, uint32_t& nodesSeen) {
    ++nodesSeen;
    ASSERT_LT(node, p.nodeCount);
    for (int side = 0; side < 2; ++side) {
        layout::ChildLink link = layout::decodeChild(p.nodeLinks[node][side]);
        uint32_t first = link.first, count = link.count;
        Aabb box = childBounds(p, node, side);
        if (count > 0) {
            for (uint32_t t = first; t < first + count; ++t) {
                ASSERT_LT(t, p.triangleCount);
                ++visits[t];
                // Bounds are exact copies of the builder's floats; the packed v0 + e is recomputed, so
                // allow one rounding of slack.
                Aabb tb = packedTriangleBounds(p, t);
                glm::vec3 slack = 1e-5f * (glm::abs(tb.lo) + glm::abs(tb.hi));
                tb.lo += slack;
                tb.hi -= slack;
                EXPECT_TRUE(contains(box, tb)) << "node " << node << " side " << side << " triangle " << t;
            }
        } else {
            for (int s = 0; s < 2; ++s) EXPECT_TRUE(contains(box, childBounds(p, first, s)));
            walk(p, first, visits, nodesSeen);
        }
    }
}

TEST(PackScene, EveryTriangleReachableOnceAndBoxesContainTheirContents) {
    for (int n : {1, 3, 4, 5, 100, 2000}) {
        Scene s = randomScene(n, uint32_t(n));
        PackedScene p = packScene(s, buildFor(s));
        ASSERT_EQ(p.triangles.size(), size_t(n) * layout::kTriangleTexels);
        ASSERT_EQ(p.nodeBounds.size(), size_t(p.nodeCount) * layout::kNodeBoundsTexels);
        std::vector<int> visits(size_t(n), 0);
        uint32_t nodesSeen = 0;
        walk(p, 0, visits, nodesSeen);
        EXPECT_EQ(nodesSeen, p.nodeCount) << n << " triangles";
        // A root that is a leaf is stored as a node with the leaf on both sides.
        int expected = p.nodeCount == 1 && p.nodeLinks[0].x == p.nodeLinks[0].y ? 2 : 1;
        for (int v : visits) EXPECT_EQ(v, expected) << n << " triangles";
    }
}

TEST(PackScene, LightCdfIsPowerProportionalAndEndsAtOne) {
    Scene s = randomScene(300, 7);
    PackedScene p = packScene(s, buildFor(s));
    ASSERT_EQ(p.lightCount, 200u);  // materials 1 and 2 emit
    double pmfSum = 0.0, previous = 0.0;
    for (const glm::vec4& light : p.lights) {
        uint32_t tri = uint32_t(light.x);
        ASSERT_EQ(float(tri), light.x) << "exact integer index";
        EXPECT_GT(light.y, previous);
        previous = light.y;
        pmfSum += light.z;
        // The triangle's own texel carries the same pmf, for MIS when a BSDF ray hits it.
        EXPECT_EQ(p.triangles[size_t(tri) * layout::kTriangleTexels + 1].w, light.z);
        int material = int(p.triangles[size_t(tri) * layout::kTriangleTexels].w);
        glm::vec3 e1(p.triangles[size_t(tri) * 3 + 1]), e2(p.triangles[size_t(tri) * 3 + 2]);
        float area = 0.5f * glm::length(glm::cross(e1, e2));
        EXPECT_NEAR(light.w, area, 1e-4f * area);
        float power = luminance(s.materials[size_t(material)].emission) * area;
        EXPECT_NEAR(light.z, power / p.totalLightPower, 1e-5);
    }
    EXPECT_NEAR(pmfSum, 1.0, 1e-5);
    EXPECT_EQ(p.lights.back().y, 1.0f);
}

TEST(PackScene, BytesPerTriangleAreReported) {
    Scene s = randomScene(1000, 3);
    PackedScene p = packScene(s, buildFor(s));
    EXPECT_EQ(p.geometryBytes(), 16 * (p.triangles.size() + p.nodeBounds.size()) + 8 * p.nodeLinks.size());
    EXPECT_GT(p.bytes(), p.geometryBytes());
}

TEST(PackScene, ChildLinksRoundTripAndRefuseWhatTheyCannotHold) {
    for (layout::ChildLink c :
         {layout::ChildLink{0, 0}, layout::ChildLink{12345, 0}, layout::ChildLink{0, 1},
          layout::ChildLink{layout::kMaxLeafFirst, layout::kMaxLeafCount}, layout::ChildLink{777, 3}}) {
        layout::ChildLink d = layout::decodeChild(layout::encodeChild(c));
        EXPECT_EQ(d.first, c.first);
        EXPECT_EQ(d.count, c.count);
    }
    EXPECT_THROW(layout::encodeChild({layout::kMaxLeafFirst + 1, 2}), Error);
    EXPECT_THROW(layout::encodeChild({0, layout::kMaxLeafCount + 1}), Error);
    // Coincident triangles cannot be split, so a builder allowed larger leaves makes one of all of them.
    Scene s = randomScene(1, 5);
    s.triangles.resize(layout::kMaxLeafCount + 1, s.triangles[0]);
    std::vector<Aabb> bounds(s.triangles.size(), s.triangles[0].bounds());
    BvhBuildOptions wide;
    wide.maxLeafSize = int(layout::kMaxLeafCount) + 1;
    EXPECT_THROW(packScene(s, buildBinnedSah(bounds, wide)), Error);
}

TEST(PackScene, MismatchedBvhIsRejected) {
    Scene s = randomScene(10, 1);
    Scene other = randomScene(11, 1);
    EXPECT_THROW(packScene(s, buildFor(other)), Error);
}

}  // namespace
}  // namespace fp
