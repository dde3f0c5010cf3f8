#pragma once
// Point, spot and directional lights (PunctualLight, scene/scene.h): their names, their checks, the
// spot's falloff, their power (for light selection) and the sphere a directional light must cover.
// The shader's copies of the falloff and the emission sampling are in glsl/common/lights.glsl.
#include <cstddef>
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace fp {

constexpr PunctualLightType kAllPunctualLightTypes[] = {PunctualLightType::Point, PunctualLightType::Spot,
                                                        PunctualLightType::Directional};
const char* punctualLightTypeName(PunctualLightType type);  // "point", "spot", "directional"

// Throws fp::Error, naming the light as `where` ("lights[2]"), for one that cannot be rendered:
// non-finite values, a negative intensity, a direction (spot, directional) that is not of unit length,
// or cone angles outside glTF's 0 <= inner < outer <= pi / 2.
void validatePunctualLight(const PunctualLight& light, const std::string& where);

// glTF's spot falloff (KHR_lights_punctual, "Inner and Outer Cone Angles"): for the cosine of the angle
// between the axis and the direction to the lit point, t = (cosTheta - cosOuter) / (cosInner - cosOuter)
// clamped to [0, 1], and the intensity is scaled by t^2: 1 inside the inner cone, 0 outside the outer
// one, falling steeply from the inner angle and levelling off toward the outer one.
float spotFalloff(float cosTheta, float cosInner, float cosOuter);

// The fraction of a point light's power a spot of these angles emits: the falloff integrated over the
// sphere, over 4 pi. With t^2 linear-squared in the cosine, the integral of the ramp over [cos outer,
// cos inner] is (cos inner - cos outer) / 3, so Phi = 2 pi I ((1 - cos inner) + (cos inner - cos outer)
// / 3) (as pbrt-v4 integrates its smoothstep falloff for SpotLight::Phi, section 12.2.1, where the ramp
// gives / 2).
double spotSolidAngle(float innerConeAngle, float outerConeAngle);  // in sr: Phi / I

// The sphere that bounds the scene's triangles, slightly enlarged (by 1e-3 of its radius, which covers
// the rounding of the disk points in the shader): a directional light's light subpaths start on a disk
// of this radius facing the light (pbrt-v4, section 12.3, DirectionalLight::SampleLe), and its power is
// pi r^2 E (DirectionalLight::Phi).
struct BoundingSphere {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};
BoundingSphere directionalLightSphere(const Scene& scene);

// One line for lists (the viewer's panel, messages): "spot 'key': (x, y, z) -> (dx, dy, dz), 20-30 deg,
// I = 100, 90, 80 W/sr".
std::string describePunctualLight(const PunctualLight& light);

}  // namespace fp
