#include "native/native_scene.h"

#include <algorithm>
#include <string>

#include "bvh/bvh.h"
#include "core/error.h"

namespace fp::native {

namespace {

float luminance(const glm::vec3& rgb) {
    return glm::dot(rgb, glm::vec3(0.2126f, 0.7152f, 0.0722f));
}

// Depth first like gpu/pack.cpp's NodePacker, so node indices match the GPU's.
struct NodeFlattener {
    const Bvh& bvh;
    std::vector<Node>& out;
    uint32_t maxDepth = 0;

    uint32_t interior(uint32_t cpuIndex, uint32_t depth) {
        maxDepth = std::max(maxDepth, depth);
        uint32_t index = uint32_t(out.size());
        out.emplace_back();
        const BvhNode& node = bvh.nodes[cpuIndex];
        setChild(index, 0, cpuIndex + 1, depth);
        setChild(index, 1, node.first, depth);
        return index;
    }

    void setChild(uint32_t index, int side, uint32_t cpuIndex, uint32_t depth) {
        const BvhNode& c = bvh.nodes[cpuIndex];
        uint32_t first = c.isLeaf() ? c.first : interior(cpuIndex, depth + 1);
        Node& n = out[index];  // after interior(), which may reallocate
        n.child[side] = c.bounds;
        n.first[side] = first;
        n.count[side] = c.count;
    }
};

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

    NodeFlattener flatten{bvh, out.nodes};
    if (bvh.nodes[0].isLeaf()) {
        const BvhNode& root = bvh.nodes[0];
        out.nodes.push_back({{root.bounds, root.bounds}, {root.first, root.first}, {root.count, root.count}});
    } else {
        flatten.interior(0, 0);
    }
    // The traversal stack holds at most one entry per level below the root.
    if (flatten.maxDepth + 2 > kStackSize)
        throw Error(scene.source + ": the BVH is " + std::to_string(flatten.maxDepth) +
                    " levels deep, more than the native reference's stack holds");

    Aabb box = scene.bounds();
    float reach = std::max({glm::length(box.extent()), glm::length(box.lo), glm::length(box.hi)});
    out.rayOffset = 1e-5f * reach;
    return out;
}

}  // namespace fp::native
