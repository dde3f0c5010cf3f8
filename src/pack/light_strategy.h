#pragma once
// Which light sampling LightSampling::Auto chooses for a scene (settings/render_settings.h).
#include "bvh/bvh.h"
#include "scene/scene.h"

namespace fp {

// Whether some emitter subtends more than 0.5 sr from the surface its normal meets first (a ray from the
// centre of each emitter triangle, at most 4096 of them): a lamp close above a floor, a light panel
// beside a wall. There sampling the emitter uniformly in solid angle has several times less variance
// than by area (BENCHMARKS.md, "Samplers"); elsewhere the two are alike, and the spherical code left
// out of the shader saves about 7 % of llvmpipe's instructions on the Cornell box (a branch that is never
// taken still costs registers). bvh is built over the scene's triangles in their order; with instances
// (scene/instancing.h) meshBvhs over each mesh's triangles, and the instances count as surfaces too.
bool emittersFaceCloseSurfaces(const Scene& scene, const Bvh& bvh, const std::vector<Bvh>& meshBvhs = {});

// Which emitter choice LightSelection::Auto makes: the light tree (pack/light_tree.h) for scenes of at
// least kLightTreeMinEmitters emitter triangles, where the power of a far or turned-away emitter would
// waste samples; below, the pick by power, which costs less per sample. Measured in halls of ceiling
// lamps (BENCHMARKS.md, "Samplers"): the tree needs 1.17x power's time for equal error with 8 emitter
// triangles, 1.02x with 32, 0.98x with 96 and 0.63-0.67x with 224.
constexpr uint32_t kLightTreeMinEmitters = 64;
inline bool lightTreePays(uint32_t emitterTriangles) {
    return emitterTriangles >= kLightTreeMinEmitters;
}

}  // namespace fp
