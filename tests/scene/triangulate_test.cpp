// Polygon triangulation: winding kept, area covered exactly once, no slivers.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/triangulate.h"

namespace fp {
namespace {

using Polygon = std::vector<glm::dvec3>;

// Sum of signed areas along `normal`; equals the polygon's area iff the triangles cover it once and
// all keep its winding.
double signedArea(const Polygon& p, const std::vector<std::array<uint32_t, 3>>& tris,
                  const glm::dvec3& normal) {
    double area = 0.0;
    for (const auto& t : tris) {
        double a = 0.5 * glm::dot(glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]), normal);
        EXPECT_GT(a, 0.0) << "triangle " << t[0] << " " << t[1] << " " << t[2] << " is flipped or flat";
        area += a;
    }
    return area;
}

TEST(Triangulate, Degeneracy) {
    EXPECT_FALSE(isDegenerate({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    EXPECT_TRUE(isDegenerate({0, 0, 0}, {1, 1, 1}, {2, 2, 2}));
    EXPECT_TRUE(isDegenerate({0, 0, 0}, {0, 0, 0}, {0, 1, 0}));
    EXPECT_TRUE(isDegenerate({1, 1, 1}, {1, 1, 1}, {1, 1, 1}));
    EXPECT_TRUE(isDegenerate({0, 0, 0}, {1e6, 0, 0}, {2e6, 1e-3, 0}));  // a needle
    EXPECT_FALSE(isDegenerate({0, 0, 0}, {1e-6, 0, 0}, {0, 1e-6, 0}));  // tiny but well shaped
    EXPECT_FALSE(isDegenerate({1e7, 1e7, 0}, {1e7 + 1, 1e7, 0}, {1e7, 1e7 + 1, 0}));
    EXPECT_TRUE(isDegenerate({NAN, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    EXPECT_TRUE(isDegenerate({1e308, 0, 0}, {-1e308, 0, 0}, {0, 1e308, 0}));
}

TEST(Triangulate, TriangleAsIs) {
    Polygon p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    auto tris = triangulate(p);
    ASSERT_EQ(tris.size(), 1u);
    EXPECT_EQ(tris[0], (std::array<uint32_t, 3>{0, 1, 2}));
    EXPECT_TRUE(triangulate({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}).empty());
}

TEST(Triangulate, ConvexKeepsWinding) {
    Polygon square{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};  // clockwise seen from +z
    auto tris = triangulate(square);
    EXPECT_EQ(tris.size(), 2u);
    EXPECT_DOUBLE_EQ(signedArea(square, tris, {0, 0, -1}), 1.0);
}

TEST(Triangulate, ConcavePolygons) {
    // An arrow head whose first corner is reflex, and a comb (several reflex corners) in the yz plane.
    Polygon arrow{{1, 1, 0}, {0, 3, 0}, {0, 0, 0}, {3, 0, 0}};
    auto tris = triangulate(arrow);
    EXPECT_EQ(tris.size(), 2u);
    EXPECT_NEAR(signedArea(arrow, tris, {0, 0, 1}), 3.0, 1e-12);

    Polygon comb{{0, 0, 0}, {0, 5, 0}, {0, 5, 2}, {0, 4, 2}, {0, 4, 1}, {0, 3, 1},
                 {0, 3, 2}, {0, 2, 2}, {0, 2, 1}, {0, 1, 1}, {0, 1, 2}, {0, 0, 2}};
    tris = triangulate(comb);
    EXPECT_EQ(tris.size(), comb.size() - 2);
    EXPECT_NEAR(signedArea(comb, tris, {1, 0, 0}), 5.0 + 3.0, 1e-12);
}

TEST(Triangulate, FlatCornersAndRepeatsSkipped) {
    Polygon p{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 2, 0}, {0, 2, 0}};
    auto tris = triangulate(p);
    EXPECT_EQ(tris.size(), 2u);
    EXPECT_NEAR(signedArea(p, tris, {0, 0, 1}), 4.0, 1e-12);
    EXPECT_TRUE(triangulate({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}).empty());
    EXPECT_TRUE(triangulate({{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {1, 0, 0}}).empty());
}

}  // namespace
}  // namespace fp
