#pragma once
// Scene + BVH -> the texel arrays described in pack/layout.h (CPU only; upload is in scene_textures.h).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bvh/bvh.h"
#include "core/huge_page_allocator.h"
#include "pack/layout.h"
#include "scene/scene.h"

namespace fp {

struct PackedScene {
    // The per-triangle and per-node arrays are large for large scenes: see core/huge_page_allocator.h.
    HugePageVector<glm::vec4> triangles, normals;
    std::vector<glm::vec4> materials, lights;
    HugePageVector<glm::uvec4> nodes;  // layout::kNodeTexels per node
    // Empty unless some material has a texture (hasTextures()).
    HugePageVector<glm::vec2> texcoords;
    HugePageVector<uint8_t> textureTexels;  // 4 bytes per texel
    std::vector<glm::ivec4> textureTable;
    HugePageVector<glm::vec4> tangents;  // empty unless some material has a normal map
    HugePageVector<glm::vec4> colors;    // empty unless some triangle has vertex colours (Scene::colors)
    int texcoordSlots = 1;               // TEXCOORD_SLOTS: 2 when some texture reads uv slot 1
    bool textureSampling = false;        // TEXTURE_SAMPLING: some texture clamps, mirrors or is nearest
    int surfaceMaps = 0;   // SURFACE_MAPS: the layout::MapBit of every kind of map some material has
    bool opacity = false;  // SURFACE_OPACITY: some material has alpha or is single-sided
    // lightCount: entries of the light-selection cdf (emitter triangles, then punctual lights: layout.h);
    // punctualCount of them are punctual lights.
    uint32_t triangleCount = 0, nodeCount = 0, lightCount = 0, punctualCount = 0;
    // Scenes with instances (pack/layout.h): the top level's entries (the instances, and the world
    // triangles as one more when there are any) and the node where their transform pairs start; 0 and
    // 0 otherwise.
    uint32_t instanceCount = 0, instanceNodeStart = 0;
    // The most entries the traversal stack can hold (WideBvh::stackEntries; with instances, the top
    // level's and the deepest mesh's together): the shader's stack is that deep (layout_defines.h).
    uint32_t stackEntries = 0;
    float totalLightPower = 0.0f;  // sum over lights of their power / pi (scene/light_selection.h)
    // The light tree's root texel in `lights` and its depth (pack/light_tree.h); lightTreeFirst 0: none.
    uint32_t lightTreeFirst = 0, lightTreeDepth = 0;

    bool hasTextures() const { return !textureTable.empty(); }
    size_t bytes() const;
    size_t geometryBytes() const;  // positions + BVH only
    size_t textureBytes() const;   // texture coordinates, texels, table, tangents and vertex colours
};

// One material's texels, as pack/layout.h describes them (the BSDF tests pack their materials with it).
std::array<glm::vec4, layout::kMaterialTexels> packMaterial(const Material& m);

// The material as packScene packs it: a metallic-roughness material at metallic 1 without a
// metallic-roughness or base colour map is exactly the conductor with F0 = its base colour, and at
// metallic 0 without a metallic-roughness map exactly the plastic with a white coat (bsdf.glsl runs the
// same functions; tests/render/metallic_roughness_test.cpp), which compile less shader code (not with a
// clearcoat or a sheen, which only the blend's code has): such
// materials are packed as those, so that a scene of plain metals (MTL Pm 1, glTF metallicFactor 1)
// renders as fast as with the Conductor type. Every other material is returned as it is, and so are
// metals in a scene with vertex colours (`vertexColors`), which multiply the base colour, not the
// conductor's F0. The renderer takes MATERIAL_TYPES from these types.
Material shaderMaterial(const Material& m, bool vertexColors = false);

// Whether some triangle of the scene, world or instanced, has vertex colours (Scene::colors).
bool hasVertexColors(const Scene& scene);

// The tangent frame of a triangle from its positions and texture coordinates (Lengyel 2001, "Computing
// Tangent Space Basis Vectors for an Arbitrary Mesh"): xyz = dp/du made orthogonal to the triangle's
// normal and unit, w = +-1 such that w cross(n, t) points along dp/dv, n the vertices' mean normal
// (the geometric normal where they cancel). Degenerate uvs give an arbitrary unit tangent in the plane
// and w = 1.
glm::vec4 triangleTangent(const Triangle& t);

// Throws fp::Error if the scene cannot be addressed by the layout (over 2^24 triangles or materials,
// 2^31 texture texels, or a BVH node over 2^40 across: pack/quantised_node.h), or has a punctual light
// that validatePunctualLight refuses.
// `bvh` is over the world triangles; a scene with instances also needs `meshBvhs`, one per
// Scene::meshes entry over its triangles (empty without instances).
PackedScene packScene(const Scene& scene, const Bvh& bvh, const std::vector<Bvh>& meshBvhs = {});

}  // namespace fp
