#include "native/native_scene.h"

#include <algorithm>
#include <string>

#include "bvh/bvh.h"
#include "bvh/wide_bvh.h"
#include "core/error.h"
#include "gpu/layout.h"

namespace fp::native {

namespace {

float luminance(const glm::vec3& rgb) {
    return glm::dot(rgb, glm::vec3(0.2126f, 0.7152f, 0.0722f));
}

}  // namespace

Scene buildScene(const fp::Scene& scene, const BvhBuildOptions& options) {
    if (scene.triangles.empty()) throw Error(scene.source + ": the native reference needs triangles");
    if (scene.environment.hasMap())
        throw Error(scene.source + ": the native reference has no environment maps (a constant colour only)");
    Scene out;
    for (const Material& m : scene.materials) {
        if (m.type != MaterialType::Diffuse)
            throw Error(scene.source + ": material '" + m.name +
                        "' is not Lambertian; the native reference implements only diffuse surfaces");
        out.diffuse.push_back(m.diffuse);
        out.emission.push_back(m.emission);
    }
    out.environment = scene.environment.color;

    AabbArray bounds;
    for (const Triangle& t : scene.triangles) bounds.push_back(t.bounds());
    Bvh bvh = buildBinnedSah(bounds, options);

    // Emitters chosen in proportion to their power, as gpu/pack.cpp does.
    float total = 0.0f;
    for (uint32_t i : bvh.primIndex) {
        const Triangle& t = scene.triangles[i];
        if (scene.materials[t.material].isEmissive())
            total += luminance(scene.materials[t.material].emission) * t.area();
    }
    float cdf = 0.0f;
    for (uint32_t i : bvh.primIndex) {
        const Triangle& t = scene.triangles[i];
        const Material& m = scene.materials[t.material];
        float pmf = m.isEmissive() && total > 0.0f ? luminance(m.emission) * t.area() / total : 0.0f;
        if (pmf > 0.0f) {
            cdf += pmf;
            out.lights.push_back({uint32_t(out.tris.size()), cdf, pmf, t.area()});
        }
        out.tris.push_back({t.p[0], t.p[1] - t.p[0], t.p[2] - t.p[0], t.material, pmf});
        out.normals.push_back(t.n);
    }
    if (!out.lights.empty()) out.lights.back().cdf = 1.0f;

    // The same wide tree, in the same order, as gpu/pack.cpp stores (with exact boxes: see Node).
    WideBvh wide = collapseToWide(bvh);
    for (const WideBvhNode& w : wide.nodes) {
        Node n{};
        for (int axis = 0; axis < 3; ++axis)
            for (int i = 0; i < kWideBvhWidth; ++i) {
                bool used = i < w.childCount;
                n.lo[axis][i] = used ? w.bounds[i].lo[axis] : kEmptyChildCoordinate;
                n.hi[axis][i] = used ? w.bounds[i].hi[axis] : kEmptyChildCoordinate;
            }
        for (int i = 0; i < kWideBvhWidth; ++i) {
            n.first[i] = i < w.childCount ? w.first[i] : 0;
            n.count[i] = i < w.childCount ? w.count[i] : 0;
        }
        out.nodes.push_back(n);
    }
    // The traversal stack holds at most three entries per level above the deepest node.
    if (3 * wide.depth + 1 > kStackSize)
        throw Error(scene.source + ": the BVH is " + std::to_string(wide.depth) +
                    " levels deep, more than the native reference's stack holds");

    Aabb box = scene.bounds();
    float reach = std::max({glm::length(box.extent()), glm::length(box.lo), glm::length(box.hi)});
    out.rayOffset = 1e-5f * reach;
    return out;
}

}  // namespace fp::native
