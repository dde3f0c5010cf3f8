#pragma once
// Floating-point operations of one path, counted from the GLSL (glsl/common/, glsl/integrators/).
// Convention: an add, subtract, multiply, divide, min, max, comparison, sqrt, inversesqrt, sin or cos
// on one float is one FLOP (an FMA two, as peak figures count it); integer work (the PCG random
// numbers, texel addressing, the traversal stack) and memory reads are not FLOPs. vec3 dot = 5,
// cross = 9, normalize = 9 (dot, inversesqrt, three multiplies).
#include <string>
#include <vector>

#include "settings/render_settings.h"

namespace fp::study {

struct FlopCount {
    std::string operation;
    double flops;
    const char* breakdown;  // where the number comes from in the GLSL
};

// The per-operation table, as it appears in the report.
// - Visiting a node of the 4-wide BVH (intersect.glsl traverse), its four child boxes quantised to the
//   node's grid (pack/quantised_node.h): boxEntries' per-axis scale and offset, 3 x (1 multiply + 1
//   subtract + 1 multiply) = 9; the six planes of the four children, one multiply-add each (2), 48;
//   entry max over three axes and 0 (12), exit min (8) and ulp scale (4), min with tMax and enter <=
//   exit (8): 89; then which leaf children were hit (4), the cull of children beyond the hit (4), the
//   sorting network (5) and which children remain (4): 106. Unpacking the 8-bit planes (shifts, masks,
//   int-to-float conversions), control flow and the stack are integer work.
// - One ray-triangle test (intersectTriangle, Moller-Trumbore): cross p (9), det (5), det == 0 (1),
//   1 / det (1), s (3), u (6), cross q (9), v (6), t (6), the six comparisons and u + v (6): 52.
// - Per ray (traverse set-up): |dir| < 1e-20 test (6) and 1 / dir (3): 9.
// - Per path (camera.glsl cameraRay): jitter (2), NDC (4), forward + x right + y up (12),
//   normalize (9): 27.
// - A surface interaction (surface.glsl surfaceAt and what the integrator does there, Lambertian;
//   other BSDFs cost more, so this is a lower bound for glossy scenes); see shadingFlops().
std::vector<FlopCount> operationTable();

constexpr double kFlopsPerNode = 106.0;
constexpr double kFlopsPerTriangleTest = 52.0;
constexpr double kFlopsPerRay = 9.0;
constexpr double kFlopsPerCameraRay = 27.0;

// FLOPs of one surface interaction of `integrator` on a Lambertian surface:
// - surfaceAt: position (6), geometric normal cross + normalize (18), front-face test (6), shading
//   normal interpolation + normalize (26), its side test (6), orthonormalBasis of Duff et al. (14),
//   eta (1): 77. Emission added: 6.
// - naive: + uniform hemisphere direction with its own basis (rand 4, z and r 4, phi 2, sin cos 2,
//   r sin r cos 2, basis 14, toWorld 15) 43, the side test 6, the weight 2 albedo cos (11), Russian
//   roulette (9), spawnRay (13): 165.
// - bsdf: + toLocal (15), cosine sample (rand 6, Malley 10, pdf and test 2) 18, toWorld (15),
//   sameSide (7), weight (3), roulette (9), spawnRay (13): 163.
// - nee: bsdf's 163 + the light sample (lights.glsl sampleLight: rand 6, selection 5, triangle point
//   18, distance and direction 9, emitter cosine 23, pdf 5, tests 2) 68, toLocal and sameSide (22),
//   bsdfEval (7) and bsdfPdf (2), the power heuristic (4), the shadow ray's spawnRay (13) and length
//   (1), the MIS-weighted contribution (15) and f != 0 (3): 298.
// - bdpt: counted as nee's 298 per vertex. This is a lower bound: it leaves out the MIS weights of
//   every join (their loops over the vertices), which bdpt adds.
// Every surfaceAt call counts as a whole interaction, also the last vertex of a path that only adds its
// emission (depth limit reached): an overestimate of at most one interaction per path.
double shadingFlops(Integrator integrator);

// What the cost view measured, per path (mean over all paths rendered).
struct PathCounts {
    double nodesVisited = 0.0, trianglesTested = 0.0, surfacesShaded = 0.0, rays = 0.0;
};

// nodes * kFlopsPerNode + triangles * kFlopsPerTriangleTest + rays * kFlopsPerRay + kFlopsPerCameraRay +
// surfaces * shadingFlops(integrator), the constants above.
double flopsPerPath(const PathCounts& counts, Integrator integrator);

}  // namespace fp::study
