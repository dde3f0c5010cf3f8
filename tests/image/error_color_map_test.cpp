// The error maps' colour scale: lightness rising evenly with the error, inside the sRGB cube.
#include "image/error_color_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "image/color_space.h"

namespace fp {
namespace {

TEST(ErrorColorMap, LightnessRisesEvenlyInsideTheSrgbCube) {
    for (int i = 0; i <= 200; ++i) {
        const double e = i / 200.0;
        const glm::dvec3 rgb = errorColor(e);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(rgb[c], -1e-9) << e;
            EXPECT_LE(rgb[c], 1.0 + 1e-9) << e;
        }
        EXPECT_NEAR(xyzToLab(linearRgbToXyz(rgb)).x, 5.0 + 90.0 * e, 1e-6) << e;
    }
    // Grey at both ends; NaN and out-of-range values clamp.
    const glm::dvec3 zero = errorColor(0.0), one = errorColor(1.0);
    EXPECT_NEAR(zero.r, zero.b, 1e-9);
    EXPECT_NEAR(one.r, one.g, 1e-6);
    EXPECT_EQ(errorColor(std::nan("")), zero);
    EXPECT_EQ(errorColor(-1.0), zero);
    EXPECT_EQ(errorColor(2.0), one);
}

}  // namespace
}  // namespace fp
