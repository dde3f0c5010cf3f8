#pragma once
// The caustic casters: the surfaces whose material has a delta lobe (smooth glass, a mirror, a smooth
// coat) or is a nearly smooth metal (a glossy caster: its one lobe narrower than kGlossyCasterRoughness),
// bounded by a few spheres. nee's light pass (--caustics light, glsl/common/caustic_casters.glsl) aims its
// light paths at them: a caustic path's first bounce after the light is on one of them.
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace fp {

// At most this many spheres (the shaders' MAX_CAUSTIC_CASTERS), so that each light path's direction
// costs a few cone tests.
constexpr int kMaxCausticCasters = 8;
// Roughness under which a lobe is a delta lobe: glsl/common/bsdf.glsl's kSmooth.
constexpr float kSmoothRoughness = 0.01f;

// Roughness under which a metal is a glossy caster (the shaders' GLOSSY_CASTER_ROUGHNESS, set from this):
// the light its highlight throws on the walls is a caustic the light pass traces, not camera paths (a
// wall's BSDF sample reaches the lamp by way of the metal's narrow lobe only by chance: fireflies).
constexpr float kGlossyCasterRoughness = 0.35f;

// Whether some point of a surface of this material can have a delta lobe: every model but the
// Lambertian has a specular lobe, a delta one below kSmoothRoughness. A roughness map multiplies the
// factor by its G channel, filtered bilinearly, so by at least its smallest texel: `textures` (the
// scene's) bound it; a map that is not there counts as one that can reach 0. Each call reads the whole
// map: a question about one material (causticCasterSpheres asks each material once).
bool hasDeltaLobe(const Material& m, const std::vector<Texture>& textures);

// Whether some point of a surface of this material can be a glossy caster: a conductor, or a
// metallic-roughness material of metallic factor 1 (a metallic map can only lower it), whose roughness,
// scaled by its map as in hasDeltaLobe, can fall below kGlossyCasterRoughness.
bool isGlossyCasterMaterial(const Material& m, const std::vector<Texture>& textures);

// (centre, radius) spheres that together hold every triangle of a caster material (either of the above),
// world triangles and instances' alike; empty when there is none. One sphere per such material (per instance
// for instanced meshes), centred on its box; while there are more than kMaxCausticCasters, the two whose
// union is smallest are merged (over 64, all of them into one). Each material is judged once and each
// roughness map read at most once, however many triangles share them: O(triangles + texels).
// `roughnessMapsRead`, when given, receives how many maps were read (for the tests).
std::vector<glm::vec4> causticCasterSpheres(const Scene& scene, size_t* roughnessMapsRead = nullptr);

}  // namespace fp
