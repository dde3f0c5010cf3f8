#pragma once
// Scene + BVH -> the texel arrays described in pack/layout.h (CPU only; upload is in scene_textures.h).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bvh/bvh.h"
#include "core/huge_page_allocator.h"
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
    // lightCount: entries of the light-selection cdf (emitter triangles, then punctual lights: layout.h);
    // punctualCount of them are punctual lights.
    uint32_t triangleCount = 0, nodeCount = 0, lightCount = 0, punctualCount = 0;
    uint32_t bvhDepth = 0;         // deepest (wide) node, root = 0: the traversal stack grows with it
    float totalLightPower = 0.0f;  // sum over lights of their power / pi (scene/light_selection.h)

    bool hasTextures() const { return !textureTable.empty(); }
    size_t bytes() const;
    size_t geometryBytes() const;  // positions + BVH only
    size_t textureBytes() const;   // texture coordinates, texels and table
};

// Throws fp::Error if the scene cannot be addressed by the layout (over 2^24 triangles or materials,
// 2^31 texture texels, or a BVH node over 2^40 across: pack/quantised_node.h), or has a punctual light
// that validatePunctualLight refuses.
PackedScene packScene(const Scene& scene, const Bvh& bvh);

}  // namespace fp
