#include "native/native_trace.h"

#include <algorithm>
#include <cmath>

namespace fp::native {

namespace {

// Moller & Trumbore 1997; two-sided. As intersectTriangle in intersect.glsl.
bool intersectTriangle(const Ray& ray, const Tri& tri, float tMax, float& t, glm::vec2& uv) {
    glm::vec3 p = glm::cross(ray.dir, tri.e2);
    float det = glm::dot(tri.e1, p);
    if (det == 0.0f) return false;
    float invDet = 1.0f / det;
    glm::vec3 s = ray.origin - tri.v0;
    uv.x = glm::dot(s, p) * invDet;
    if (uv.x < 0.0f || uv.x > 1.0f) return false;  // early outs: what a scalar CPU tracer does
    glm::vec3 q = glm::cross(s, tri.e1);
    uv.y = glm::dot(ray.dir, q) * invDet;
    if (uv.y < 0.0f || uv.x + uv.y > 1.0f) return false;
    t = glm::dot(tri.e2, q) * invDet;
    return t > 0.0f && t < tMax;
}

// Slab test, as boxEntry in intersect.glsl: entry distance, or kInf when missed within (0, tMax).
float boxEntry(const glm::vec3& origin, const glm::vec3& invDir, const Aabb& box, float tMax) {
    glm::vec3 t0 = (box.lo - origin) * invDir, t1 = (box.hi - origin) * invDir;
    glm::vec3 tNear = glm::min(t0, t1), tFar = glm::max(t0, t1);
    float enter = std::max(std::max(tNear.x, tNear.y), std::max(tNear.z, 0.0f));
    float exit = std::min(std::min(std::min(tFar.x, tFar.y), tFar.z) * 1.0000004f, tMax);
    return enter <= exit ? enter : kInf;
}

bool intersectLeaf(const Scene& scene, const Ray& ray, uint32_t first, uint32_t count, bool anyHit,
                   Hit& hit) {
    for (uint32_t i = first; i < first + count; ++i) {
        float t;
        glm::vec2 uv;
        if (intersectTriangle(ray, scene.tris[i], hit.t, t, uv)) {
            hit = {t, int(i), uv};
            if (anyHit) return true;
        }
    }
    return false;
}

}  // namespace

bool traverse(const Scene& scene, const Ray& ray, float tMax, bool anyHit, Hit& hit) {
    hit = {tMax, -1, glm::vec2(0.0f)};
    glm::vec3 safeDir = ray.dir;
    for (int a = 0; a < 3; ++a)
        if (std::abs(safeDir[a]) < 1e-20f) safeDir[a] = 1e-20f;
    glm::vec3 invDir = 1.0f / safeDir;
    uint32_t stack[kStackSize];
    int size = 0;
    uint32_t node = 0;
    for (;;) {
        const Node& n = scene.nodes[node];
        float tLeft = boxEntry(ray.origin, invDir, n.child[0], hit.t);
        float tRight = boxEntry(ray.origin, invDir, n.child[1], hit.t);
        if (tLeft < kInf && n.count[0] > 0) {
            if (intersectLeaf(scene, ray, n.first[0], n.count[0], anyHit, hit)) return true;
            tLeft = kInf;
        }
        if (tRight < kInf && n.count[1] > 0) {
            if (intersectLeaf(scene, ray, n.first[1], n.count[1], anyHit, hit)) return true;
            tRight = kInf;
        }
        if (tLeft < kInf && tRight < kInf) {
            bool leftFirst = tLeft <= tRight;
            stack[size++] = leftFirst ? n.first[1] : n.first[0];
            node = leftFirst ? n.first[0] : n.first[1];
        } else if (tLeft < kInf) {
            node = n.first[0];
        } else if (tRight < kInf) {
            node = n.first[1];
        } else {
            if (size == 0) break;
            node = stack[--size];
        }
    }
    return hit.triangle >= 0;
}

}  // namespace fp::native
