#pragma once
// The counting mode: renders the `cost` view (glsl/passes/debug_views.glsl), in which every sample
// runs the integrator's whole path and returns the BVH nodes it visited, the triangles it tested and
// the surfaces it shaded, summed over its rays; the accumulated mean is the average path.
#include "render/renderer.h"
#include "study/flop_model.h"

namespace fp::study {

// Leaves the renderer configured for the cost view; `settings` gives size, depth, seed, integrator.
PathCounts measurePathCounts(Renderer& renderer, RenderSettings settings, const Camera& camera, int spp);

}  // namespace fp::study
