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
// The two halves of hasLight: a triangle of an emissive material; a punctual light or an environment
// that is not black (the light a scene's author chose, as request/default_light.h weighs it).
bool hasEmitters(const Scene& scene);
bool hasPunctualOrEnvironmentLight(const Scene& scene);

// The uniform white sky (--environment 1, and the native reference's default light): a constant environment
// of radiance 1 from every direction. It is the most neutral choice (no direction, colour or time of day
// favoured), every renderer draws it (the native reference has constant colours only), and it has analytic
// answers: an unoccluded Lambertian surface of albedo k shows exactly k after one bounce, as in a white
// furnace.
Environment defaultSky();

// An equirectangular environment map by its extension (case-insensitive): a Radiance .hdr (RGBE) or
// an OpenEXR .exr of linear radiance (image/exr.h decodeExrRadiance: R, G, B or Y; multi-part, deep,
// tiled and integer files are refused). `label` says where the path came from, for errors: "scene.json:
// environment map 'sky.png'". Negative and non-finite texels, which a map of radiance cannot hold and
// importance sampling cannot weigh, become 0 with one warning.
Image loadEnvironmentMap(const std::string& path, const std::string& label);

// Whether `path` has an extension loadEnvironmentMap reads.
bool isEnvironmentMapPath(const std::string& path);

}  // namespace fp
