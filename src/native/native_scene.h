#pragma once
// The native reference's scene: the data the GPU layout holds (src/gpu/layout.h), as plain C++ arrays
// in the natural in-memory form a scalar CPU tracer would use. The BVH is the renderer's own
// (buildBinnedSah with gpu/layout.h bvhOptions()), so both trace the same tree in the same order.
//
// Benchmark-only: this and the other src/native files are a single-threaded scalar C++ path tracer of
// exactly the default integrator's algorithm (glsl/integrators/nee.glsl on Lambertian surfaces), so that
// `fragpath bench --native` can say how the fragment shader compares with native code on this machine.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bvh/bvh.h"
#include "core/aabb.h"
#include "gpu/quantised_node.h"
#include "scene/scene.h"

namespace fp::native {

constexpr uint32_t kStackSize = 64;  // traversal stack entries

// A node of the 4-wide BVH (bvh/wide_bvh.h) exactly as the GPU layout stores it: 64 bytes, one cache
// line, with the four children's boxes quantised to the node's grid and their links
// (gpu/quantised_node.h). The reference tests the same quantised boxes as the shader, so that both
// visit the same nodes (quantised boxes are a little larger than the exact ones, so exact boxes would
// visit fewer) and read the same bytes per node.
struct alignas(64) Node {
    layout::QuantisedNode texels;
};

struct Tri {
    glm::vec3 v0, e1, e2;  // e1 = v1 - v0, e2 = v2 - v0
    uint32_t material;
    float lightPmf;  // probability that light sampling picks it (0 if not emissive)
};

struct Light {
    uint32_t triangle;
    float cdf, pmf, area;
};

struct Scene {
    std::vector<Node> nodes;  // nodes[0] is the root
    std::vector<Tri> tris;    // in BVH leaf order
    std::vector<std::array<glm::vec3, 3>> normals;
    std::vector<glm::vec3> diffuse, emission;  // per material
    std::vector<Light> lights;
    glm::vec3 environment{0.0f};  // constant radiance from every unblocked direction
    float rayOffset = 0.0f;       // as Renderer computes it
};

// Throws fp::Error for what the reference does not implement: materials other than Lambertian (with
// optional emission) and environment maps.
// `options` must be the renderer's (gpu/layout.h bvhOptions()) for both to trace the same tree.
Scene buildScene(const fp::Scene& scene, const BvhBuildOptions& options);

}  // namespace fp::native
