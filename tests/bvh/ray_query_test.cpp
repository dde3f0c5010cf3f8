// Ray-triangle and ray-box tests on hand-worked cases, and BVH traversal against brute force.
#include <cmath>
#include <cstdio>
#include <functional>

#include "bvh/bvh_test_util.h"

namespace fp {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// ---- intersectTriangle -------------------------------------------------------------------------

const TriangleVerts kUnitTri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

RayHit hitTri(const Ray& ray, const TriangleVerts& tri = kUnitTri) {
    RayHit h;
    if (intersectTriangle(ray, tri, h.t, h.u, h.v)) h.prim = 0;
    return h;
}

TEST(IntersectTriangle, FrontAndBackFacesHitWithExactBarycentrics) {
    // pvec = (1,0,0), det = 1, qvec = (0, 1, -0.5): every quantity is exact.
    RayHit front = hitTri({{0.25f, 0.5f, 1.0f}, {0, 0, -1}});
    ASSERT_TRUE(front.hit());
    EXPECT_EQ(front.t, 1.0f);
    EXPECT_EQ(front.u, 0.25f);
    EXPECT_EQ(front.v, 0.5f);
    RayHit back = hitTri({{0.25f, 0.5f, -1.0f}, {0, 0, 1}});  // two-sided
    ASSERT_TRUE(back.hit());
    EXPECT_EQ(back.t, 1.0f);
    EXPECT_EQ(back.u, 0.25f);
    EXPECT_EQ(back.v, 0.5f);
    // t is measured in units of the (unnormalized) direction.
    EXPECT_EQ(hitTri({{0.25f, 0.5f, 1.0f}, {0, 0, -2}}).t, 0.5f);
}

TEST(IntersectTriangle, EdgesAndVerticesAreInside) {
    for (glm::vec2 p : {glm::vec2(0.5f, 0.0f), glm::vec2(0.0f, 0.5f), glm::vec2(0.5f, 0.5f),
                        glm::vec2(0.0f, 0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(0.0f, 1.0f)}) {
        RayHit h = hitTri({{p.x, p.y, 1.0f}, {0, 0, -1}});
        EXPECT_TRUE(h.hit()) << p.x << "," << p.y;
        EXPECT_EQ(h.u, p.x);
        EXPECT_EQ(h.v, p.y);
    }
}

TEST(IntersectTriangle, PointsJustOutsideMiss) {
    for (glm::vec2 p : {glm::vec2(0.5f, -1e-6f), glm::vec2(-1e-6f, 0.5f), glm::vec2(0.5f, 0.5f + 1e-6f),
                        glm::vec2(0.8f, 0.8f), glm::vec2(-1.0f, -1.0f)})
        EXPECT_FALSE(hitTri({{p.x, p.y, 1.0f}, {0, 0, -1}}).hit()) << p.x << "," << p.y;
}

TEST(IntersectTriangle, TIntervalIsOpen) {
    Ray ray{{0.25f, 0.5f, 1.0f}, {0, 0, -1}};  // hits at t = 1 exactly
    ray.tMax = 1.0f;
    EXPECT_FALSE(hitTri(ray).hit());
    ray.tMax = std::nextafter(1.0f, 2.0f);
    EXPECT_TRUE(hitTri(ray).hit());
    ray.tMax = kInf;
    ray.tMin = 1.0f;
    EXPECT_FALSE(hitTri(ray).hit());
    ray.tMin = std::nextafter(1.0f, 0.0f);
    EXPECT_TRUE(hitTri(ray).hit());
    // Behind the origin: t = -1 < tMin = 0.
    EXPECT_FALSE(hitTri({{0.25f, 0.5f, -1.0f}, {0, 0, -1}}).hit());
}

TEST(IntersectTriangle, ParallelDegenerateAndNaNMissAndLeaveOutputsAlone) {
    float t = 7.0f, u = 8.0f, v = 9.0f;
    // In the triangle's plane, and parallel above it: det == 0.
    EXPECT_FALSE(intersectTriangle({{-1.0f, 0.2f, 0.0f}, {1, 0, 0}}, kUnitTri, t, u, v));
    EXPECT_FALSE(intersectTriangle({{-1.0f, 0.2f, 1.0f}, {1, 0, 0}}, kUnitTri, t, u, v));
    // Collinear vertices.
    const TriangleVerts line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    EXPECT_FALSE(intersectTriangle({{0.0f, 1.0f, 0.0f}, {0, -1, 0}}, line, t, u, v));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(intersectTriangle({{0.25f, 0.5f, 1.0f}, {nan, 0, -1}}, kUnitTri, t, u, v));
    EXPECT_FALSE(intersectTriangle({{nan, 0.5f, 1.0f}, {0, 0, -1}}, kUnitTri, t, u, v));
    EXPECT_EQ(t, 7.0f);
    EXPECT_EQ(u, 8.0f);
    EXPECT_EQ(v, 9.0f);
}

TEST(IntersectTriangle, ConfirmedDropsSpuriousHitsOnSlivers) {
    // A pole triangle of a latitude-longitude sphere: p1 and p2 are 1e-8 apart, so det is rounding
    // noise. The ray aims exactly at p0 (true hit at t = 1), but Möller–Trumbore reports t = 1/3, a
    // point more than a unit away from the triangle's box.
    const TriangleVerts sliver{{0x1.5bb0b4p-4f, -0x1.fd88dap-1f, -0x1.917a54p-5f},
                               {-0x1.452c6cp-24f, -0x1p+0f, 0x1.777a5p-25f},
                               {-0x1.5ae57cp-24f, -0x1p+0f, 0x1.1f60dep-25f}};
    const Ray ray{{-0x1.eba1f4p+0f, 0x1.af227p-1f, 0x1.acef4p-2f},
                  {0x1.eba1f6p+0f, -0x1.d79138p+0f, -0x1.acef3ep-2f}};
    RayHit raw = hitTri(ray, sliver);
    ASSERT_TRUE(raw.hit());
    EXPECT_LT(raw.t, 0.5f);
    float t, u, v;
    EXPECT_FALSE(intersectTriangleConfirmed(ray, 1.0f / ray.dir, sliver, t, u, v));
    // Genuine hits are kept, with the same numbers, including ones exactly on an edge of the box.
    for (const Ray& r :
         {Ray{{0.25f, 0.5f, 1.0f}, {0, 0, -1}}, Ray{{0.0f, 0.0f, 1.0f}, {0, 0, -1}},
          Ray{{1.0f, 0.0f, -1.0f}, {0, 0, 1}}, Ray{{-1.0f, -1.0f, 1.0f}, {1.5f, 1.5f, -1.0f}}}) {
        RayHit expected = hitTri(r);
        ASSERT_TRUE(expected.hit());
        ASSERT_TRUE(intersectTriangleConfirmed(r, 1.0f / r.dir, kUnitTri, t, u, v));
        EXPECT_EQ(t, expected.t);
        EXPECT_EQ(u, expected.u);
        EXPECT_EQ(v, expected.v);
    }
}

// ---- slabTest ----------------------------------------------------------------------------------

const Aabb kUnitBox{glm::vec3(0.0f), glm::vec3(1.0f)};

struct SlabResult {
    bool hit;
    float tEnter;
};
SlabResult slab(const Ray& ray, const Aabb& box = kUnitBox) {
    SlabResult r{false, -1.0f};
    r.hit = slabTest(box, ray, 1.0f / ray.dir, ray.tMax, r.tEnter);
    EXPECT_EQ(r.hit, slabTest(box, ray, 1.0f / ray.dir, ray.tMax));
    return r;
}

TEST(SlabTest, AxisAlignedRaysUseInfiniteInverseDirections) {
    SlabResult r = slab({{-1.0f, 0.5f, 0.5f}, {1, 0, 0}});
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(r.tEnter, 1.0f);
    EXPECT_TRUE(slab({{-1.0f, 0.5f, 0.5f}, {1, -0.0f, -0.0f}}).hit);
    EXPECT_FALSE(slab({{-1.0f, 1.5f, 0.5f}, {1, 0, 0}}).hit);      // parallel, above the y slab
    EXPECT_FALSE(slab({{-1.0f, 1.5f, 0.5f}, {1, -0.0f, 0}}).hit);  // same with -0
    EXPECT_FALSE(slab({{-1.0f, -0.5f, 0.5f}, {1, 0, 0}}).hit);     // below
    EXPECT_FALSE(slab({{-1.0f, -0.5f, 0.5f}, {1, -0.0f, 0}}).hit);
    EXPECT_FALSE(slab({{2.0f, 0.5f, 0.5f}, {1, 0, 0}}).hit);  // box behind
    // A zero direction: all distances infinite; only an origin inside counts.
    EXPECT_TRUE(slab({{0.5f, 0.5f, 0.5f}, {0, 0, 0}}).hit);
    EXPECT_FALSE(slab({{-1.0f, 0.5f, 0.5f}, {0, 0, 0}}).hit);
    EXPECT_FALSE(slab({{2.0f, 0.5f, 0.5f}, {0, -0.0f, 0}}).hit);
    r = slab({{2.0f, 0.5f, 0.5f}, {-1, 0, 0}});
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(r.tEnter, 1.0f);
}

TEST(SlabTest, OriginOnASlabPlaneOfAParallelRayCountsAsInside) {
    // (plane - origin) * (1/0) = 0 * inf = NaN on these axes; the closed slab must still pass.
    for (float y : {0.0f, 1.0f})
        for (float dy : {0.0f, -0.0f}) {
            EXPECT_TRUE(slab({{-1.0f, y, 0.5f}, {1, dy, 0}}).hit) << y << " " << dy;
            EXPECT_TRUE(slab({{-1.0f, y, 1.0f}, {1, dy, -0.0f}}).hit) << y << " " << dy;  // along an edge
            EXPECT_TRUE(slab({{y, y, 2.0f}, {0, dy, -1}}).hit) << y << " " << dy;         // down an edge
        }
}

TEST(SlabTest, FlatBoxes) {
    const Aabb flat{{0.0f, 0.0f, 0.5f}, {1.0f, 1.0f, 0.5f}};
    SlabResult r = slab({{0.5f, 0.5f, -1.0f}, {0, 0, 1}}, flat);
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(r.tEnter, 1.5f);
    EXPECT_TRUE(slab({{-1.0f, 0.5f, 0.5f}, {1, 0, 0}}, flat).hit);  // in its plane: both z distances NaN
    EXPECT_FALSE(slab({{-1.0f, 0.5f, 0.6f}, {1, 0, 0}}, flat).hit);
}

TEST(SlabTest, IntervalClipping) {
    SlabResult inside = slab({{0.5f, 0.5f, 0.5f}, {0.3f, -0.2f, 0.9f}});
    EXPECT_TRUE(inside.hit);
    EXPECT_EQ(inside.tEnter, 0.0f);  // starts inside: enters at tMin
    Ray ray{{-1.0f, 0.5f, 0.5f}, {1, 0, 0}};
    ray.tMax = 0.5f;
    EXPECT_FALSE(slab(ray).hit);
    ray.tMax = 1.0f;  // touching the entry face is enough (closed interval)
    EXPECT_TRUE(slab(ray).hit);
    ray.tMax = kInf;
    ray.tMin = 1.5f;
    SlabResult r = slab(ray);
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(r.tEnter, 1.5f);
    ray.tMin = 2.5f;  // past the exit at t = 2
    EXPECT_FALSE(slab(ray).hit);
}

TEST(SlabTest, CornerTouchIsAHitAndANearMissIsNot) {
    // x = 2 - t, y = 1 - t: inside [0,1] in x for t in [1,2] and in y for t in [0,1]; they meet at t = 1.
    EXPECT_TRUE(slab({{2.0f, 1.0f, 0.5f}, {-1, -1, 0}}).hit);
    // y = 0.999 - t leaves [0,1] at t = 0.999, before x enters at t = 1.
    EXPECT_FALSE(slab({{2.0f, 0.999f, 0.5f}, {-1, -1, 0}}).hit);
}

TEST(SlabTest, RoundingNeverCullsABoxTheRayTouches) {
    // Rays aimed at a box corner that meet the closed box in exact arithmetic (checked in 113-bit
    // floating point when these were found by random search) but that an unwidened float test culls.
    struct Case {
        Aabb box;
        Ray ray;
    };
    const Case cases[] = {
        {{{-0x1.41832p-3f, -0x1.ed5d06p-1f, -0x1.a6a358p-3f},
          {0x1.397292p-1f, 0x1.dedabap-1f, 0x1.b288a6p-1f}},
         {{0x1.c4d5dep+1f, -0x1.1bcadp+0f, 0x1.807204p+0f},
          {-0x1.d8ee1p+1f, 0x1.28e268p-3f, -0x1.4e5b62p-1f}}},
        {{{-0x1.f5a908p-2f, -0x1.96c52ap-1f, -0x1.4a44acp-2f},
          {0x1.cb7d0ap-2f, 0x1.aff9c4p-4f, 0x1.de6a4ap-1f}},
         {{-0x1.a089fp-1f, 0x1.ce0dd2p+1f, -0x1.84e03p+0f},
          {0x1.43243ap+0f, -0x1.c08e04p+1f, 0x1.3a0aaap+1f}}},
        {{{-0x1.d8ee6ap-1f, -0x1.df1998p-3f, -0x1.455cd8p-1f},
          {0x1.98496p-1f, 0x1.57ef5ap-2f, 0x1.252106p-1f}},
         {{0x1.bf9f2ep+1f, 0x1.e9e11p+0f, 0x1.51d594p-2f},
          {-0x1.598cd6p+1f, -0x1.93e53ap+0f, 0x1.f0d8fp-3f}}},
    };
    for (const Case& c : cases) EXPECT_TRUE(slab(c.ray, c.box).hit);
}

// ---- closestHit against brute force ------------------------------------------------------------

enum Category { kOutsideIn, kInside, kAtVertex, kAtEdge, kAxisAligned, kAxisToVertex, kOnNodePlane, kCount };
const char* const kCategoryNames[] = {"outsideIn",   "inside",       "atVertex",   "atEdge",
                                      "axisAligned", "axisToVertex", "onNodePlane"};

struct TestRay {
    Ray ray;
    Category category;
};

// `perCategory` rays of each kind; a quarter of them then get a tMin/tMax window, placed around the
// unclipped nearest hit when there is one (including windows ending or starting exactly at it).
std::vector<TestRay> makeRays(const test::Mesh& mesh, const Bvh& bvh, int perCategory, uint32_t seed) {
    std::mt19937 rng(seed);
    Aabb box;
    for (const TriangleVerts& t : mesh) box.grow(t.bounds());
    const float reach = std::max(glm::length(box.extent()), 1.0f);
    const Aabb around{box.lo - reach, box.hi + reach};
    auto vertex = [&]() {
        const TriangleVerts& t = mesh[test::uniformIndex(rng, mesh.size())];
        const uint32_t k = test::uniformIndex(rng, 3);
        return k == 0 ? t.p0 : k == 1 ? t.p1 : t.p2;
    };
    auto signedZero = [&]() { return rng() & 1 ? 0.0f : -0.0f; };
    auto sign = [&]() { return rng() & 1 ? 1.0f : -1.0f; };

    std::vector<TestRay> rays;
    for (int c = 0; c < kCount; ++c)
        for (int i = 0; i < perCategory; ++i) {
            Ray ray;
            switch (Category(c)) {
                case kOutsideIn:
                    ray.origin = test::uniformIn(rng, around);
                    ray.dir = test::uniformIn(rng, box) - ray.origin;
                    break;
                case kInside:
                    ray.origin = test::uniformIn(rng, box);
                    ray.dir = test::unitVector(rng);
                    break;
                case kAtVertex:
                    ray.origin = test::uniformIn(rng, i % 2 ? around : box);
                    ray.dir = vertex() - ray.origin;
                    break;
                case kAtEdge: {
                    ray.origin = test::uniformIn(rng, i % 2 ? around : box);
                    const TriangleVerts& t = mesh[test::uniformIndex(rng, mesh.size())];
                    const glm::vec3 a = i % 3 == 0 ? t.p0 : i % 3 == 1 ? t.p1 : t.p2;
                    const glm::vec3 b = i % 3 == 0 ? t.p1 : i % 3 == 1 ? t.p2 : t.p0;
                    const float s = i % 4 == 0 ? 0.5f : test::uniform01(rng);  // midpoints, or anywhere
                    ray.dir = a + s * (b - a) - ray.origin;
                    break;
                }
                case kAxisAligned: {
                    ray.origin = test::uniformIn(rng, box);
                    const uint32_t axis = test::uniformIndex(rng, 3);
                    ray.dir = {signedZero(), signedZero(), signedZero()};
                    ray.dir[axis] = sign();
                    if (i % 2) ray.dir[(axis + 1) % 3] = test::uniform(rng, -1, 1);  // one zero only
                    break;
                }
                case kAxisToVertex: {
                    // Straight along an axis onto a vertex: exact hits on vertices and edges, and
                    // (for the grid) origins on node planes in the other two axes.
                    const uint32_t axis = test::uniformIndex(rng, 3);
                    const float s = sign();
                    ray.origin = vertex();
                    ray.origin[axis] += s * test::uniform(rng, 0.1f, reach);
                    ray.dir = {signedZero(), signedZero(), signedZero()};
                    ray.dir[axis] = -s;
                    break;
                }
                case kOnNodePlane: {
                    // Parallel to, and exactly on, one face plane of a random node's box.
                    const BvhNode& node = bvh.nodes[test::uniformIndex(rng, bvh.nodes.size())];
                    const uint32_t axis = test::uniformIndex(rng, 3);
                    ray.origin = test::uniformIn(rng, around);
                    ray.origin[axis] = rng() & 1 ? node.bounds.lo[axis] : node.bounds.hi[axis];
                    ray.dir = test::uniformIn(rng, box) - ray.origin;
                    ray.dir[axis] = signedZero();
                    break;
                }
                case kCount:
                    break;
            }
            if (i % 4 == 3) {
                const float t = closestHitBruteForce(mesh, ray).t;
                const float scale = std::isfinite(t) ? t : 1.0f;
                switch (i / 4 % 4) {
                    case 0:
                        ray.tMax = scale;
                        break;  // excludes that hit
                    case 1:
                        ray.tMin = scale;
                        break;  // excludes it too
                    case 2:
                        ray.tMax = scale * test::uniform(rng, 0.5f, 1.5f);
                        break;
                    case 3:
                        ray.tMin = scale * test::uniform(rng, 0.0f, 1.0f);
                        break;
                }
            }
            rays.push_back({ray, Category(c)});
        }
    return rays;
}

std::string describe(const Ray& r) {
    char s[256];
    std::snprintf(s, sizeof s, "origin (%a, %a, %a) dir (%a, %a, %a) t in (%a, %a)", r.origin.x, r.origin.y,
                  r.origin.z, r.dir.x, r.dir.y, r.dir.z, r.tMin, r.tMax);
    return s;
}

// Same t as brute force; the reported primitive really is hit there with the reported u, v.
::testing::AssertionResult agrees(const Bvh& bvh, const test::Mesh& mesh, const std::vector<TestRay>& rays,
                                  const std::vector<RayHit>& expected, size_t& hits) {
    size_t failures = 0;
    std::string first;
    for (size_t i = 0; i < rays.size(); ++i) {
        const Ray& ray = rays[i].ray;
        const RayHit got = closestHit(bvh, mesh, ray);
        bool ok = got.t == expected[i].t && got.hit() == expected[i].hit();
        if (ok && got.hit()) {
            hits++;
            RayHit again = hitTri(ray, mesh[got.prim]);
            ok = again.hit() && again.t == got.t && again.u == got.u && again.v == got.v;
        }
        if (!ok && failures++ == 0)
            first = std::string(kCategoryNames[rays[i].category]) + " ray " + describe(ray) + ": bvh t " +
                    std::to_string(got.t) + " prim " + std::to_string(got.prim) + ", brute force t " +
                    std::to_string(expected[i].t) + " prim " + std::to_string(expected[i].prim);
    }
    if (failures == 0) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << failures << " of " << rays.size() << " rays disagree; first: " << first;
}

TEST(ClosestHit, MatchesBruteForceOnEveryMeshAndBuilder) {
    uint32_t seed = 100;
    for (const test::NamedMesh& m : test::testMeshes()) {
        if (m.mesh.empty()) continue;
        const AabbArray bounds = triangleBounds(m.mesh);
        const Bvh reference = buildBinnedSah(bounds);
        const std::vector<TestRay> rays = makeRays(m.mesh, reference, 400, seed++);
        std::vector<RayHit> expected;
        for (const TestRay& r : rays) expected.push_back(closestHitBruteForce(m.mesh, r.ray));
        for (const test::NamedBuilder& b : test::builders())
            for (int maxLeafSize : {1, 4}) {
                SCOPED_TRACE(m.name + " " + b.name + " maxLeafSize=" + std::to_string(maxLeafSize));
                BvhBuildOptions options;
                options.maxLeafSize = maxLeafSize;
                size_t hits = 0;
                EXPECT_TRUE(agrees(b.build(bounds, options), m.mesh, rays, expected, hits));
                // Not vacuous: a fair share of the rays hit something (slivers are hit least).
                EXPECT_GT(hits, rays.size() / 10);
            }
    }
}

TEST(ClosestHit, EmptyBvhAndEmptyMeshMiss) {
    const Ray ray{{0, 0, -1}, {0, 0, 1}};
    EXPECT_FALSE(closestHit(Bvh{}, {}, ray).hit());
    EXPECT_EQ(closestHit(Bvh{}, {}, ray).t, kInf);
    EXPECT_FALSE(closestHitBruteForce({}, ray).hit());
}

TEST(ClosestHit, BruteForceBreaksTiesByLowestIndexAndBvhByAnyTiedPrimitive) {
    const test::Mesh mesh = test::identicalTriangles(10);
    const Bvh bvh = buildBinnedSah(triangleBounds(mesh));
    const Ray ray{{0.2f, 0.2f, 5.0f}, {0, 0, -1}};
    const RayHit brute = closestHitBruteForce(mesh, ray);
    EXPECT_EQ(brute.prim, 0u);
    const RayHit got = closestHit(bvh, mesh, ray);
    EXPECT_TRUE(got.hit());
    EXPECT_EQ(got.t, brute.t);
}

// A hand-built chain: node(k) = interior over primitives k..n-1, with node(k+1) as its left child
// and primitive k's leaf as its right child. A ray down -x meets node(k+1) first, so the traversal
// pushes every leaf: deeper than the 64 entries the stack holds without allocating.
struct Chain {
    test::Mesh mesh;
    Bvh bvh;
};
Chain makeChain(int n, bool bigFirst) {
    Chain c;
    for (int k = 0; k < n; ++k) {
        // In the plane x = k + y + z, inside [k, k+1] x [0,1] x [0,1], covering y + z <= 1. With
        // bigFirst, primitive 0 is twice as large and also covers y = z = 0.9.
        const float s = k == 0 && bigFirst ? 2.0f : 1.0f;
        c.mesh.push_back({{float(k), 0, 0}, {k + s, s, 0}, {k + s, 0, s}});
    }
    c.bvh.primIndex.resize(n);
    std::function<uint32_t(int)> emit = [&](int k) -> uint32_t {  // returns the node index
        const auto index = uint32_t(c.bvh.nodes.size());
        if (k == n - 1) {
            c.bvh.primIndex[k] = k;
            c.bvh.nodes.push_back({c.mesh[k].bounds(), uint32_t(k), 1});
            return index;
        }
        c.bvh.nodes.push_back({});
        emit(k + 1);
        const uint32_t right = uint32_t(c.bvh.nodes.size());
        c.bvh.primIndex[k] = k;
        c.bvh.nodes.push_back({c.mesh[k].bounds(), uint32_t(k), 1});
        Aabb b = c.bvh.nodes[index + 1].bounds;
        b.grow(c.bvh.nodes[right].bounds);
        c.bvh.nodes[index] = {b, right, 0};
        return index;
    };
    emit(0);
    return c;
}

TEST(ClosestHit, TraversesTreesDeeperThanItsFixedStack) {
    // Leaf ranges here are not in depth-first order, which closestHit does not need; everything else
    // is the documented layout.
    const Chain plain = makeChain(100, false);
    EXPECT_EQ(computeStats(plain.bvh).maxDepth, 99u);
    // Misses every triangle but crosses every box: all nodes visited, every primitive tested.
    TraversalCounters counters;
    const Ray miss{{200.0f, 0.9f, 0.9f}, {-1, 0, 0}};
    EXPECT_FALSE(closestHit(plain.bvh, plain.mesh, miss, &counters).hit());
    EXPECT_EQ(counters.nodesVisited, plain.bvh.nodes.size());
    EXPECT_EQ(counters.trianglesTested, 100u);
    // Only primitive 0, the first leaf pushed (bottom of the stack), is hit.
    const Chain c = makeChain(100, true);
    const Ray deepest{{200.0f, 0.9f, 0.9f}, {-1, 0, 0}};
    const RayHit hit = closestHit(c.bvh, c.mesh, deepest);
    EXPECT_EQ(hit.prim, 0u);
    EXPECT_EQ(hit.t, closestHitBruteForce(c.mesh, deepest).t);
    // Every primitive is hit at y = z = 0.2; the nearest from +x is the last one.
    const Ray all{{200.0f, 0.2f, 0.2f}, {-1, 0, 0}};
    EXPECT_EQ(closestHit(c.bvh, c.mesh, all).prim, 99u);
    EXPECT_EQ(closestHit(c.bvh, c.mesh, {{-10.0f, 0.2f, 0.2f}, {1, 0, 0}}).prim, 0u);
}

TEST(ClosestHit, CullsMostTrianglesAndVisitsTheNearerChildFirst) {
    const test::Mesh mesh = test::tessellatedSphere(100, 100);  // 20000 triangles
    const Bvh bvh = buildBinnedSah(triangleBounds(mesh));
    std::mt19937 rng(21);
    TraversalCounters counters;
    const int rays = 2000;
    for (int i = 0; i < rays; ++i) {
        Ray ray{3.0f * test::unitVector(rng), glm::vec3(0.0f)};
        ray.dir = 0.5f * test::unitVector(rng) - ray.origin;  // towards the sphere's inside
        ASSERT_TRUE(closestHit(bvh, mesh, ray, &counters).hit());
    }
    // A sphere seen from outside: nearer-first traversal finds the front hit and culls the back half,
    // so each ray tests a handful of triangles out of 20000. (Measured 2.7 and 19.5; always taking the
    // left child first gives 4.2 and 30.2, the farther child first 5.8 and 41.5.)
    const double tested = double(counters.trianglesTested) / rays,
                 visited = double(counters.nodesVisited) / rays;
    RecordProperty("trianglesTestedPerRay", std::to_string(tested));
    RecordProperty("nodesVisitedPerRay", std::to_string(visited));
    EXPECT_LT(tested, 3.5);
    EXPECT_LT(visited, 25.0);
}

}  // namespace
}  // namespace fp
