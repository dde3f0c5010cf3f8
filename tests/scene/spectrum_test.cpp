// The numbers behind dispersion (src/scene/spectrum.h).
#include <gtest/gtest.h>

#include <cmath>

#include "scene/spectrum.h"

namespace fp {
namespace {

TEST(Spectrum, ChannelWeightsIntegrateToOne) {
    // Simpson's rule, independent of the midpoint rule the code uses.
    glm::vec3 norm = spectrum::normalisation();
    const int n = 2000;
    const double h = double(spectrum::kMaxNm - spectrum::kMinNm) / n;
    for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int i = 0; i <= n; ++i) {
            double x = spectrum::kMinNm + i * h;
            double t = (x - spectrum::kCentreNm[c]) / spectrum::kWidthNm[c];
            double w = norm[c] * std::exp(-0.5 * t * t);
            sum += w * (i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0);
        }
        EXPECT_NEAR(sum * h / 3.0, 1.0, 1e-6) << "channel " << c;
    }
}

TEST(Spectrum, CauchyFitReproducesTheIndexAndTheAbbeNumber) {
    for (float v : {20.0f, 36.4f, 64.17f}) {
        glm::vec2 ab = spectrum::cauchyFromAbbe(1.5168f, v);
        auto n = [&](double nm) { return ab.x + ab.y / (nm * nm); };
        EXPECT_NEAR(n(587.6), 1.5168, 1e-6);
        EXPECT_NEAR((n(587.6) - 1.0) / (n(486.1) - n(656.3)), v, 1e-3 * v);
        EXPECT_GT(n(400.0), n(700.0)) << "normal dispersion: blue bends more";
    }
    EXPECT_EQ(spectrum::cauchyFromAbbe(1.5f, 0.0f), glm::vec2(1.5f, 0.0f)) << "Vd 0: no dispersion";
}

}  // namespace
}  // namespace fp
