// The binned SAH builder must give cheaper trees (MacDonald-Booth SAH cost) than the object median.
#include "bvh/bvh_test_util.h"

namespace fp {
namespace {

struct Costs {
    float binned, median;
};

Costs sahCosts(const test::Mesh& mesh) {
    const std::vector<Aabb> bounds = triangleBounds(mesh);
    BvhBuildOptions options;
    Bvh binned = buildBinnedSah(bounds, options), median = buildMedianSplit(bounds, options);
    EXPECT_TRUE(test::checkStructure(binned, bounds, options));
    EXPECT_TRUE(test::checkStructure(median, bounds, options));
    return {computeStats(binned, options).sahCost, computeStats(median, options).sahCost};
}

TEST(SahQuality, BinnedBeatsMedianOnRandomSoup) {
    Costs c = sahCosts(test::randomSoup(20000, 11));
    RecordProperty("binned", std::to_string(c.binned));
    RecordProperty("median", std::to_string(c.median));
    EXPECT_LT(c.binned, c.median);
}

TEST(SahQuality, BinnedBeatsMedianOnSphere) {
    Costs c = sahCosts(test::tessellatedSphere(100, 100));
    RecordProperty("binned", std::to_string(c.binned));
    RecordProperty("median", std::to_string(c.median));
    EXPECT_LT(c.binned, c.median);
}

TEST(SahQuality, BinnedBeatsMedianClearlyOnUnevenDensity) {
    // The median wastes levels cutting the dense cluster while the large sparse triangles keep every
    // such node big; the SAH isolates the cluster, so the gap here is large.
    Costs c = sahCosts(test::unevenDensity(20000, 500, 12));
    RecordProperty("binned", std::to_string(c.binned));
    RecordProperty("median", std::to_string(c.median));
    EXPECT_LT(c.binned, 0.8f * c.median);
}

TEST(SahQuality, MoreBinsDoNotMakeMuchWorseTrees) {
    // Sanity of the bin sweep: 2 bins (centroid-box midpoint only) should not beat 32 bins by much.
    const std::vector<Aabb> bounds = triangleBounds(test::unevenDensity(20000, 500, 13));
    BvhBuildOptions two, many;
    two.binCount = 2;
    many.binCount = 32;
    float costTwo = computeStats(buildBinnedSah(bounds, two), two).sahCost;
    float costMany = computeStats(buildBinnedSah(bounds, many), many).sahCost;
    EXPECT_LT(costMany, 1.05f * costTwo);
}

}  // namespace
}  // namespace fp
