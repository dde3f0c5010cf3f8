#include "scene/material_maps.h"

#include "image/rgba8_image.h"

namespace fp {

std::array<int32_t*, 6> textureSlots(Material& m) {
    return {&m.diffuseTexture, &m.metallicRoughnessTexture, &m.emissionTexture, &m.normalTexture,
            &m.alphaTexture,   &m.specularTexture};
}

void scaleByMapMean(Material* m, MapKind kind, const Rgba8Image& image) {
    switch (kind) {
        case MapKind::Diffuse:
            m->diffuse *= meanLinearColor(image);
            break;
        case MapKind::Emission:
            m->emission *= meanLinearColor(image);
            break;
        case MapKind::Specular:
            m->specular *= meanLinearColor(image);
            break;
        case MapKind::MetallicRoughness: {
            glm::vec4 mean = meanCodes(image);
            m->roughness *= mean.g;
            m->metallic *= mean.b;
            break;
        }
        case MapKind::Alpha:
            m->alpha *= meanCodes(image).a;
            break;
        case MapKind::Normal:
            break;  // a flat surface is the mean look of a normal map
    }
}

Material withoutMaps(const Material& m, const std::vector<Texture>& textures) {
    Material copy = m;
    const int32_t maps[] = {m.diffuseTexture, m.metallicRoughnessTexture, m.emissionTexture, m.normalTexture,
                            m.alphaTexture,   m.specularTexture};
    const MapKind kinds[] = {MapKind::Diffuse, MapKind::MetallicRoughness, MapKind::Emission, MapKind::Normal,
                             MapKind::Alpha,   MapKind::Specular};
    for (size_t k = 0; k < 6; ++k)
        if (maps[k] >= 0) scaleByMapMean(&copy, kinds[k], textures[static_cast<size_t>(maps[k])].image);
    for (int32_t* slot : textureSlots(copy)) *slot = -1;
    return copy;
}

}  // namespace fp
