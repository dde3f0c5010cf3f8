#include "gpu/layout_defines.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "pack/caustic_casters.h"
#include "pack/layout.h"

namespace fp::layout {

ShaderDefines layoutDefines(bool images) {
    auto s = [](int v) { return std::to_string(v); };
    ShaderDefines defines = {{"TRIANGLE_TEXELS", s(kTriangleTexels)},
                             {"NORMAL_TEXELS", s(kNormalTexels)},
                             {"NODE_TEXELS", s(kNodeTexels)},
                             {"NODE_LINK_TEXEL", s(kNodeLinkTexel)},
                             {"MATERIAL_TEXELS", s(kMaterialTexels)},
                             {"TEXCOORD_TEXELS", s(kTexcoordTexels)},
                             {"LEAF_BIT", std::to_string(kLeafBit) + "u"},
                             {"LEAF_COUNT_SHIFT", s(kLeafCountShift)},
                             {"LEAF_FIRST_MASK", std::to_string(kMaxLeafFirst) + "u"},
                             {"MATERIAL_MAPS_TEXEL", s(kMaterialMapsTexel)},
                             {"MATERIAL_ALPHA_TEXEL", s(kMaterialAlphaTexel)},
                             {"MATERIAL_EXTRA_TEXEL", s(kMaterialExtraTexel)},
                             {"MATERIAL_VOLUME_TEXEL", s(kMaterialVolumeTexel)},
                             {"MATERIAL_CLEARCOAT_TEXEL", s(kMaterialClearcoatTexel)},
                             {"MATERIAL_SHEEN_TEXEL", s(kMaterialSheenTexel)},
                             {"TANGENT_TEXELS", s(kTangentTexels)},
                             {"COLOR_TEXELS", s(kColorTexels)},
                             {"TEXTURE_WRAP_T_SHIFT", s(kTextureWrapTShift)},
                             {"TEXTURE_NEAREST_FLAG", s(kTextureNearestFlag)},
                             {"TEXTURE_SLOT1_FLAG", s(kTextureSlot1Flag)},
                             {"DIFFUSE_MAP_BIT", s(kDiffuseMapBit)},
                             {"ROUGHNESS_MAP_BIT", s(kRoughnessMapBit)},
                             {"EMISSION_MAP_BIT", s(kEmissionMapBit)},
                             {"NORMAL_MAP_BIT", s(kNormalMapBit)},
                             {"ALPHA_MAP_BIT", s(kAlphaMapBit)},
                             {"SPECULAR_MAP_BIT", s(kSpecularMapBit)},
                             {"TRIANGLE_ALPHA_FLAG", s(kTriangleAlphaFlag)},
                             {"TRIANGLE_SINGLE_SIDED_FLAG", s(kTriangleSingleSidedFlag)},
                             // The rule the caustic casters are packed by (pack/caustic_casters.h), which
                             // the shaders apply to each hit.
                             {"GLOSSY_CASTER_ROUGHNESS", std::to_string(kGlossyCasterRoughness)}};
    defines.emplace_back("PUNCTUAL_TEXELS", s(kPunctualTexels));
    if (images) {
        // A GL_ name becomes an #extension line (gl/shader_source.h): the shaders are #version 410.
        defines.emplace_back("GL_ARB_shader_image_load_store", "require");
        defines.emplace_back("SCENE_READS_IMAGES", "1");
    }
    return defines;
}

uint32_t traversalStackEntries(uint32_t treeEntries) {
    if (treeEntries > kMaxTraversalStack)
        throw Error("the scene's BVH needs a traversal stack of " + std::to_string(treeEntries) +
                    " entries; the GPU traversal handles at most " + std::to_string(kMaxTraversalStack));
    return std::max<uint32_t>(4, treeEntries);
}

}  // namespace fp::layout
