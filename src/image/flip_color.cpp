// LDR-FLIP's colour pipeline (Andersson et al. 2020): both images into the opponent space YCxCz,
// filtered per channel by the contrast sensitivity functions, clamped to the sRGB cube, into CIELAB
// with the Hunt adjustment, compared by HyAB, raised to qc and remapped to [0, 1].
#include <cmath>
#include <utility>
#include <vector>

#include "image/color_space.h"
#include "image/flip_pipelines.h"
#include "image/plane_filter.h"

namespace fp {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The contrast sensitivity functions as spatial filters (the paper's table of their parameters):
// S(x) = a1 sqrt(pi / b1) exp(-pi^2 x^2 / b1) + a2 sqrt(pi / b2) exp(-pi^2 x^2 / b2), x in degrees,
// one per opponent channel. The achromatic and red-green ones have a single term (a2 = 0); b2 = 1e-5
// only keeps the formula defined.
struct Csf {
    double a1, b1, a2, b2;
};
constexpr Csf kCsf[3] = {{1.0, 0.0047, 0.0, 1e-5},    // Y: achromatic
                         {1.0, 0.0053, 0.0, 1e-5},    // Cx: red-green
                         {34.1, 0.04, 13.5, 0.025}};  // Cz: blue-yellow
// Every channel's filter has the radius of the widest Gaussian, 3 standard deviations of it.
constexpr double kWidestB = 0.04;

// The image in YCxCz, one plane per channel.
std::vector<Plane> toYcxcz(const Image& image) {
    std::vector<Plane> planes(3, Plane(image.width, image.height));
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const glm::dvec3 o = xyzToYcxcz(linearRgbToXyz(ldrPixel(image.pixels[i])));
        for (int c = 0; c < 3; ++c) planes[size_t(c)].values[i] = o[c];
    }
    return planes;
}

// One channel filtered by its CSF, sampled at pixel spacing 1 / pixelsPerDegree degrees and normalised
// to sum 1. Each Gaussian term is separable, so the 2D filter is a weighted sum of separable passes.
Plane csfFilter(const Plane& plane, const Csf& csf, double pixelsPerDegree) {
    const int r = int(std::ceil(3.0 * std::sqrt(kWidestB / (2.0 * kPi * kPi)) * pixelsPerDegree));
    struct Term {
        double weight;
        std::vector<double> gaussian;
    };
    std::vector<Term> terms;
    double total = 0.0;  // the sum of the 2D kernel's weights
    for (auto [a, b] : {std::pair{csf.a1, csf.b1}, std::pair{csf.a2, csf.b2}}) {
        if (a == 0.0) continue;
        Term term{a * std::sqrt(kPi / b), std::vector<double>(size_t(2 * r + 1))};
        double sum = 0.0;
        for (int i = -r; i <= r; ++i) {
            const double x = i / pixelsPerDegree;
            sum += term.gaussian[size_t(i + r)] = std::exp(-kPi * kPi * x * x / b);
        }
        total += term.weight * sum * sum;
        terms.push_back(std::move(term));
    }
    Plane out(plane.width, plane.height);
    for (const Term& term : terms) {
        const Plane filtered = filterSeparable(plane, term.gaussian, term.gaussian);
        for (size_t i = 0; i < out.values.size(); ++i)
            out.values[i] += term.weight / total * filtered.values[i];
    }
    return out;
}

glm::dvec3 perceived(const glm::dvec3& linearRgb) {
    return huntAdjust(xyzToLab(linearRgbToXyz(linearRgb)));
}

// Each pixel as the eye sees it: the CSF-filtered opponent channels back in linear RGB, clamped to the
// sRGB cube (filtering can leave it), then Hunt-adjusted CIELAB.
std::vector<glm::dvec3> perceivedColors(const Image& image, double pixelsPerDegree) {
    const std::vector<Plane> ycxcz = toYcxcz(image);
    std::vector<Plane> filtered;
    for (int c = 0; c < 3; ++c) filtered.push_back(csfFilter(ycxcz[size_t(c)], kCsf[c], pixelsPerDegree));
    std::vector<glm::dvec3> lab(image.pixels.size());
    for (size_t i = 0; i < lab.size(); ++i) {
        const glm::dvec3 o(filtered[0].values[i], filtered[1].values[i], filtered[2].values[i]);
        lab[i] = perceived(glm::clamp(xyzToLinearRgb(ycxczToXyz(o)), 0.0, 1.0));
    }
    return lab;
}

// cmax: the largest distance between two colours of the sRGB cube, which the paper finds between
// green and blue, raised to qc like every distance.
double maxColorDistance() {
    static const double cmax =
        std::pow(hyab(perceived({0.0, 1.0, 0.0}), perceived({0.0, 0.0, 1.0})), kFlipQc);
    return cmax;
}

// The remapping of a distance d = HyAB^qc into [0, 1]: linear up to pc * cmax, where it reaches pt, and
// linear from there to 1 at cmax, so that the common small differences spread over most of the range.
double remapColorDistance(double d) {
    const double cmax = maxColorDistance(), knee = kFlipPc * cmax;
    if (d < knee) return kFlipPt / knee * d;
    return kFlipPt + (d - knee) / (cmax - knee) * (1.0 - kFlipPt);
}

}  // namespace

std::vector<double> flipColorError(const Image& test, const Image& reference, double pixelsPerDegree) {
    const std::vector<glm::dvec3> t = perceivedColors(test, pixelsPerDegree);
    const std::vector<glm::dvec3> r = perceivedColors(reference, pixelsPerDegree);
    std::vector<double> error(t.size());
    for (size_t i = 0; i < t.size(); ++i) error[i] = remapColorDistance(std::pow(hyab(t[i], r[i]), kFlipQc));
    return error;
}

}  // namespace fp
