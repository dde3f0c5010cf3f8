#pragma once
// Axis-aligned bounding box, shared by the scene (framing the camera) and the BVH builder.
#include <glm/glm.hpp>
#include <limits>

#include "core/huge_page_allocator.h"

namespace fp {

struct Aabb {
    glm::vec3 lo{std::numeric_limits<float>::infinity()};
    glm::vec3 hi{-std::numeric_limits<float>::infinity()};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void grow(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void grow(const Aabb& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    glm::vec3 extent() const { return hi - lo; }
    glm::vec3 center() const { return 0.5f * (lo + hi); }
    // Surface area; 0 for an empty box so that SAH sums stay finite.
    float area() const {
        if (empty()) return 0.0f;
        glm::vec3 e = extent();
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
};

// One box per primitive: the BVH builders' input, a large array for large scenes.
using AabbArray = HugePageVector<Aabb>;

}  // namespace fp
