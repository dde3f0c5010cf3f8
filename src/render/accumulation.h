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
    // (rays traced, samples whose camera ray hit an emitter first, samples whose camera ray hit anything,
    // 0), the last two counted with the guides only; then the first-hit guides of
    // the denoisers, summed over the samples: (shading normal, distance) and (albedo, guide samples).
    // A miss adds zeros (and 1 guide sample).
    std::vector<glm::vec4> sum, squares, counters, normalDepth, albedo;
    // bdpt's light image (render/light_splat.h), empty for the other integrators: per pixel, (sum of the
    // light-traced contributions that landed there, rays traced by light paths launched there) and (sum
    // of their squares, non-finite contributions dropped); and N, the light paths traced per pixel
    // (those launched over the whole image / pixels), samples resumed from a file included.
    std::vector<glm::vec4> splatSum, splatSquares;
    double lightPathsPerPixel = 0.0;

    // The Monte Carlo estimate: sum / samples per pixel, plus splatSum / N (pbrt-v3 16.3: splats are
    // scaled by 1 / spp).
    Image mean() const;
    // Per pixel, the variance of that estimate. The camera part: the sample variance divided by the
    // sample count. The light image at a pixel is (1/N) times a sum of M = N W H independent per-path
    // contributions X (most of them 0), so its variance is M Var(X) / N^2, estimated as
    // sum X^2 / N^2 - (splatSum / N)^2 / M. The two parts are added as if independent: they share only
    // the light subpaths of the pixel's own samples, 1 / (W H) of those that splat onto it.
    Image varianceOfMean() const;
    // Samples that were NaN or Inf and were replaced by 0 (should be none).
    uint64_t droppedSamples() const;
    // Pixels holding fewer than `samples` samples: a driver that cut the pass's shader loops short
    // (llvmpipe stops them after a fixed number of iterations in all; RenderSettings::samplesPerPass).
    uint64_t pixelsShortOf(int samples) const;
    // Rays traced (camera, bounce and shadow rays) over all pixels and samples.
    double raysTraced() const;
};

// The same on the GPU, for a display pass: the (radiance sum, samples) texture and, for bdpt, the light
// image's (sum, rays) texture and N (0: no light image), and its (sum of squares, dropped) texture for
// the denoisers' variance.
struct AccumulationTextures {
    uint32_t sum = 0, splatSum = 0;
    float lightPathsPerPixel = 0.0f;
    uint32_t splatSquares = 0;
};

}  // namespace fp
