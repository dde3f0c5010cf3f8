#pragma once
// The native reference's path tracer: next-event estimation with MIS on Lambertian surfaces, the
// algorithm of glsl/integrators/nee.glsl step for step (same random stream per pixel and sample, same
// camera, a thin lens included, light selection, power heuristic and Russian roulette), on one thread.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "native/native_scene.h"
#include "scene/scene.h"
#include "settings/render_settings.h"

namespace fp::native {

struct Settings {
    int width = 512, height = 512;
    int maxDepth = kDefaultMaxDepth;
    uint32_t seed = 0;
    int spp = 1;
    uint32_t sampleOffset = 0;  // the first sample index
};

struct Result {
    int width = 0, height = 0;
    // Per pixel, rows top to bottom as fp::Accumulation stores them: (sum of radiance, samples) and
    // (sum of squared radiance, 0).
    std::vector<glm::vec4> sum, squares;
    double paths = 0, rays = 0;
    double cpuSeconds = 0;  // CPU time of the calling thread while tracing
};

// Renders `settings.spp` samples per pixel of `scene` seen from `camera`.
Result render(const Scene& scene, const Camera& camera, const Settings& settings);

}  // namespace fp::native
