#pragma once
// The native reference's scene: the data the GPU layout holds (src/pack/layout.h), as plain C++ arrays
// in the natural in-memory form a scalar CPU tracer would use. The BVH is the renderer's own
// (buildBinnedSah with pack/layout.h bvhOptions()), so both trace the same tree in the same order; the
// reference keeps its children's exact boxes where the GPU stores them quantised (see Node below).
//
// Benchmark-only: this and the other src/native files are a single-threaded scalar C++ path tracer of
// exactly the default integrator's algorithm (glsl/integrators/nee.glsl on Lambertian surfaces), so that
// `fragpath bench --native` can say how the fragment shader compares with native code on this machine.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bvh/bvh.h"
#include "core/aabb.h"
#include "scene/scene.h"

namespace fp::native {

constexpr uint32_t kStackSize = 64;  // traversal stack entries

// A node of the 4-wide BVH (bvh/wide_bvh.h) with its four children's boxes, as in the GPU layout: one
// bound of all four children per vector, so that the slab test of four boxes is a few vector operations
// (what a native SIMD tracer does; Wald, Benthin & Boulos 2008). Empty slots are the unreachable box
// kEmptyChildCoordinate. The boxes are exact floats, not the GPU layout's 8-bit quantised boxes
// (pack/quantised_node.h): decoding those costs a scalar CPU tracer more than it saves (the reference
// ran 25-30 % slower with them on both the Cornell box and sphere-1m, docs/optimisation-log.md, entry 21),
// so a native tracer would not use them, and the comparison stays against what native code does best.
// The quantised boxes are a little larger, so the shader visits a few more nodes and tests more
// triangles than the reference (the Cornell box: +1 % nodes, +2 % triangle tests per path); every
// hit is the same except on exact ties.
constexpr float kEmptyChildCoordinate = 1e30f;  // no ray reaches it before kInf

struct Node {
    glm::vec4 lo[3], hi[3];  // lo[axis][i]: child i's lower bound on that axis
    uint32_t first[4];       // count > 0: triangles [first, first + count); count == 0: interior node `first`
    uint32_t count[4];
};

struct Tri {
    glm::vec3 v0, e1, e2;  // e1 = v1 - v0, e2 = v2 - v0
    uint32_t material;
    float lightPmf;  // probability that light sampling picks it (0 if not emissive)
};

struct Light {
    uint32_t triangle;
    float cdf;  // on the 2^-24 grid of the random numbers; the pmfs are its exact differences
};

struct Scene {
    std::vector<Node> nodes;  // nodes[0] is the root
    std::vector<Tri> tris;    // in BVH leaf order
    std::vector<std::array<glm::vec3, 3>> normals;
    std::vector<glm::vec3> diffuse, emission;  // per material
    std::vector<Light> lights;
    glm::vec3 environment{0.0f};    // constant radiance from every unblocked direction
    bool solidAngleLights = false;  // the renderer's LightSampling::Auto choice (pack/light_strategy.h)
};

// Throws fp::Error for what the reference does not implement (unsupportedFeature).
// `options` must be the renderer's (pack/layout.h bvhOptions()) for both to trace the same tree.
Scene buildScene(const fp::Scene& scene, const BvhBuildOptions& options);

// Why the reference cannot render `scene` as the renderer would (materials other than Lambertian with
// optional emission, textures, environment maps, punctual lights), or nothing if it can.
std::optional<std::string> unsupportedFeature(const fp::Scene& scene);

}  // namespace fp::native
