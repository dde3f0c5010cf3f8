#include "study/flop_model.h"

#include "settings/integrators.h"

namespace fp::study {

std::vector<FlopCount> operationTable() {
    std::vector<FlopCount> table = {
        {"BVH node visited (4-wide: four slab tests)", kFlopsPerNode,
         "boxEntries: node terms 9, 24 plane multiply-adds 48, 4 x (3 max, 3 min/scale, 2 tests); 4 + 4 + 4 "
         "child tests, 5 sorting compares"},
        {"ray-triangle test (Moller-Trumbore)", kFlopsPerTriangleTest,
         "2 cross, 4 dot, 1 reciprocal, 3 sub, 3 scale, 6 tests"},
        {"ray set-up", kFlopsPerRay, "tiny-direction guard 6, reciprocal direction 3"},
        {"camera ray", kFlopsPerCameraRay, "jitter, NDC, image-plane point, normalize"},
    };
    for (Integrator i : kAllIntegrators)
        table.push_back({std::string("surface interaction, ") + integratorName(i), shadingFlops(i),
                         integratorFacts(i).flopNote});
    return table;
}

double shadingFlops(Integrator integrator) {
    return integratorFacts(integrator).shadingFlops;
}

double flopsPerPath(const PathCounts& c, Integrator integrator) {
    return c.nodesVisited * kFlopsPerNode + c.trianglesTested * kFlopsPerTriangleTest +
           c.rays * kFlopsPerRay + kFlopsPerCameraRay + c.surfacesShaded * shadingFlops(integrator);
}

}  // namespace fp::study
