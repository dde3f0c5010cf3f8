#include "pack/light_strategy.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "bvh/ray_query.h"

namespace fp {
namespace {

// Solid angle of the triangle a, b, c seen from p: Van Oosterom & Strackee 1983, eq. 8 (as
// glsl/common/sampling.glsl sphericalTriangleArea).
double solidAngle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    glm::dvec3 u = glm::normalize(a - p), v = glm::normalize(b - p), w = glm::normalize(c - p);
    return 2.0 * std::atan2(std::abs(glm::dot(u, glm::cross(v, w))),
                            1.0 + glm::dot(u, v) + glm::dot(v, w) + glm::dot(w, u));
}

}  // namespace

bool emittersFaceCloseSurfaces(const Scene& scene, const Bvh& bvh, const std::vector<Bvh>& meshBvhs) {
    constexpr double kLargeSolidAngle = 0.5;
    constexpr size_t kMaxRays = 4096;
    std::vector<uint32_t> emitters;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i)
        if (scene.materials[scene.triangles[i].material].isEmissive()) emitters.push_back(i);
    if (emitters.empty()) return false;
    std::vector<TriangleVerts> verts;
    verts.reserve(scene.triangles.size());
    for (const Triangle& t : scene.triangles) verts.push_back({t.p[0], t.p[1], t.p[2]});
    // Instances: each mesh's triangles in its space, and each instance's inverse transform.
    const bool instanced = !scene.instances.empty() && meshBvhs.size() == scene.meshes.size();
    std::vector<std::vector<TriangleVerts>> meshVerts;
    std::vector<glm::mat4> toObject;
    if (instanced) {
        for (const InstancedMesh& mesh : scene.meshes) {
            meshVerts.emplace_back();
            for (const Triangle& t : mesh.triangles) meshVerts.back().push_back({t.p[0], t.p[1], t.p[2]});
        }
        for (const Instance& instance : scene.instances)
            toObject.push_back(glm::inverse(instance.objectToWorld));
    }
    size_t stride = std::max<size_t>(1, emitters.size() / kMaxRays);
    for (size_t k = 0; k < emitters.size(); k += stride) {
        const Triangle& t = scene.triangles[emitters[k]];
        glm::vec3 n = t.geometricNormal();
        if (!(glm::dot(n, n) > 0.0f)) continue;
        Ray ray;
        ray.origin = (t.p[0] + t.p[1] + t.p[2]) / 3.0f;
        ray.dir = glm::normalize(n);  // the emitting side (one-sided emitters: the front)
        float extent = glm::length(t.p[1] - t.p[0]) + glm::length(t.p[2] - t.p[0]);
        ray.tMin = 1e-4f * extent;  // past the emitter itself
        RayHit hit = verts.empty() || bvh.nodes.empty() ? RayHit{} : closestHit(bvh, verts, ray);
        // In an instance's space the direction is not renormalised, so t is the same distance.
        for (size_t i = 0; instanced && i < scene.instances.size(); ++i) {
            Ray local = ray;
            local.origin = glm::vec3(toObject[i] * glm::vec4(ray.origin, 1.0f));
            local.dir = glm::vec3(toObject[i] * glm::vec4(ray.dir, 0.0f));
            local.tMax = hit.t;
            uint32_t mesh = scene.instances[i].mesh;
            RayHit h = closestHit(meshBvhs[mesh], meshVerts[mesh], local);
            if (h.hit() && h.t < hit.t) hit = h;
        }
        if (!hit.hit()) continue;
        glm::dvec3 p = glm::dvec3(ray.origin) + double(hit.t) * glm::dvec3(ray.dir);
        if (solidAngle(p, t.p[0], t.p[1], t.p[2]) > kLargeSolidAngle) return true;
    }
    return false;
}

}  // namespace fp
