// The native reference's traversal (native/native_trace.h, the shader's visit order) against the
// binary tree's closest hit (bvh/ray_query.h): the same nearest hit for random rays, and any-hit
// queries that agree with it. The visit order must never change which hit is nearest.
#include <gtest/gtest.h>

#include "../bvh/bvh_test_util.h"
#include "pack/layout.h"
#include "native/native_trace.h"

namespace fp::test {
namespace {

fp::Scene sceneOf(const Mesh& mesh) {
    fp::Scene s;
    s.source = "test mesh";
    s.materials.resize(1);
    for (const TriangleVerts& v : mesh) {
        Triangle t;
        t.p = {v.p0, v.p1, v.p2};
        glm::vec3 g = glm::cross(v.p1 - v.p0, v.p2 - v.p0);
        glm::vec3 n = glm::length(g) > 0.0f ? glm::normalize(g) : glm::vec3(0.0f, 0.0f, 1.0f);
        t.n = {n, n, n};
        s.triangles.push_back(t);
    }
    return s;
}

TEST(NativeTraverse, ClosestAndAnyHitAgreeWithTheBinaryTree) {
    for (const NamedMesh& m : testMeshes()) {
        // Slivers: the binary reference drops the spurious hits Moller-Trumbore reports on them
        // (intersectTriangleConfirmed), which the shader and native reference do not.
        if (m.mesh.empty() || m.name == "slivers") continue;
        native::Scene prepared = native::buildScene(sceneOf(m.mesh), layout::bvhOptions());
        Bvh bvh = buildBinnedSah(triangleBounds(m.mesh), layout::bvhOptions());
        Aabb box;
        for (const TriangleVerts& t : m.mesh) box.grow(t.bounds());
        glm::vec3 margin = 0.2f * (box.hi - box.lo) + glm::vec3(1e-3f);
        Aabb origins{box.lo - margin, box.hi + margin};
        std::mt19937 rng(17);
        int hits = 0;
        for (int r = 0; r < 1500; ++r) {
            glm::vec3 origin = uniformIn(rng, origins);
            // Half the rays aim at a triangle, so that most of them hit something.
            glm::vec3 dir = r % 2
                                ? unitVector(rng)
                                : glm::normalize(m.mesh[uniformIndex(rng, m.mesh.size())].bounds().center() -
                                                 origin + 1e-3f * unitVector(rng));
            RayHit expected = closestHit(bvh, m.mesh, Ray{origin, dir});
            native::Hit hit;
            bool found = native::traverse(prepared, {origin, dir}, native::kInf, false, hit);
            ASSERT_EQ(found, expected.hit()) << m.name << " ray " << r;
            if (!found) continue;
            ++hits;
            // The two triangle tests round differently (the reference's edges are precomputed), by a few
            // ulps of the hit's coordinates; the nearest hit of another triangle would differ by more.
            EXPECT_NEAR(hit.t, expected.t, 1e-4f * expected.t) << m.name << " ray " << r;
            // Any hit: something before just past the nearest hit, and, just before it, exactly what
            // the binary tree finds there.
            native::Hit any;
            EXPECT_TRUE(native::traverse(prepared, {origin, dir}, expected.t * 1.001f, true, any));
            float shorter = expected.t * 0.999f;
            Ray clipped{origin, dir};
            clipped.tMax = shorter;
            EXPECT_EQ(native::traverse(prepared, {origin, dir}, shorter, true, any),
                      closestHit(bvh, m.mesh, clipped).hit())
                << m.name << " ray " << r;
        }
        EXPECT_GT(hits, 300) << m.name;
    }
}

}  // namespace
}  // namespace fp::test
