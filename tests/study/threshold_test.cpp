// The crossings of the perceptual thresholds (SSIM and FLIP beside relMSE), their sensitivity band, the
// answer by metric with its year band, and the scene column of study.csv. Every expected value is worked
// out by hand in the comments from series built as exact power laws.
#include <gtest/gtest.h>

#include <cmath>

#include "study/metric_answer.h"
#include "study/spp_needed.h"
#include "study/study_csv.h"

namespace fp::study {
namespace {

std::vector<StudyRow> seriesOf(const std::string& integrator, const std::string& denoiser,
                               double (*value)(int spp), double StudyRow::*field) {
    std::vector<StudyRow> series;
    for (int n : {1, 2, 4, 8, 16}) {
        StudyRow r;
        r.scene = "test";
        r.integrator = integrator;
        r.denoiser = denoiser;
        r.spp = n;
        r.*field = value(n);
        series.push_back(r);
    }
    return series;
}

TEST(Thresholds, ScalingMovesTheDistanceFromPerfect) {
    // relMSE and FLIP: perfect is 0, so the threshold itself is halved or doubled.
    EXPECT_DOUBLE_EQ(scaledThreshold(relMseMetric(), 4e-4, 2.0), 8e-4);
    EXPECT_DOUBLE_EQ(scaledThreshold(flipMetric(), 0.05, 0.5), 0.025);
    // SSIM: perfect is 1, so 1 - SSIM = 0.02 becomes 0.04 (SSIM 0.96) or 0.01 (SSIM 0.99).
    EXPECT_NEAR(scaledThreshold(ssimMetric(), 0.98, 2.0), 0.96, 1e-12);
    EXPECT_NEAR(scaledThreshold(ssimMetric(), 0.98, 0.5), 0.99, 1e-12);
}

TEST(Thresholds, FlipCrossingInterpolatesAndIsNeverExtrapolated) {
    // FLIP = 0.32 / sqrt(spp): 0.32, 0.226, 0.16, 0.113, 0.08 at 1 ... 16 spp. A power law is a line in
    // log-log, so the interpolation is exact: FLIP <= 0.1 at spp = (0.32 / 0.1)^2 = 10.24 (between 8 and
    // 16); at double the threshold, 0.2: (0.32 / 0.2)^2 = 2.56 (between 2 and 4); at half, 0.05, it
    // would need (0.32 / 0.05)^2 = 41, past 16, and FLIP follows no known rate: not reached, even raw.
    auto series = seriesOf(
        "nee", "none", [](int n) { return 0.32 / std::sqrt(double(n)); }, &StudyRow::flip);
    SppBand band = sppBand(series, flipMetric(), 0.1);
    EXPECT_EQ(band.atThreshold.kind, Crossing::Measured);
    EXPECT_NEAR(band.atThreshold.spp, 10.24, 1e-9);
    EXPECT_EQ(band.lenient.kind, Crossing::Measured);
    EXPECT_NEAR(band.lenient.spp, 2.56, 1e-9);
    EXPECT_EQ(band.strict.kind, Crossing::NotReached);
    EXPECT_EQ(describe(band), "10.2 [2.56, >16]");
}

TEST(Thresholds, SsimCrossingRisesToTheThreshold) {
    // SSIM = 1 - 0.16 / spp: 0.84, 0.92, 0.96, 0.98, 0.99. SSIM >= 0.975 means 1 - SSIM <= 0.025:
    // spp = 0.16 / 0.025 = 6.4 (between 4 and 8). Double the dissimilarity, 0.05 (SSIM 0.95): 3.2; half,
    // 0.0125 (SSIM 0.9875): 12.8 (between 8 and 16).
    auto series = seriesOf(
        "nee", "atrous", [](int n) { return 1.0 - 0.16 / n; }, &StudyRow::ssim);
    SppBand band = sppBand(series, ssimMetric(), 0.975);
    EXPECT_NEAR(band.atThreshold.spp, 6.4, 1e-9);
    EXPECT_NEAR(band.lenient.spp, 3.2, 1e-9);
    EXPECT_NEAR(band.strict.spp, 12.8, 1e-9);
    EXPECT_EQ(describe(band), "6.4 [3.2, 12.8]");
    // At 0.98 exactly the level of 8 spp meets it: no interpolation needed.
    EXPECT_DOUBLE_EQ(sppNeeded(series, ssimMetric(), 0.98).spp, 8.0);
    // SSIM 0.995 (1 - SSIM = 0.005) would need 32: not reached, and SSIM is never extrapolated.
    for (StudyRow& r : series) r.denoiser = "none";
    EXPECT_EQ(sppNeeded(series, ssimMetric(), 0.995).kind, Crossing::NotReached);
}

TEST(Thresholds, RelMseBandExtrapolatesARawSeries) {
    // relMSE = 0.04 / spp: <= 0.01 at 4 spp exactly; 0.02 at 2; 0.005 at 8. At 0.001 the raw series is
    // extrapolated from 16 spp (relMSE 0.0025) by 1/N: 16 x 0.0025 / 0.001 = 40.
    auto series = seriesOf(
        "bdpt", "none", [](int n) { return 0.04 / n; }, &StudyRow::relMse);
    SppBand band = sppBand(series, relMseMetric(), 0.01);
    EXPECT_DOUBLE_EQ(band.atThreshold.spp, 4.0);
    EXPECT_DOUBLE_EQ(band.lenient.spp, 2.0);
    EXPECT_DOUBLE_EQ(band.strict.spp, 8.0);
    SppNeeded far = sppNeeded(series, relMseMetric(), 0.001);
    EXPECT_EQ(far.kind, Crossing::Extrapolated);
    EXPECT_NEAR(far.spp, 40.0, 1e-9);
    EXPECT_EQ(describeShort(far), "~40");
}

TEST(Thresholds, CheapestAnswerCarriesTheBandToTheYear) {
    // Two raw combinations at 10% efficiency. 1080p60 is 1920 x 1080 x 60 = 124,416,000 paths per second
    // per spp. nee: relMSE = 0.1 / spp reaches 0.01 at 10 spp, x 1000 FLOPs = 12.4 TFLOPS of peak;
    // bdpt: relMSE = 0.04 / spp reaches it at 4 spp, x 2000 FLOPs = 9.95 TFLOPS: bdpt is cheaper. Its
    // peak at 4 spp, 9.95 TFLOPS, is first reached, over both classes of gpus.h, by the flagship GTX
    // 1080 Ti (3584 x 2 x 1582 MHz = 11.3; the GTX 1080 has 8.9, the GTX 980 Ti 6.1): 2017. At double
    // the threshold, 2 spp: 4.977 TFLOPS, the GTX 980 (2048 x 2 x 1216 MHz = 4.981): 2014. At half,
    // 8 spp: 19.9 TFLOPS, the RTX 3080 (29.8; the RTX 2080 Ti has 13.4): 2020.
    std::vector<StudyRow> rows = seriesOf(
        "nee", "none", [](int n) { return 0.1 / n; }, &StudyRow::relMse);
    std::vector<StudyRow> bdpt = seriesOf(
        "bdpt", "none", [](int n) { return 0.04 / n; }, &StudyRow::relMse);
    rows.insert(rows.end(), bdpt.begin(), bdpt.end());
    FeasibilityRow nee;
    nee.integrator = "nee";
    nee.denoiser = "none";
    nee.flopsPerPath = 1000.0;
    nee.efficiency = 0.1;
    FeasibilityRow b = nee;
    b.integrator = "bdpt";
    b.flopsPerPath = 2000.0;
    MetricAnswer a = cheapestAnswer({nee, b}, rows, relMseMetric(), 0.01, false);
    EXPECT_EQ(a.integrator, "bdpt");
    EXPECT_DOUBLE_EQ(a.band.atThreshold.spp, 4.0);
    ASSERT_TRUE(a.year && a.year->firstGpuYear && a.lenientYear && a.strictYear);
    EXPECT_EQ(*a.year->firstGpuYear, 2017);
    EXPECT_EQ(*a.lenientYear->firstGpuYear, 2014);
    EXPECT_EQ(*a.strictYear->firstGpuYear, 2020);
    EXPECT_EQ(yearBandText(a), "2017 [2014, 2020]");
    // No denoised combination at all: no answer.
    EXPECT_TRUE(cheapestAnswer({nee, b}, rows, relMseMetric(), 0.01, true).integrator.empty());
    // FLIP was never measured here (all 0 = perfect): every combination meets it at 1 spp, so nee, whose
    // single spp costs 1000 FLOPs against bdpt's 2000, is the cheaper.
    EXPECT_EQ(cheapestAnswer({nee, b}, rows, flipMetric(), 0.05, false).integrator, "nee");
}

TEST(Thresholds, CsvStartsWithTheScene) {
    StudyRow r;
    r.scene = "cornell-spheres";
    r.integrator = "nee";
    r.denoiser = "none";
    r.spp = 4;
    std::string text = csvText({r});
    EXPECT_EQ(text.rfind("scene,integrator,denoiser,spp,", 0), 0u) << text;
    EXPECT_NE(text.find("\ncornell-spheres,nee,none,4,"), std::string::npos) << text;
}

}  // namespace
}  // namespace fp::study
