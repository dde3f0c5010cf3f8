#pragma once
// The accumulated sums read back from the GPU, and the estimates they give.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"

namespace fp {

struct Accumulation {
    int width = 0, height = 0;
    // Per pixel, rows top to bottom: (sum of radiance, samples), (sum of squares, dropped samples) and
    // (rays traced, samples whose camera ray hit an emitter first, 0, 0); then the first-hit guides of
    // the denoisers, summed over the samples: (shading normal, distance) and (albedo, guide samples).
    // A miss adds zeros (and 1 guide sample).
    std::vector<glm::vec4> sum, squares, counters, normalDepth, albedo;

    // The Monte Carlo estimate: sum / samples per pixel.
    Image mean() const;
    // Per pixel, the sample variance divided by the sample count: the variance of the mean itself.
    Image varianceOfMean() const;
    // Samples that were NaN or Inf and were replaced by 0 (should be none).
    uint64_t droppedSamples() const;
    // Rays traced (camera, bounce and shadow rays) over all pixels and samples.
    double raysTraced() const;
};

}  // namespace fp
