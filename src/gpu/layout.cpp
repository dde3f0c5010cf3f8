#include "gpu/layout.h"

#include <string>

#include "core/error.h"

namespace fp::layout {

ShaderDefines layoutDefines(bool images) {
    auto s = [](int v) { return std::to_string(v); };
    ShaderDefines defines = {
        {"TRIANGLE_TEXELS", s(kTriangleTexels)},  {"NORMAL_TEXELS", s(kNormalTexels)},
        {"NODE_TEXELS", s(kNodeTexels)},          {"NODE_LINK_TEXEL", s(kNodeLinkTexel)},
        {"MATERIAL_TEXELS", s(kMaterialTexels)},  {"TRIANGLES_UNIT", s(kTrianglesUnit)},
        {"NORMALS_UNIT", s(kNormalsUnit)},        {"NODES_UNIT", s(kNodesUnit)},
        {"MATERIALS_UNIT", s(kMaterialsUnit)},    {"LIGHTS_UNIT", s(kLightsUnit)},
        {"TEXCOORD_TEXELS", s(kTexcoordTexels)},  {"LEAF_BIT", std::to_string(kLeafBit) + "u"},
        {"LEAF_COUNT_SHIFT", s(kLeafCountShift)}, {"LEAF_FIRST_MASK", std::to_string(kMaxLeafFirst) + "u"}};
    if (images) {
        // A GL_ name becomes an #extension line (gl/shader_source.h): the shaders are #version 410.
        defines.emplace_back("GL_ARB_shader_image_load_store", "require");
        defines.emplace_back("SCENE_READS_IMAGES", "1");
    }
    return defines;
}

BvhBuildOptions bvhOptions() {
    BvhBuildOptions options;
    options.maxLeafSize = 8;
    options.traversalCost = 3.0f;
    return options;
}

uint32_t encodeChild(const ChildLink& child) {
    if (child.count == 0) {
        if (child.first >= kLeafBit) throw Error("internal: BVH node index too large for the GPU layout");
        return child.first;
    }
    if (child.first > kMaxLeafFirst || child.count > kMaxLeafCount)
        throw Error("the GPU layout cannot address a BVH leaf of " + std::to_string(child.count) +
                    " triangles from triangle " + std::to_string(child.first) + " (at most " +
                    std::to_string(kMaxLeafCount) + " triangles, from below " +
                    std::to_string(kMaxLeafFirst + 1) + ")");
    return kLeafBit | ((child.count - 1) << kLeafCountShift) | child.first;
}

ChildLink decodeChild(uint32_t link) {
    if (!(link & kLeafBit)) return {link, 0};
    return {link & kMaxLeafFirst, ((link >> kLeafCountShift) & 15u) + 1};
}

}  // namespace fp::layout
