// LDR-FLIP's feature pipeline (Andersson et al. 2020): edges and points of the achromatic channel,
// found with first and second derivatives of a Gaussian the size of the eye's edge detector; the
// larger of the two differences between the images, scaled to [0, 1] and raised to qf.
#include <algorithm>
#include <cmath>
#include <vector>

#include "image/color_space.h"
#include "image/flip_pipelines.h"
#include "image/plane_filter.h"

namespace fp {

namespace {

// Positive weights scaled to sum to 1 and negative weights to sum to -1, as the paper normalises its
// feature detectors, so that a unit step gives a response of 1 whatever the filter's width.
void normaliseSigned(std::vector<double>& kernel) {
    double positive = 0.0, negative = 0.0;
    for (double k : kernel) (k > 0.0 ? positive : negative) += k;
    for (double& k : kernel) {
        if (k > 0.0) k /= positive;
        if (k < 0.0) k /= -negative;
    }
}

// The detectors: derivatives of a Gaussian g of standard deviation sigma = w / 2 degrees. The 2D edge
// filter is -x g(x, y) and the point filter (x^2 / sigma^2 - 1) g(x, y) (and their transposes for y);
// both are a 1D kernel along x times a normalised Gaussian along y, and normalising the 1D kernel's
// signed parts normalises the 2D kernel's.
struct FeatureKernels {
    std::vector<double> gaussian, edge, point;
};

FeatureKernels featureKernels(double pixelsPerDegree) {
    const double sigma = 0.5 * kFlipW * pixelsPerDegree;  // in pixels
    const int r = std::max(1, int(std::ceil(3.0 * sigma)));
    FeatureKernels k;
    double sum = 0.0;
    for (int i = -r; i <= r; ++i) {
        const double x = double(i), g = std::exp(-x * x / (2.0 * sigma * sigma));
        k.gaussian.push_back(g);
        k.edge.push_back(-x * g);
        k.point.push_back((x * x / (sigma * sigma) - 1.0) * g);
        sum += g;
    }
    for (double& g : k.gaussian) g /= sum;
    normaliseSigned(k.edge);
    normaliseSigned(k.point);
    return k;
}

// The achromatic channel normalised to [0, 1]: YCxCz's Y as (Y + 16) / 116, which is relative luminance.
Plane achromatic(const Image& image) {
    Plane y(image.width, image.height);
    const double white = whiteXyz().y;
    for (size_t i = 0; i < image.pixels.size(); ++i)
        y.values[i] = linearRgbToXyz(ldrPixel(image.pixels[i])).y / white;
    return y;
}

// The magnitudes of the edge and point responses, |(response along x, response along y)|.
struct Features {
    Plane edges, points;
};

Features detectFeatures(const Image& image, const FeatureKernels& k) {
    const Plane y = achromatic(image);
    auto magnitude = [&](const std::vector<double>& detector) {
        Plane along = filterSeparable(y, detector, k.gaussian);
        const Plane across = filterSeparable(y, k.gaussian, detector);
        for (size_t i = 0; i < along.values.size(); ++i)
            along.values[i] = std::hypot(along.values[i], across.values[i]);
        return along;
    };
    return {magnitude(k.edge), magnitude(k.point)};
}

}  // namespace

std::vector<double> flipFeatureError(const Image& test, const Image& reference, double pixelsPerDegree) {
    const FeatureKernels kernels = featureKernels(pixelsPerDegree);
    const Features t = detectFeatures(test, kernels), r = detectFeatures(reference, kernels);
    std::vector<double> error(test.pixels.size());
    for (size_t i = 0; i < error.size(); ++i) {
        const double difference = std::max(std::abs(t.edges.values[i] - r.edges.values[i]),
                                           std::abs(t.points.values[i] - r.points.values[i]));
        // Each magnitude is at most sqrt(2) (a unit response along x and along y), so this is in [0, 1].
        error[i] = std::pow(difference / std::sqrt(2.0), kFlipQf);
    }
    return error;
}

}  // namespace fp
