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

// Slab test of a node's four children at once, as boxEntries in intersect.glsl: entry distances,
// kInf where a box is missed within (0, tMax).
glm::vec4 boxEntries(const glm::vec3& origin, const glm::vec3& invDir, const Node& n, float tMax) {
    glm::vec4 enter(0.0f), exit(tMax);
    glm::vec4 tFar(kInf * 4.0f);  // above any distance, so the first min takes the axis' value
    for (int axis = 0; axis < 3; ++axis) {
        glm::vec4 t0 = (n.lo[axis] - origin[axis]) * invDir[axis],
                  t1 = (n.hi[axis] - origin[axis]) * invDir[axis];
        enter = glm::max(enter, glm::min(t0, t1));
        tFar = glm::min(tFar, glm::max(t0, t1));
    }
    exit = glm::min(tFar * 1.0000004f, exit);
    return glm::mix(glm::vec4(kInf), enter, glm::lessThanEqual(enter, exit));
}

// One compare-exchange of intersect.glsl's sorting network.
void orderPair(float& ta, uint32_t& la, float& tb, uint32_t& lb) {
    if (tb < ta) {
        std::swap(ta, tb);
        std::swap(la, lb);
    }
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
        glm::vec4 t = boxEntries(ray.origin, invDir, n, hit.t);
        // The leaf children hit, in child order, then the interior ones nearest first, as the shader.
        for (int i = 0; i < 4; ++i)
            if (n.count[i] > 0) {
                if (t[i] < kInf && intersectLeaf(scene, ray, n.first[i], n.count[i], anyHit, hit))
                    return true;
                t[i] = kInf;
            }
        t = glm::mix(t, glm::vec4(kInf), glm::greaterThan(t, glm::vec4(hit.t)));
        float t0 = t.x, t1 = t.y, t2 = t.z, t3 = t.w;
        uint32_t l0 = n.first[0], l1 = n.first[1], l2 = n.first[2], l3 = n.first[3];
        orderPair(t0, l0, t1, l1);
        orderPair(t2, l2, t3, l3);
        orderPair(t0, l0, t2, l2);
        orderPair(t1, l1, t3, l3);
        orderPair(t1, l1, t2, l2);
        if (t3 < kInf) stack[size++] = l3;
        if (t2 < kInf) stack[size++] = l2;
        if (t1 < kInf) stack[size++] = l1;
        if (t0 < kInf) {
            node = l0;
        } else {
            if (size == 0) break;
            node = stack[--size];
        }
    }
    return hit.triangle >= 0;
}

}  // namespace fp::native
