#include "request/own_light.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "bvh/ray_query.h"
#include "scene/instancing.h"
#include "scene/light_selection.h"
#include "scene/studio_environment.h"

namespace fp {

namespace {

// Every triangle in world space (instances placed), with its material, and a BVH over them.
struct WorldGeometry {
    std::vector<TriangleVerts> verts;
    std::vector<uint32_t> material;
    Bvh bvh;
    float tMin = 0.0f;  // hits nearer than this along a unit direction are the surface left from

    explicit WorldGeometry(const Scene& scene) {
        auto add = [this](const Triangle& t) {
            verts.push_back({t.p[0], t.p[1], t.p[2]});
            material.push_back(t.material);
        };
        for (const Triangle& t : scene.triangles) add(t);
        for (const Instance& instance : scene.instances)
            for (const Triangle& t : scene.meshes[instance.mesh].triangles)
                add(placedTriangle(t, instance.objectToWorld));
        bvh = buildBinnedSah(triangleBounds(verts));
        tMin = 1e-5f * glm::length(scene.bounds().extent());
    }

    glm::vec3 unitNormal(uint32_t i) const {
        const TriangleVerts& t = verts[i];
        return glm::normalize(glm::cross(t.p1 - t.p0, t.p2 - t.p0));
    }
    RayHit trace(const glm::vec3& origin, const glm::vec3& dir) const {
        Ray ray;
        ray.origin = origin;
        ray.dir = dir;
        ray.tMin = tMin;
        return closestHit(bvh, verts, ray);
    }
};

// Fixed-seed uniform numbers in [0, 1): the top 24 bits of mt19937's output, which the C++ standard
// fixes, so that the estimate is the same with every standard library.
class Uniform {
  public:
    float operator()() { return float(engine_() >> 8) * (1.0f / 16777216.0f); }

  private:
    std::mt19937 engine_{20261205u};
};

// A cosine-distributed direction about the unit normal n: Malley's method (a uniform point of the disc,
// concentricDisk, lifted onto the hemisphere), in the orthonormal basis of Duff et al. 2017, "Building
// an Orthonormal Basis, Revisited".
glm::vec3 cosineDirection(const glm::vec3& n, Uniform& u) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z), b = n.x * n.y * a;
    const glm::vec3 t(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const glm::vec3 s(b, sign + n.y * n.y * a, -n.y);
    const glm::vec2 p = concentricDisk({u(), u()});
    const float z = std::sqrt(std::max(0.0f, 1.0f - glm::dot(p, p)));
    return glm::normalize(p.x * t + p.y * s + z * n);
}

// A uniformly distributed point of the triangle (pbrt-v4 A.5.4's square-root map).
glm::vec3 pointOn(const TriangleVerts& t, Uniform& u) {
    const float r = std::sqrt(u()), v = u();
    return (1.0f - r) * t.p0 + r * (1.0f - v) * t.p1 + r * v * t.p2;
}

// Picks an index with probability weight[i] / sum from a running sum of the weights.
uint32_t pick(const std::vector<double>& cumulative, Uniform& u) {
    const double x = double(u()) * cumulative.back();
    auto it = std::upper_bound(cumulative.begin(), cumulative.end(), x);
    return uint32_t(std::min<std::ptrdiff_t>(it - cumulative.begin(), std::ptrdiff_t(cumulative.size()) - 1));
}

double enclosure(const WorldGeometry& world, const std::vector<double>& powerSum, int samples, Uniform& u) {
    int kept = 0;
    for (int i = 0; i < samples; ++i) {
        const uint32_t emitter = pick(powerSum, u);
        glm::vec3 origin = pointOn(world.verts[emitter], u);
        glm::vec3 side = world.unitNormal(emitter);  // emitters send light from their front faces
        bool stayed = true;
        for (int bounce = 0; bounce < kEnclosureBounces && stayed; ++bounce) {
            const glm::vec3 dir = cosineDirection(side, u);
            const RayHit hit = world.trace(origin, dir);
            stayed = hit.hit();
            if (!stayed) break;
            origin += hit.t * dir;
            side = world.unitNormal(hit.prim);
            if (glm::dot(side, dir) > 0.0f) side = -side;  // the side the light arrived on
        }
        kept += stayed ? 1 : 0;
    }
    return double(kept) / double(samples);
}

double ownToStudio(const WorldGeometry& world, const std::vector<double>& emitted,
                   const std::vector<double>& areaSum, int samples, Uniform& u) {
    double own = 0.0, studio = 0.0;
    for (int i = 0; i < samples; ++i) {
        const uint32_t at = pick(areaSum, u);
        const glm::vec3 dir = cosineDirection(world.unitNormal(at), u);
        const RayHit hit = world.trace(pointOn(world.verts[at], u), dir);
        if (!hit.hit())
            studio += double(luminance(studioRadiance(dir)));
        else if (glm::dot(world.unitNormal(hit.prim), dir) < 0.0f)  // an emitter's front face
            own += emitted[world.material[hit.prim]];
    }
    if (studio == 0.0) return own > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
    return own / studio;
}

}  // namespace

OwnLightEstimate estimateOwnLight(const Scene& scene, int samples) {
    std::vector<double> emitted(scene.materials.size(), 0.0);
    bool anyEmitter = false;
    for (size_t m = 0; m < scene.materials.size(); ++m)
        if (scene.materials[m].isEmissive()) {
            emitted[m] = meanEmittedLuminance(scene, scene.materials[m]);
            anyEmitter = anyEmitter || emitted[m] > 0.0;
        }
    if (!anyEmitter || samples <= 0) return {};
    const WorldGeometry world(scene);
    // Running sums of power (emitters are world triangles: scene/scene.h InstancedMesh) and of area.
    std::vector<double> powerSum, areaSum;
    double power = 0.0, area = 0.0;
    for (size_t i = 0; i < world.verts.size(); ++i) {
        const double a = double(glm::length(
            glm::cross(world.verts[i].p1 - world.verts[i].p0, world.verts[i].p2 - world.verts[i].p0)));
        const uint32_t m = world.material[i];
        area += a;
        areaSum.push_back(area);
        if (i < scene.triangles.size() && m < emitted.size()) power += emitted[m] * a;
        powerSum.push_back(power);
    }
    if (!(power > 0.0) || !(area > 0.0)) return {};
    Uniform u;
    OwnLightEstimate estimate;
    estimate.enclosure = enclosure(world, powerSum, samples, u);
    estimate.ownToStudio = ownToStudio(world, emitted, areaSum, samples, u);
    return estimate;
}

}  // namespace fp
