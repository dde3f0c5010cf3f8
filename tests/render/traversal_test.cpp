// The GLSL BVH traversal against brute force on the CPU: the depth view of a few thousand random
// triangles (a deep tree) must show, pixel for pixel, the distance a CPU brute-force search finds.
#include <gtest/gtest.h>

#include <random>

#include "bvh/ray_query.h"
#include "core/error.h"
#include "gpu/layout_defines.h"
#include "render_test_util.h"

namespace fp::test {
namespace {

Scene randomSoup(int count, float size, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Scene s;
    s.source = "random soup";
    s.materials.resize(1);
    while (int(s.triangles.size()) < count) {
        Triangle t;
        glm::vec3 c(u(rng), u(rng), u(rng));
        for (auto& p : t.p) p = c + size * glm::vec3(u(rng), u(rng), u(rng));
        if (t.area() < 1e-6f) continue;
        glm::vec3 n = glm::normalize(t.geometricNormal());
        t.n = {n, n, n};
        s.triangles.push_back(t);
    }
    return s;
}

// The primary ray through the centre of pixel (x, row) as glsl/common/camera.glsl builds it.
fp::Ray pixelRay(const Camera& c, int x, int row, int size) {
    glm::vec3 forward = glm::normalize(c.target - c.eye);
    glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    glm::vec3 up = glm::cross(right, forward);
    float tanHalf = std::tan(0.5f * glm::radians(c.fovY));
    int glY = size - 1 - row;  // images are stored top row first, GL counts from the bottom
    glm::vec2 ndc = 2.0f * (glm::vec2(x, glY) + 0.5f) / float(size) - 1.0f;
    fp::Ray r;
    r.origin = c.eye;
    r.dir = glm::normalize(forward + ndc.x * tanHalf * right + ndc.y * tanHalf * up);
    return r;
}

void expectDepthMatchesBruteForce(const Scene& scene, const Camera& camera) {
    ensureGlContext();
    const int size = 64;
    Renderer renderer(scene, testShaders());
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.view = View::Depth;
    renderer.configure(settings, camera);
    renderer.render(1);
    Image depth = renderer.readback().mean();

    std::vector<TriangleVerts> tris;
    for (const Triangle& t : scene.triangles) tris.push_back({t.p[0], t.p[1], t.p[2]});
    int hits = 0, mismatches = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            RayHit h = closestHitBruteForce(tris, pixelRay(camera, x, y, size));
            float expected = h.hit() ? h.t : 0.0f;
            hits += h.hit();
            // The GPU evaluates the same formulas in a different order: allow float rounding.
            if (std::abs(depth.at(x, y).x - expected) > 1e-4f * std::max(1.0f, expected)) ++mismatches;
        }
    EXPECT_GT(hits, size * size / 2) << "the view should be mostly covered";
    // A ray that grazes an edge can go either way by a rounding; a traversal bug loses whole subtrees.
    EXPECT_LE(mismatches, size * size / 400) << mismatches << " of " << size * size << " pixels differ";
    EXPECT_EQ(renderer.stats().triangles, scene.triangles.size());
}

TEST(GpuTraversal, DeepTreeOfSmallTrianglesMatchesBruteForce) {
    Camera c;
    c.eye = glm::vec3(0.3f, 0.2f, -4.0f);
    c.fovY = 35.0f;
    expectDepthMatchesBruteForce(randomSoup(4000, 0.08f, 1), c);
}

TEST(GpuTraversal, PanesBehindACloudOfSpecksAreFoundDeepInTheStack) {
    // Rays cross a cloud of tiny triangles, entering many boxes and hitting few, before a stack of
    // small panes at staggered depths: the panes' subtrees wait at every depth of the stack while the
    // cloud's are visited, so a stack that drops or mixes up any of its entries loses panes
    // (intersect.glsl, shiftStack).
    Scene s = randomSoup(6000, 0.004f, 5);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int k = 0; k < 400; ++k) {
        glm::vec3 c(u(rng), u(rng), 1.2f + 0.5f * u(rng));
        Triangle t;
        t.p = {c + glm::vec3(-0.15f, -0.1f, 0.0f), c + glm::vec3(0.15f, -0.1f, 0.02f),
               c + glm::vec3(0.0f, 0.15f, -0.02f)};
        glm::vec3 n = glm::normalize(t.geometricNormal());
        t.n = {n, n, n};
        s.triangles.push_back(t);
    }
    Camera c;
    c.eye = glm::vec3(0.1f, 0.05f, -4.0f);
    c.fovY = 30.0f;
    expectDepthMatchesBruteForce(s, c);
}

TEST(GpuTraversal, OverlappingLongTrianglesFromInsideMatchBruteForce) {
    // Large overlapping triangles make every box overlap its siblings: both children must be visited.
    Camera c;
    c.eye = glm::vec3(0.05f, -0.1f, 0.02f);
    c.target = glm::vec3(1.0f, 0.3f, 0.5f);
    c.fovY = 90.0f;
    expectDepthMatchesBruteForce(randomSoup(600, 0.9f, 2), c);
}

TEST(GpuTraversal, SmallTrianglesFarFromTheOriginMatchBruteForce) {
    // Quantised boxes (pack/quantised_node.h) on nodes whose coordinates are 10^4 times their size:
    // the plane distances are differences of large terms, which the quantiser's margin must cover.
    Scene s = randomSoup(3000, 0.08f, 3);
    const glm::vec3 offset(4000.0f, -3000.0f, 2500.0f);
    for (Triangle& t : s.triangles)
        for (glm::vec3& p : t.p) p = offset + 0.25f * p;
    Camera c;
    c.eye = offset + glm::vec3(0.05f, 0.1f, -0.8f);
    c.target = offset;
    c.fovY = 35.0f;
    expectDepthMatchesBruteForce(s, c);
}

TEST(GpuTraversal, TheStackHoldsWhatTheTreeNeedsAndRefusesTreesThatNeedTooMuch) {
    // The shader shifts every entry at every node visit, so the stack is as deep as the tree needs
    // (WideBvh::stackEntries), no deeper; a tree it cannot hold is an error, not lost subtrees.
    EXPECT_EQ(layout::traversalStackEntries(0), 4u);
    EXPECT_EQ(layout::traversalStackEntries(3), 4u);
    EXPECT_EQ(layout::traversalStackEntries(30), 30u);
    EXPECT_EQ(layout::traversalStackEntries(layout::kMaxTraversalStack), layout::kMaxTraversalStack);
    EXPECT_THROW(layout::traversalStackEntries(layout::kMaxTraversalStack + 1), Error);
}

TEST(GpuTraversal, EmptyChildSlotsAreNeverEntered) {
    // One triangle: the root has one leaf child and three empty slots. An entered empty slot would
    // push its link 0, the root, so some ray would count more than the one node.
    ensureGlContext();
    Scene s = randomSoup(1, 0.5f, 4);
    s.triangles[0].p = {glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(1.0f, -1.0f, 0.0f),
                        glm::vec3(0.0f, 1.0f, 0.0f)};
    Camera c;
    c.eye = glm::vec3(0.0f, 0.0f, -3.0f);
    c.target = glm::vec3(0.0f);
    c.fovY = 60.0f;
    Renderer renderer(s, testShaders());
    RenderSettings settings;
    settings.width = settings.height = 32;
    settings.view = View::Nodes;
    renderer.configure(settings, c);
    renderer.render(1);
    Image nodes = renderer.readback().mean();
    for (const glm::vec3& p : nodes.pixels) ASSERT_EQ(p.x, 1.0f);
}

}  // namespace
}  // namespace fp::test
