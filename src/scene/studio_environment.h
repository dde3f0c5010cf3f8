#pragma once
// The studio environment: the light a model without its own gets by default
// (request/default_light.h lightIfUnlit, --environment studio), as a model viewer lights a model with a
// neutral studio map. Made here, in code, from a few smooth shapes; no image is read or copied.
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace fp {

// Radiance arriving from the unit direction `d` (+y up; the default camera looks from +z towards -z,
// scene/scene.h frameBounds, so +x is the image's right):
// - a grey ground below the horizon (kStudioGround), the floor's bounce;
// - a sky above it rising from kStudioHorizon at the horizon to kStudioZenith overhead;
// - a soft key light, a disc of radiance kStudioKey about kStudioKeyDirection (upper left, in front of
//   the model), 20 degrees in radius with an edge that fades out to 30 degrees;
// - a fill light, dimmer and wider, from the front right, low (kStudioFill, 30 fading to 45 degrees).
// Neutral (equal channels) and of moderate dynamic range (kStudioKey / kStudioGround = 20), so that the
// environment map's importance sampling (pack/environment.h) finds the key without fireflies. A
// Lambertian surface facing +z (the default camera) shows 0.87 of its albedo after one bounce, one facing
// up 1.01 (measured, 256 spp), so an albedo of 0.8 stays within the clamp tone map.
glm::vec3 studioRadiance(const glm::vec3& d);

constexpr float kStudioGround = 0.2f, kStudioHorizon = 0.4f, kStudioZenith = 0.6f;
constexpr float kStudioKey = 4.0f, kStudioFill = 1.2f;
const glm::vec3 kStudioKeyDirection = glm::normalize(glm::vec3(-0.5f, 0.65f, 0.55f));
const glm::vec3 kStudioFillDirection = glm::normalize(glm::vec3(0.7f, 0.25f, 0.6f));

// studioRadiance baked into an equirectangular map of kStudioMapWidth x kStudioMapHeight at the texel
// centres (the renderer's mapping, scene/scene.h Environment), intensity 1, no rotation.
constexpr int kStudioMapWidth = 256, kStudioMapHeight = 128;
Environment studioEnvironment();

}  // namespace fp
