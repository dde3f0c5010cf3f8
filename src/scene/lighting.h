#pragma once
// What lights a scene: whether anything does, the neutral sky a scene without light gets, and the
// environment maps a scene file or the command line names.
#include <string>

#include "scene/scene.h"

namespace fp {

// True when something in the scene emits light: a triangle of an emissive material, a point, spot or
// directional light that is not black, or an environment that is not black (a non-zero colour, or a map
// with a positive texel and a positive intensity).
// Anything that adds a kind of light to Scene must be counted here too.
bool hasLight(const Scene& scene);

// The uniform white sky (--environment 1, and the native reference's default light): a constant environment
// of radiance 1 from every direction. It is the most neutral choice (no direction, colour or time of day
// favoured), every renderer draws it (the native reference has constant colours only), and it has analytic
// answers: an unoccluded Lambertian surface of albedo k shows exactly k after one bounce, as in a white
// furnace.
Environment defaultSky();

// The light lightIfUnlit gives: the studio environment (scene/studio_environment.h), or, for the native
// reference, which has constant skies only, the uniform white sky (defaultSky).
enum class DefaultLight { Studio, UniformSky };

// Lights a scene that has no light of its own as a model viewer does: unless it has a punctual light or
// an environment that is not black, or emitters that light it (scene/own_light.h: a closed room's lamp,
// not a glowing visor), it gets `light`, with a note (not a warning: it is the documented default, not
// a repair, so --strict does not refuse it) that says why and how to keep it dark (--environment none).
// Returns whether it did.
bool lightIfUnlit(Scene& scene, DefaultLight light = DefaultLight::Studio);

// An equirectangular environment map by its extension (case-insensitive): a Radiance .hdr (RGBE) or
// an OpenEXR .exr of linear radiance (image/exr.h decodeExrRadiance: R, G, B or Y; multi-part, deep,
// tiled and integer files are refused). `label` says where the path came from, for errors: "scene.json:
// environment map 'sky.png'". Negative and non-finite texels, which a map of radiance cannot hold and
// importance sampling cannot weigh, become 0 with one warning.
Image loadEnvironmentMap(const std::string& path, const std::string& label);

// Whether `path` has an extension loadEnvironmentMap reads.
bool isEnvironmentMapPath(const std::string& path);

}  // namespace fp
