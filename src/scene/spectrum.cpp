#include "scene/spectrum.h"

#include <cmath>

namespace fp::spectrum {

glm::vec3 normalisation() {
    // Midpoint rule with 1/100 nm steps: far below float precision for Gaussians this wide.
    const int steps = 34000;
    const double dx = double(kMaxNm - kMinNm) / steps;
    glm::dvec3 integral(0.0);
    for (int i = 0; i < steps; ++i) {
        double x = kMinNm + (i + 0.5) * dx;
        for (int c = 0; c < 3; ++c) {
            double t = (x - kCentreNm[c]) / kWidthNm[c];
            integral[c] += std::exp(-0.5 * t * t) * dx;
        }
    }
    return glm::vec3(1.0 / integral);
}

glm::vec2 cauchyFromAbbe(float indexD, float abbeNumber) {
    if (abbeNumber <= 0.0f) return {indexD, 0.0f};
    const double d = 587.6, f = 486.1, c = 656.3;
    double b = (indexD - 1.0) / (abbeNumber * (1.0 / (f * f) - 1.0 / (c * c)));
    return {float(indexD - b / (d * d)), float(b)};
}

}  // namespace fp::spectrum
