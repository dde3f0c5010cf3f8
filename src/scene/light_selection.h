#pragma once
// How light sampling chooses an emitter: in proportion to its power, with probabilities that are
// exactly the ones the shader's pick realises (glsl/common/lights.glsl pickLight), for the GPU packer
// and the native reference alike.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace fp {

// Rec. 709 luminance: the weight of a colour's channels in an emitter's power.
float luminance(const glm::vec3& rgb);

// The power of a punctual light (scene/scene.h) in watts, of the luminance of its colour: 4 pi I for a
// point light, I times spotSolidAngle for a spot (scene/punctual_light.h), pi r^2 E for a directional
// light, r the radius of the sphere its light subpaths start from (pbrt-v4, sections 12.2, 12.2.1 and
// 12.3, PointLight::Phi, SpotLight::Phi and DirectionalLight::Phi). `sceneRadius` matters only for the
// last.
double punctualLightPower(const PunctualLight& light, float sceneRadius);

// The mean radiance (luminance) of a material's emitters over their area, as far as it is known without
// texture coordinates: Ke times its emission map's mean colour, times the coverage of a constant alpha
// (BLEND: alpha; MASK: 0 or 1). An emitter whose mean is 0 emits nothing anywhere (a black map, or no
// coverage), so light sampling may skip it.
double meanEmittedLuminance(const Scene& scene, const Material& material);

struct EmitterPmfs {
    std::vector<float> pmf;          // per triangle, in the order asked for; 0 for non-emitters
    std::vector<float> punctualPmf;  // per Scene::punctualLights entry, after the triangles in the cdf
    double totalPower = 0.0;         // sum of the powers below
};

// The selection probabilities of scene's triangles order[0 .. count) (e.g. a BVH's leaf order) and then
// of its punctual lights, each in proportion to its power, as lightPmfs rounds them. The powers are in
// the unit of luminance(Ke) * area, a triangle's power divided by pi (a one-sided Lambertian emitter of
// radiance L and area A emits pi L A): so a punctual light's is punctualLightPower / pi. A scene
// without punctual lights gets the probabilities it always had, to the bit. Ke is taken times its
// emission map's mean colour and a constant coverage (BLEND alpha; MASK 0 or 1), so that an emitter
// that emits nothing anywhere is never picked; the shader's light samples then carry the map and
// coverage at their point (lights.glsl emitterRadiance).
EmitterPmfs emitterPmfs(const Scene& scene, const uint32_t* order, size_t count);

// Probabilities proportional to `power`, on the 2^-24 grid of the shader's random numbers and summing to
// 1 exactly: the cdf is summed in double and rounded to the grid, and each pmf is the difference of two
// rounded entries. The shader picks the first emitter whose cdf exceeds u = k / 2^24, so the number its
// pdf uses is then the probability of the pick for any count of emitters (a cdf summed in float drifts
// from the stored pmfs by far more than a small emitter's share once there are ~1e5 of them). An emitter
// whose share rounds to 0 is never picked and has density 0; BSDF sampling then covers it in full (its
// MIS weight is 1), which is still unbiased.
std::vector<float> lightPmfs(const std::vector<double>& power, double totalPower);

}  // namespace fp
