#include "render/accumulation.h"

#include <algorithm>

namespace fp {

Image Accumulation::mean() const {
    Image image(width, height);
    for (size_t i = 0; i < sum.size(); ++i)
        image.pixels[i] = sum[i].w > 0.0f ? glm::vec3(sum[i]) / sum[i].w : glm::vec3(0.0f);
    if (lightPathsPerPixel > 0.0)
        for (size_t i = 0; i < splatSum.size(); ++i)
            image.pixels[i] += glm::vec3(glm::dvec3(splatSum[i]) / lightPathsPerPixel);
    return image;
}

Image Accumulation::varianceOfMean() const {
    Image image(width, height);
    for (size_t i = 0; i < sum.size(); ++i) {
        float n = sum[i].w;
        if (n < 2.0f) continue;
        glm::vec3 m = glm::vec3(sum[i]) / n;
        // Unbiased sample variance (sum x^2 - n m^2) / (n - 1), then / n for the mean.
        glm::vec3 variance = glm::max(glm::vec3(squares[i]) - n * m * m, glm::vec3(0.0f)) / (n - 1.0f);
        image.pixels[i] = variance / n;
    }
    if (lightPathsPerPixel > 0.0) {
        double n = lightPathsPerPixel, paths = n * double(width) * double(height);
        for (size_t i = 0; i < splatSum.size(); ++i) {
            glm::dvec3 splat = glm::dvec3(splatSum[i]) / n;
            glm::dvec3 variance = glm::dvec3(splatSquares[i]) / (n * n) - splat * splat / paths;
            image.pixels[i] += glm::vec3(glm::max(variance, glm::dvec3(0.0)));
        }
    }
    return image;
}

uint64_t Accumulation::droppedSamples() const {
    uint64_t dropped = 0;
    for (const glm::vec4& s : squares) dropped += uint64_t(s.w);
    for (const glm::vec4& s : splatSquares) dropped += uint64_t(s.w);
    return dropped;
}

uint64_t Accumulation::pixelsShortOf(int samples) const {
    uint64_t pixels = 0;
    for (const glm::vec4& s : sum) pixels += s.w < float(samples);
    return pixels;
}

double Accumulation::raysTraced() const {
    double rays = 0.0;
    for (const glm::vec4& c : counters) rays += double(c.x);
    for (const glm::vec4& s : splatSum) rays += double(s.w);
    return rays;
}

}  // namespace fp
