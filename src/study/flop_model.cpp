#include "study/flop_model.h"

namespace fp::study {

std::vector<FlopCount> operationTable() {
    return {
        {"BVH node visited (4-wide: four slab tests)", kFlopsPerNode,
         "boxEntries: node terms 9, 24 plane multiply-adds 48, 4 x (3 max, 3 min/scale, 2 tests); 4 + 4 + 4 "
         "child tests, 5 sorting compares"},
        {"ray-triangle test (Moller-Trumbore)", kFlopsPerTriangleTest,
         "2 cross, 4 dot, 1 reciprocal, 3 sub, 3 scale, 6 tests"},
        {"ray set-up", kFlopsPerRay, "tiny-direction guard 6, reciprocal direction 3"},
        {"camera ray", kFlopsPerCameraRay, "jitter, NDC, image-plane point, normalize"},
        {"surface interaction, naive", shadingFlops(Integrator::Naive),
         "surfaceAt 77, emission 6, uniform hemisphere 43, weight, roulette, spawn"},
        {"surface interaction, bsdf", shadingFlops(Integrator::Bsdf),
         "surfaceAt 77, emission 6, cosine sample, frames, roulette, spawn"},
        {"surface interaction, nee", shadingFlops(Integrator::Nee),
         "bsdf's 163 + light sample 68, BSDF eval + pdf, MIS, shadow ray"},
        {"surface interaction, bdpt", shadingFlops(Integrator::Bdpt),
         "as nee (lower bound: join MIS weights not counted)"},
    };
}

double shadingFlops(Integrator integrator) {
    switch (integrator) {
        case Integrator::Naive:
            return 165.0;
        case Integrator::Bsdf:
            return 163.0;
        case Integrator::Nee:
        case Integrator::Bdpt:
            return 298.0;
    }
    return 298.0;
}

double flopsPerPath(const PathCounts& c, Integrator integrator) {
    return c.nodesVisited * kFlopsPerNode + c.trianglesTested * kFlopsPerTriangleTest +
           c.rays * kFlopsPerRay + kFlopsPerCameraRay + c.surfacesShaded * shadingFlops(integrator);
}

}  // namespace fp::study
