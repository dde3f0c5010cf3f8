// What both loaders do with a material's texture maps (scene.h, Material's *Texture fields).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace fp {

// The texture fields of a material, to visit them all.
std::array<int32_t*, 6> textureSlots(Material& m);

// A copy of material m for faces without texture coordinates: every map replaced by its mean (Kd, Ke
// and Ks times their map's mean linear colour, roughness and metallic times the means of G and B, alpha
// times the mean of A), the normal map dropped, so that the surface keeps the maps' average look.
Material withoutMaps(const Material& m, const std::vector<Texture>& textures);

}  // namespace fp
