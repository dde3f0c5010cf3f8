// What both loaders do with a material's texture maps (scene.h, Material's *Texture fields).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace fp {

// The texture fields of a material, to visit them all.
std::array<int32_t*, 6> textureSlots(Material& m);

// The kinds of map, in textureSlots' order.
enum class MapKind { Diffuse, MetallicRoughness, Emission, Normal, Alpha, Specular };

// Multiplies the factor that a map of `kind` scales by the map's mean over `image`: Kd, Ke and Ks by its
// mean linear colour, roughness and metallic by the means of G and B, alpha by the mean of A; a normal
// map's mean is the flat surface, so it changes nothing. What a map that cannot be drawn leaves behind.
void scaleByMapMean(Material* m, MapKind kind, const Rgba8Image& image);

// A copy of material m for faces without texture coordinates: every map replaced by its mean (Kd, Ke
// and Ks times their map's mean linear colour, roughness and metallic times the means of G and B, alpha
// times the mean of A), the normal map dropped, so that the surface keeps the maps' average look.
Material withoutMaps(const Material& m, const std::vector<Texture>& textures);

}  // namespace fp
