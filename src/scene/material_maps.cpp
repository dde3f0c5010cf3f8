#include "scene/material_maps.h"

#include "image/rgba8_image.h"

namespace fp {

std::array<int32_t*, 6> textureSlots(Material& m) {
    return {&m.diffuseTexture, &m.metallicRoughnessTexture, &m.emissionTexture, &m.normalTexture,
            &m.alphaTexture,   &m.specularTexture};
}

Material withoutMaps(const Material& m, const std::vector<Texture>& textures) {
    Material copy = m;
    auto image = [&textures](int32_t t) -> const Rgba8Image& {
        return textures[static_cast<size_t>(t)].image;
    };
    if (m.diffuseTexture >= 0) copy.diffuse *= meanLinearColor(image(m.diffuseTexture));
    if (m.emissionTexture >= 0) copy.emission *= meanLinearColor(image(m.emissionTexture));
    if (m.specularTexture >= 0) copy.specular *= meanLinearColor(image(m.specularTexture));
    if (m.metallicRoughnessTexture >= 0) {
        glm::vec4 mean = meanCodes(image(m.metallicRoughnessTexture));
        copy.roughness *= mean.g;
        copy.metallic *= mean.b;
    }
    if (m.alphaTexture >= 0) copy.alpha *= meanCodes(image(m.alphaTexture)).a;
    for (int32_t* slot : textureSlots(copy)) *slot = -1;
    return copy;
}

}  // namespace fp
