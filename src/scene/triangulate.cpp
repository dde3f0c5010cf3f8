#include "scene/triangulate.h"

#include <algorithm>
#include <cmath>

namespace fp {

// Twice a triangle's area, relative to its longest edge squared (about the sine of its sharpest corner),
// below which it counts as degenerate: far above double rounding, far below anything drawn on purpose.
static constexpr double kMinRelativeArea = 1e-6;

bool isDegenerate(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2) {
    double area2 = glm::length(glm::cross(p1 - p0, p2 - p0));
    double longest = std::max({glm::length(p1 - p0), glm::length(p2 - p1), glm::length(p0 - p2)});
    double scale = longest * longest;
    return !(std::isfinite(area2) && std::isfinite(scale)) || !(area2 > kMinRelativeArea * scale);
}

bool unitVector(const glm::dvec3& v, glm::vec3* out) {
    double length = glm::length(v);
    if (!std::isfinite(length) || !(length > 0.0)) return false;
    glm::vec3 unit(v / length);
    if (!std::isfinite(unit.x) || !std::isfinite(unit.y) || !std::isfinite(unit.z)) return false;
    *out = unit;
    return true;
}

namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;

// Newell's method: a robust normal for a polygon that may be concave or slightly non-planar. Its
// direction follows the winding.
glm::dvec3 polygonNormal(const std::vector<glm::dvec3>& p, const std::vector<uint32_t>& ring) {
    glm::dvec3 n(0.0);
    for (size_t i = 0; i < ring.size(); ++i) {
        const glm::dvec3& a = p[ring[i]];
        const glm::dvec3& b = p[ring[(i + 1) % ring.size()]];
        n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return n;
}

// Removes corners that add no area (repeated points, points on a straight edge, spikes) until none is left.
void dropFlatCorners(const std::vector<glm::dvec3>& p, std::vector<uint32_t>* ring) {
    bool changed = true;
    while (changed && ring->size() >= 3) {
        changed = false;
        for (size_t i = 0; i < ring->size() && ring->size() >= 3; ++i) {
            size_t n = ring->size();
            uint32_t prev = (*ring)[(i + n - 1) % n], cur = (*ring)[i], next = (*ring)[(i + 1) % n];
            if (isDegenerate(p[prev], p[cur], p[next])) {
                ring->erase(ring->begin() + static_cast<std::ptrdiff_t>(i));
                changed = true;
                --i;
            }
        }
    }
}

// Whether corner b (between a and c) turns the same way as the polygon normal.
bool isConvex(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& normal) {
    return glm::dot(glm::cross(b - a, c - b), normal) > 0.0;
}

// Whether q lies inside or on triangle abc (all seen along `normal`).
bool contains(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& q,
              const glm::dvec3& normal) {
    return glm::dot(glm::cross(b - a, q - a), normal) >= 0.0 &&
           glm::dot(glm::cross(c - b, q - b), normal) >= 0.0 &&
           glm::dot(glm::cross(a - c, q - c), normal) >= 0.0;
}

void fan(const std::vector<uint32_t>& ring, Triangles* out) {
    for (size_t i = 1; i + 1 < ring.size(); ++i) out->push_back({ring[0], ring[i], ring[i + 1]});
}

// Cuts off ears (convex corners whose triangle holds no other corner) until a triangle remains.
// O(n^2) per ear in the worst case, but only concave polygons get here, and those are small in practice.
void clipEars(const std::vector<glm::dvec3>& p, std::vector<uint32_t> ring, const glm::dvec3& normal,
              Triangles* out) {
    while (ring.size() > 3) {
        size_t n = ring.size();
        bool clipped = false;
        for (size_t i = 0; i < n && !clipped; ++i) {
            uint32_t a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
            if (!isConvex(p[a], p[b], p[c], normal)) continue;
            bool empty = true;
            for (uint32_t q : ring) {
                if (q == a || q == b || q == c || p[q] == p[a] || p[q] == p[b] || p[q] == p[c]) continue;
                if (contains(p[a], p[b], p[c], p[q], normal)) {
                    empty = false;
                    break;
                }
            }
            if (!empty) continue;
            out->push_back({a, b, c});
            ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
            clipped = true;
        }
        if (!clipped) break;  // self-intersecting: no ear exists
    }
    fan(ring, out);
}

}  // namespace

std::vector<std::array<uint32_t, 3>> triangulate(const std::vector<glm::dvec3>& polygon) {
    Triangles out;
    if (polygon.size() == 3) {
        if (!isDegenerate(polygon[0], polygon[1], polygon[2])) out.push_back({0, 1, 2});
        return out;
    }
    std::vector<uint32_t> ring(polygon.size());
    for (uint32_t i = 0; i < ring.size(); ++i) ring[i] = i;
    dropFlatCorners(polygon, &ring);
    if (ring.size() < 3) return out;
    glm::dvec3 normal = polygonNormal(polygon, ring);
    bool convex = true;
    for (size_t i = 0; i < ring.size() && convex; ++i) {
        size_t n = ring.size();
        convex =
            isConvex(polygon[ring[(i + n - 1) % n]], polygon[ring[i]], polygon[ring[(i + 1) % n]], normal);
    }
    if (convex) {
        fan(ring, &out);
    } else {
        clipEars(polygon, ring, normal, &out);
    }
    return out;
}

}  // namespace fp
