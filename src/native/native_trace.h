#pragma once
// Ray queries of the native reference: the same traversal as glsl/common/intersect.glsl (4-wide nodes
// with the children's boxes, leaves tested in child order, interior children nearest first, any-hit
// exit for shadows).
#include <cstdint>

#include <glm/glm.hpp>

#include "native/native_scene.h"

namespace fp::native {

constexpr float kInf = 1e30f;

struct Ray {
    glm::vec3 origin, dir;
};

struct Hit {
    float t = kInf;
    int triangle = -1;   // -1: nothing hit
    glm::vec2 uv{0.0f};  // barycentrics of v1 and v2
};

// Closest hit with t < tMax (anyHit false), or any hit (anyHit true: returns at the first one).
bool traverse(const Scene& scene, const Ray& ray, float tMax, bool anyHit, Hit& hit);

}  // namespace fp::native
