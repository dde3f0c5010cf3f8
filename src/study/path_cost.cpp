#include "study/path_cost.h"

#include "image/image_stats.h"

namespace fp::study {

PathCounts measurePathCounts(Renderer& renderer, RenderSettings settings, const Camera& camera, int spp) {
    settings.view = View::Cost;
    renderer.configure(settings, camera);
    renderer.render(spp);
    Accumulation acc = renderer.readback();
    // Every pixel took the same number of samples, so the mean of the pixel means is the path mean.
    glm::dvec3 mean = meanColor(acc.mean());
    PathCounts counts;
    counts.nodesVisited = mean.x;
    counts.trianglesTested = mean.y;
    counts.surfacesShaded = mean.z;
    counts.rays = acc.raysTraced() / (double(settings.width) * settings.height * spp);
    return counts;
}

}  // namespace fp::study
