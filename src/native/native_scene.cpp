#include "native/native_scene.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bvh/bvh.h"
#include "bvh/wide_bvh.h"
#include "core/error.h"
#include "pack/layout.h"
#include "pack/light_strategy.h"
#include "pack/pack.h"
#include "scene/instancing.h"
#include "scene/light_selection.h"

namespace fp::native {

std::optional<std::string> unsupportedFeature(const fp::Scene& scene) {
    if (scene.environment.hasMap())
        return "an environment map (the native reference has a constant colour only)";
    if (!scene.punctualLights.empty())
        return "point, spot or directional lights (the native reference samples emissive triangles only)";
    if (hasVertexColors(scene)) return "vertex colours (the native reference has one Kd per material)";
    for (const Material& m : scene.materials) {
        if (m.type != MaterialType::Diffuse)
            return "material '" + m.name +
                   "' is not Lambertian; the native reference implements only diffuse surfaces";
        if (m.hasTextures())
            return "material '" + m.name + "' has a texture; the native reference implements none";
        if (m.needsOpacityTest())
            return "material '" + m.name +
                   "' has alpha or is single-sided; the native reference implements opaque double-sided "
                   "surfaces only";
    }
    return std::nullopt;
}

namespace {

Scene buildFlatScene(const fp::Scene& scene, const BvhBuildOptions& options) {
    if (scene.triangles.empty()) throw Error(scene.source + ": the native reference needs triangles");
    if (auto why = unsupportedFeature(scene)) throw Error(scene.source + ": " + *why);
    Scene out;
    for (const Material& m : scene.materials) {
        out.diffuse.push_back(m.diffuse);
        out.emission.push_back(m.emission);
    }
    out.environment = scene.environment.color;

    AabbArray bounds;
    for (const Triangle& t : scene.triangles) bounds.push_back(t.bounds());
    Bvh bvh = buildBinnedSah(bounds, options);
    out.solidAngleLights = emittersFaceCloseSurfaces(scene, bvh);

    // Emitters chosen in proportion to their power, with the probabilities pack/pack.cpp stores.
    std::vector<float> pmf = emitterPmfs(scene, bvh.primIndex.data(), bvh.primIndex.size()).pmf;
    float cdf = 0.0f;
    for (size_t k = 0; k < bvh.primIndex.size(); ++k) {
        const Triangle& t = scene.triangles[bvh.primIndex[k]];
        if (pmf[k] > 0.0f) {
            cdf += pmf[k];  // exact: multiples of 2^-24 in [0, 1]
            out.lights.push_back({uint32_t(k), cdf});
        }
        out.tris.push_back({t.p[0], t.p[1] - t.p[0], t.p[2] - t.p[0], t.material, pmf[k]});
        out.normals.push_back(t.n);
    }

    // The same wide tree, in the same order, as pack/pack.cpp stores (with exact boxes: see Node).
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

    return out;
}

}  // namespace

Scene buildScene(const fp::Scene& scene, const BvhBuildOptions& options) {
    // One level: instances become world triangles (the two-level BVH is the GPU renderer's own).
    return scene.instances.empty() ? buildFlatScene(scene, options)
                                   : buildFlatScene(flattenInstances(scene), options);
}

}  // namespace fp::native
