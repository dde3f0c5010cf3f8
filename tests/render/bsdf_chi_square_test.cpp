// Chi-square goodness-of-fit tests of every BSDF sampling routine of glsl/common/bsdf.glsl, run in
// GLSL through OSMesa (issue 4), the way Mitsuba tests its BSDFs: the directions bsdfSample draws must
// be distributed as bsdfPdf says. A sampler and a density that disagree bias every estimator that uses
// both: MIS weights, and the light-sampling half of next-event estimation.
#include <gtest/gtest.h>

#include <cstdio>

#include "bsdf_test_util.h"

namespace fp::test {
namespace {

// Bonferroni: the family of all the chi-square tests below fails by chance with probability 1% at most.
double significance() {
    static const double level = 0.01 / double(samplingCases().size() * incidentAngles().size());
    return level;
}

// Runs the test of every (case, incident angle) of one model and prints its p-values.
void checkModel(MaterialType type) {
    BsdfProbe& probe = bsdfProbe();
    const std::vector<BsdfCase> cases = samplingCases();
    for (size_t c = 0; c < cases.size(); ++c) {
        if (cases[c].material.type != type) continue;
        probe.setMaterial(cases[c].material);
        for (size_t a = 0; a < incidentAngles().size(); ++a) {
            const glm::vec3 wo = incidentDirection(incidentAngles()[a]);
            const std::string what = describe(cases[c], incidentAngles()[a]);
            std::vector<ProbeSample> samples = probe.sample(wo, cases[c].eta, caseSeed(c, a), kSampleCount);
            ChiSquareResult r = chiSquareTest(probe, samples, wo, cases[c].eta);
            std::printf("  %-38s chi2 %8.2f  dof %3d  p %.4f  pdf mass %.5f  non-delta %.5f\n", what.c_str(),
                        r.statistic, r.dof, r.pValue, r.pdfIntegral, r.nonDeltaFraction);
            EXPECT_GT(r.pValue, significance())
                << what << ": chi2 " << r.statistic << " with " << r.dof << " dof";
            // The density's total mass is the probability of a successful non-delta sample; its binomial
            // noise, and an allowance for the quadrature (accurate to ~1e-5, see integratePdfOverBins).
            const double f = r.nonDeltaFraction;
            EXPECT_NEAR(r.pdfIntegral, f, 5.0 * std::sqrt(f * (1.0 - f) / kSampleCount) + 1e-4) << what;
        }
    }
}

TEST(BsdfChiSquare, Diffuse) {
    checkModel(MaterialType::Diffuse);
}
TEST(BsdfChiSquare, Conductor) {
    checkModel(MaterialType::Conductor);
}
TEST(BsdfChiSquare, Plastic) {
    checkModel(MaterialType::Plastic);
}
TEST(BsdfChiSquare, Dielectric) {
    checkModel(MaterialType::Dielectric);
}
TEST(BsdfChiSquare, MetallicRoughness) {
    checkModel(MaterialType::MetallicRoughness);
}

// The p-values come from our own incomplete gamma function: check it against closed forms. With k
// degrees of freedom, P(X >= x) is exp(-x/2) for k = 2, exp(-x/2) (1 + x/2) for k = 4, and
// erfc(sqrt(x/2)) for k = 1 (Abramowitz & Stegun, section 26.4). Both branches (series below a + 1,
// continued fraction above) are exercised.
TEST(BsdfChiSquareMath, PValuesMatchClosedForms) {
    for (double x : {0.01, 0.5, 1.0, 2.9, 3.1, 7.5, 20.0, 60.0}) {
        EXPECT_NEAR(chiSquarePValue(x, 2), std::exp(-0.5 * x), 1e-12) << x;
        EXPECT_NEAR(chiSquarePValue(x, 4), std::exp(-0.5 * x) * (1.0 + 0.5 * x), 1e-12) << x;
        EXPECT_NEAR(chiSquarePValue(x, 1), std::erfc(std::sqrt(0.5 * x)), 1e-12) << x;
    }
    // Large dof, as in the tests: the median of chi-square(k) is close to k (1 - 2 / (9k))^3 (Wilson &
    // Hilferty 1931), and the mean k is above the median.
    for (int k : {100, 400, 600}) {
        double median = k * std::pow(1.0 - 2.0 / (9.0 * k), 3.0);
        EXPECT_NEAR(chiSquarePValue(median, k), 0.5, 2e-3) << k;
        EXPECT_LT(chiSquarePValue(double(k), k), 0.5) << k;
    }
    EXPECT_EQ(chiSquarePValue(0.0, 10), 1.0);
}

// The pooling and the statistic on a histogram small enough to check by hand.
TEST(BsdfChiSquareMath, PearsonStatisticPoolsSparseCells) {
    // Expected 10, 10, 3, 1, 1 with observed 12, 8, 2, 2, 1: the three sparse cells (3 + 1 + 1 = 5 >= 5)
    // are pooled, leaving 3 cells: (12-10)^2/10 + (8-10)^2/10 + (5-5)^2/5 = 0.8 with 2 dof.
    std::vector<std::pair<double, double>> cells = {{10, 12}, {10, 8}, {3, 2}, {1, 2}, {1, 1}};
    PearsonResult r = pearsonChiSquare(cells);
    EXPECT_EQ(r.dof, 2);
    EXPECT_NEAR(r.statistic, 0.8, 1e-12);
}

}  // namespace
}  // namespace fp::test
