// The binned builder gives the same tree, bit for bit, for any thread count, and the same tree as the
// single-threaded builder it replaced, so that images do not change.
#include <cmath>
#include <cstring>

#include "bvh/bvh_test_util.h"
#include "pack/layout.h"
#include "scene/procedural.h"

namespace fp {
namespace {

// FNV-1a over every node field and primIndex entry, 32 bits at a time (float bits as they are).
uint64_t digest(const Bvh& bvh) {
    uint64_t h = 14695981039346656037ull;
    auto mix = [&h](uint32_t word) {
        for (int byte = 0; byte < 4; ++byte) {
            h ^= (word >> (8 * byte)) & 0xffu;
            h *= 1099511628211ull;
        }
    };
    auto mixFloat = [&mix](float f) {
        uint32_t bits;
        std::memcpy(&bits, &f, sizeof bits);
        mix(bits);
    };
    for (const BvhNode& n : bvh.nodes) {
        for (int a = 0; a < 3; ++a) mixFloat(n.bounds.lo[a]);
        for (int a = 0; a < 3; ++a) mixFloat(n.bounds.hi[a]);
        mix(n.first);
        mix(n.count);
    }
    for (uint32_t p : bvh.primIndex) mix(p);
    return h;
}

::testing::AssertionResult sameBits(const Bvh& a, const Bvh& b) {
    if (a.primIndex != b.primIndex) return ::testing::AssertionFailure() << "primIndex differs";
    if (a.nodes.size() != b.nodes.size())
        return ::testing::AssertionFailure() << a.nodes.size() << " nodes against " << b.nodes.size();
    for (size_t i = 0; i < a.nodes.size(); ++i)
        if (std::memcmp(&a.nodes[i], &b.nodes[i], sizeof(BvhNode)) != 0)
            return ::testing::AssertionFailure() << "node " << i << " differs";
    return ::testing::AssertionSuccess();
}

// Large enough that two or more threads split the top of the tree apart from the subtree jobs.
std::vector<test::NamedMesh> largeMeshes() {
    // Signed zeros as the lowest y of the scene and of most nodes: min and max of +0 and -0 depend on the
    // order they are met in, so partial bounds must be merged in index order for the bits to match. Runs
    // of 7 of each sign, over more than one chunk of binning.
    test::Mesh zeros = test::randomSoup(40000, 31);
    for (size_t i = 0; i < zeros.size(); ++i) {
        zeros[i].p0.y = (i / 7) % 2 ? 0.0f : -0.0f;
        zeros[i].p1.y = std::abs(zeros[i].p1.y);
        zeros[i].p2.y = std::abs(zeros[i].p2.y);
    }
    return {
        {"randomSoup", test::randomSoup(30000, 21)},     {"uneven", test::unevenDensity(20000, 500, 22)},
        {"coincidentGrid", test::coincidentGrid(40, 4)}, {"slivers", test::sliverSoup(10000, 23)},
        {"identical", test::identicalTriangles(10000)},  {"signedZeros", zeros},
    };
}

TEST(ParallelBuild, SameTreeForAnyThreadCount) {
    for (const test::NamedMesh& m : largeMeshes()) {
        const AabbArray bounds = triangleBounds(m.mesh);
        BvhBuildOptions options;
        options.threadCount = 1;
        const Bvh one = buildBinnedSah(bounds, options);
        ASSERT_TRUE(test::checkStructure(one, bounds, options)) << m.name;
        for (int threads : {2, 3, 8}) {
            options.threadCount = threads;
            EXPECT_TRUE(sameBits(buildBinnedSah(bounds, options), one))
                << m.name << ", " << threads << " threads";
        }
    }
}

TEST(ParallelBuild, SameTreeForAnyThreadCountInTheRoom) {
    // The walls around the sphere and the soup are split off by exact planes at large primitives
    // (large_prim_planes.h) in the top nodes, which two or more threads search and evaluate in chunks.
    for (const Scene& scene : {benchmarkSphereScene(100000), randomTriangleSoup(100000, 1)}) {
        AabbArray bounds;
        for (const Triangle& t : scene.triangles) bounds.push_back(t.bounds());
        for (BvhBuildOptions options : {BvhBuildOptions{}, layout::bvhOptions()}) {
            options.threadCount = 1;
            const Bvh one = buildBinnedSah(bounds, options);
            ASSERT_TRUE(test::checkStructure(one, bounds, options)) << scene.triangles.size();
            for (int threads : {2, 3, 8}) {
                options.threadCount = threads;
                EXPECT_TRUE(sameBits(buildBinnedSah(bounds, options), one))
                    << scene.triangles.size() << " triangles, " << threads << " threads";
            }
        }
    }
}

TEST(ParallelBuild, SameTreeWhenTheTopNodesBecomeLeaves) {
    // Traversal so expensive that the root is a leaf, reached through the multithreaded path.
    const AabbArray bounds = triangleBounds(test::randomSoup(20000, 24));
    BvhBuildOptions options;
    options.maxLeafSize = 1 << 20;
    options.traversalCost = 1e9f;
    options.threadCount = 2;
    const Bvh two = buildBinnedSah(bounds, options);
    ASSERT_EQ(two.nodes.size(), 1u);
    options.threadCount = 1;
    EXPECT_TRUE(sameBits(two, buildBinnedSah(bounds, options)));
}

TEST(ParallelBuild, SameTreeAsTheSingleThreadedBuilderItReplaced) {
    // Digests of the trees that buildBinnedSah built at commit a330d72, before it had threads. The meshes
    // use only mt19937 and sqrt, so they are the same on every platform.
    const std::vector<std::pair<std::string, uint64_t>> before = {
        {"randomSoup", 0xe8e486d17daddcc9ull},     {"uneven", 0x27f6055109b7c39bull},
        {"coincidentGrid", 0x4cd41d5bb8900a17ull}, {"slivers", 0x5565ef3bfb9be07dull},
        {"identical", 0xc950a21b1a67b9fdull},      {"signedZeros", 0x46ceddbd108b1939ull},
    };
    const std::vector<test::NamedMesh> meshes = largeMeshes();
    ASSERT_EQ(meshes.size(), before.size());
    for (size_t i = 0; i < meshes.size(); ++i) {
        ASSERT_EQ(meshes[i].name, before[i].first);
        const AabbArray bounds = triangleBounds(meshes[i].mesh);
        for (int threads : {1, 2}) {
            BvhBuildOptions options;
            options.threadCount = threads;
            EXPECT_EQ(digest(buildBinnedSah(bounds, options)), before[i].second)
                << meshes[i].name << ", " << threads << " threads";
        }
    }
}

TEST(ParallelBuild, NegativeThreadCountThrows) {
    BvhBuildOptions options;
    options.threadCount = -1;
    EXPECT_THROW(buildBinnedSah(triangleBounds(test::randomSoup(10, 1)), options), std::invalid_argument);
}

}  // namespace
}  // namespace fp
