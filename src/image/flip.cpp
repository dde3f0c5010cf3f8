// LDR-FLIP as the combination of its two pipelines (flip_pipelines.h), and HDR-FLIP over it (see
// flip.h for the papers).
#include "image/flip.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/statistics.h"
#include "image/color_space.h"
#include "image/flip_pipelines.h"
#include "image/tone_map.h"

namespace fp {

namespace {

void checkInputs(const Image& test, const Image& reference, double pixelsPerDegree) {
    if (test.width != reference.width || test.height != reference.height)
        throw Error("cannot compare a " + std::to_string(test.width) + "x" + std::to_string(test.height) +
                    " image with a " + std::to_string(reference.width) + "x" +
                    std::to_string(reference.height) + " image");
    if (test.pixels.empty() || test.pixels.size() != reference.pixels.size())
        throw Error("cannot compare empty images");
    if (!(pixelsPerDegree > 0.0) || !std::isfinite(pixelsPerDegree))
        throw Error("pixels per degree must be a positive number, not " + std::to_string(pixelsPerDegree));
}

}  // namespace

double pixelsPerDegree(double distance, double displayWidth, int displayPixels) {
    return distance * (double(displayPixels) / displayWidth) * 3.14159265358979323846 / 180.0;
}

FlipResult ldrFlip(const Image& test, const Image& reference, double pixelsPerDegree) {
    checkInputs(test, reference, pixelsPerDegree);
    const std::vector<double> color = flipColorError(test, reference, pixelsPerDegree);
    const std::vector<double> feature = flipFeatureError(test, reference, pixelsPerDegree);
    FlipResult result{Image(test.width, test.height), 0.0};
    double sum = 0.0;
    for (size_t i = 0; i < color.size(); ++i) {
        // Feature differences sharpen the colour error: an exponent below 1 raises values in (0, 1).
        const double error = std::pow(color[i], 1.0 - feature[i]);
        result.errorMap.pixels[i] = glm::vec3(float(error));
        sum += error;
    }
    result.mean = sum / double(color.size());
    return result;
}

float hdrFlipToneMap(float x) {
    if (!(x > 0.0f)) return 0.0f;  // also NaN
    if (std::isinf(x)) return 1.0f;
    return std::clamp(toneMapAces(0.6f * x), 0.0f, 1.0f);
}

FlipExposures hdrFlipExposures(const Image& reference) {
    if (reference.pixels.empty()) throw Error("cannot compare empty images");
    // The radiance hdrFlipToneMap maps to 0.85: the positive root of the ACES fit's
    // (a - t c) u^2 + (b - t d) u - t e = 0 at t = 0.85, for u = 0.6 x.
    const double t = 0.85, qa = kAcesA - t * kAcesC, qb = kAcesB - t * kAcesD, qc = -t * kAcesE;
    const double x85 = (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa) / 0.6;

    std::vector<double> luminance, positive;
    double largest = 0.0;
    for (const glm::vec3& p : reference.pixels) {
        const double y = linearRgbToXyz(glm::max(glm::dvec3(p), 0.0)).y;  // channels as tone mapped
        const double finite = std::isfinite(y) ? y : 0.0;
        luminance.push_back(finite);
        if (finite > 0.0) positive.push_back(finite);
        largest = std::max(largest, finite);
    }
    FlipExposures e;
    if (positive.empty()) return e;  // all black: start = stop = 0
    double typical = median(luminance);
    if (typical <= 0.0) typical = median(positive);
    e.start = std::log2(x85 / largest);
    e.stop = std::log2(x85 / typical);
    e.count = std::max(2, int(std::ceil(e.stop - e.start)));
    return e;
}

FlipResult hdrFlip(const Image& test, const Image& reference, double pixelsPerDegree,
                   const FlipExposures& exposures) {
    checkInputs(test, reference, pixelsPerDegree);
    FlipResult result{Image(test.width, test.height), 0.0};
    const int count = std::max(exposures.count, 1);
    for (int i = 0; i < count; ++i) {
        const double exposure =
            exposures.start + i * (exposures.stop - exposures.start) / std::max(count - 1, 1);
        const float scale = float(std::exp2(exposure));
        auto toneMapped = [&](const Image& image) {
            Image out(image.width, image.height);
            for (size_t p = 0; p < image.pixels.size(); ++p)
                for (int c = 0; c < 3; ++c) out.pixels[p][c] = hdrFlipToneMap(scale * image.pixels[p][c]);
            return out;
        };
        const FlipResult ldr = ldrFlip(toneMapped(test), toneMapped(reference), pixelsPerDegree);
        for (size_t p = 0; p < ldr.errorMap.pixels.size(); ++p)
            result.errorMap.pixels[p] = glm::max(result.errorMap.pixels[p], ldr.errorMap.pixels[p]);
    }
    double sum = 0.0;
    for (const glm::vec3& p : result.errorMap.pixels) sum += p.r;
    result.mean = sum / double(result.errorMap.pixels.size());
    return result;
}

FlipResult hdrFlip(const Image& test, const Image& reference, double pixelsPerDegree) {
    checkInputs(test, reference, pixelsPerDegree);
    return hdrFlip(test, reference, pixelsPerDegree, hdrFlipExposures(reference));
}

}  // namespace fp
