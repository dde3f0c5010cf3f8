#pragma once
// Splitting OBJ polygons into triangles that keep the polygon's winding, so front faces stay front.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace fp {

// Whether p0, p1, p2 span no area worth keeping: coincident or (nearly) collinear points, a needle or
// a point. Measured relative to the longest edge so the test does not depend on the scene's scale. Such
// triangles have no reliable normal.
bool isDegenerate(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2);

// Sets *out to the unit vector along v; false if v has no usable direction (zero, NaN, infinite). Every
// loader computes geometric and shading normals with it, so the same triangle gets the same bits.
bool unitVector(const glm::dvec3& v, glm::vec3* out);

// Triangles (as indices into `polygon`) covering a simple polygon given in order, wound like it. Corners
// on a straight edge and repeated corners are skipped rather than producing zero-area slivers; convex
// polygons become a fan, concave ones are ear-clipped in the polygon's plane. Returns nothing if the
// whole polygon is degenerate. Self-intersecting polygons get a best effort (the rest as a fan).
std::vector<std::array<uint32_t, 3>> triangulate(const std::vector<glm::dvec3>& polygon);

}  // namespace fp
