// The FLOP arithmetic of the feasibility report, the CPU peak formula and the spp-needed crossing.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "study/cpu_peak.h"
#include "study/feasibility.h"
#include "study/flop_model.h"
#include "study/spp_needed.h"

namespace fp::study {
namespace {

TEST(FlopModel, PathFlopsAddTheCountedOperations) {
    PathCounts c;
    c.nodesVisited = 10;
    c.trianglesTested = 4;
    c.rays = 3;
    c.surfacesShaded = 2;
    EXPECT_DOUBLE_EQ(flopsPerPath(c, Integrator::Nee), 10 * 106 + 4 * 52 + 3 * 9 + 27 + 2 * 298);
    EXPECT_DOUBLE_EQ(flopsPerPath(PathCounts{}, Integrator::Naive), kFlopsPerCameraRay);
    // Light sampling costs more per interaction than following the BSDF alone.
    EXPECT_GT(shadingFlops(Integrator::Nee), shadingFlops(Integrator::Bsdf));
    for (const FlopCount& f : operationTable()) EXPECT_GT(f.flops, 0.0) << f.operation;
}

TEST(Feasibility, RequiredRateIsPixelsTimesFpsTimesSppTimesFlops) {
    EXPECT_DOUBLE_EQ(requiredFlopsPerSecond(1.0, 1.0), 1920.0 * 1080.0 * 60.0);
    EXPECT_DOUBLE_EQ(requiredFlopsPerSecond(16.0, 1000.0), 1920.0 * 1080.0 * 60.0 * 16.0 * 1000.0);
    // 1e9 FLOP/s achieved on a 10 GFLOPS core is 10%.
    EXPECT_DOUBLE_EQ(measuredEfficiency(1000.0, 1e6, 10.0), 0.1);
}

TEST(Feasibility, FirstGpuAndTrendYear) {
    // 4 TFLOPS sustained at 50% needs 8 of peak: the GTX 1080 (8.9), not the GTX 980 (5.0).
    YearAnswer a = yearReached(4e12, 0.5);
    ASSERT_TRUE(a.firstGpuYear.has_value());
    EXPECT_EQ(*a.firstGpuYear, 2016);
    EXPECT_EQ(a.firstGpuName, "GTX 1080");
    // Beyond every GPU: none, and the trend puts it after 2025.
    YearAnswer b = yearReached(1e15, 0.1);
    EXPECT_FALSE(b.firstGpuYear.has_value());
    EXPECT_GT(b.extrapolatedYear, 2025.0);
    // Within one class: 8 TFLOPS at 100% among the flagships is the GTX 1080 Ti (11.3; the GTX 980 Ti
    // has 6.05), a year after the GTX 1080 of the x80 line.
    YearAnswer c = yearReached(8e12, 1.0, GpuClass::Flagship);
    ASSERT_TRUE(c.firstGpuYear.has_value());
    EXPECT_EQ(*c.firstGpuYear, 2017);
    EXPECT_EQ(c.firstGpuName, "GTX 1080 Ti");
    // One trend line per class (the mixed line is gone): each monotonic, doubling in a few years (x80:
    // 5.0 to 56 TFLOPS in 11 years, ~3.1; flagship: 6.05 to 105 in 10, ~2.4).
    for (GpuClass k : {GpuClass::X80, GpuClass::Flagship}) {
        EXPECT_LT(yearOfPeak(10.0, k), yearOfPeak(20.0, k));
        EXPECT_NEAR(yearOfPeak(20.0, k) - yearOfPeak(10.0, k), doublingYears(k), 1e-9);
        EXPECT_GT(doublingYears(k), 1.5);
        EXPECT_LT(doublingYears(k), 4.0);
    }
    EXPECT_GT(doublingYears(GpuClass::X80), doublingYears(GpuClass::Flagship));
}

TEST(Feasibility, Log2FitOfTwoPoints) {
    // (2016, 8) and (2020, 32): log2 goes 3 -> 5 in 4 years, slope 0.5, doubling every 2 years;
    // log2(64) = 6 is reached 2 years after 5: 2022; 16 halfway: 2018.
    Log2Fit fit = fitLog2({{2016.0, 8.0}, {2020.0, 32.0}});
    EXPECT_NEAR(fit.slope, 0.5, 1e-12);
    EXPECT_NEAR(fit.doublingYears(), 2.0, 1e-9);
    EXPECT_NEAR(fit.yearOf(64.0), 2022.0, 1e-9);
    EXPECT_NEAR(fit.yearOf(16.0), 2018.0, 1e-9);
    EXPECT_THROW(fitLog2({{2016.0, 8.0}}), Error);
    EXPECT_THROW(fitLog2({{2016.0, 8.0}, {2016.0, 16.0}}), Error);
    EXPECT_THROW(fitLog2({{2016.0, 8.0}, {2020.0, 0.0}}), Error);
}

TEST(CpuPeak, FollowsTheStatedFormula) {
    const std::string cpuinfo =
        "processor\t: 0\nmodel name\t: Test CPU\ncpu MHz\t\t: 2500.000\nphysical id\t: 0\ncpu cores\t: 2\n"
        "flags\t\t: fpu sse sse2 avx fma avx2 avx512f\n\n"
        "processor\t: 1\nmodel name\t: Test CPU\ncpu MHz\t\t: 2500.000\nphysical id\t: 0\ncpu cores\t: 2\n"
        "flags\t\t: fpu sse sse2 avx fma avx2 avx512f\n";
    CpuPeak p = parseCpuPeak(cpuinfo, 0.0, 256);
    EXPECT_EQ(p.cores, 2);
    EXPECT_EQ(p.simdBits, 256);  // AVX-512 in the flags, but llvmpipe compiles 256-bit vectors
    EXPECT_TRUE(p.fma);
    EXPECT_DOUBLE_EQ(p.gflops(), 2 * 2.5 * 8 * 2 * 2);
    EXPECT_EQ(parseCpuPeak(cpuinfo, 3000.0, 0).gflops(), 2 * 3.0 * 16 * 2 * 2);  // cpufreq maximum, 512 bits
    EXPECT_EQ(rendererVectorBits("llvmpipe (LLVM 15.0.6, 256 bits)"), 256);
    EXPECT_EQ(rendererVectorBits("NVIDIA GeForce"), 0);
    EXPECT_THROW(parseCpuPeak("nothing here\n", 0.0, 0), Error);
}

StudyRow row(const std::string& denoiser, int spp, double relMse) {
    StudyRow r;
    r.integrator = "nee";
    r.denoiser = denoiser;
    r.spp = spp;
    r.relMse = relMse;
    return r;
}

TEST(SppNeeded, InterpolatesExtrapolatesOrGivesUp) {
    // relMSE = 0.1 / spp: the threshold 0.01 is met at exactly 10 spp, between 8 and 16.
    std::vector<StudyRow> series;
    for (int n : {1, 2, 4, 8, 16}) series.push_back(row("none", n, 0.1 / n));
    SppNeeded a = sppNeeded(series, 0.01);
    EXPECT_EQ(a.kind, Crossing::Measured);
    EXPECT_NEAR(a.spp, 10.0, 1e-9);
    // Past the last level: 1/N from 16 spp.
    SppNeeded b = sppNeeded(series, 0.001);
    EXPECT_EQ(b.kind, Crossing::Extrapolated);
    EXPECT_NEAR(b.spp, 100.0, 1e-9);
    EXPECT_NE(describe(b).find("not reached by 16 spp"), std::string::npos);
    // Already under at 1 spp.
    EXPECT_EQ(sppNeeded(series, 1.0).spp, 1.0);
    // A denoised series is not extrapolated.
    for (StudyRow& r : series) r.denoiser = "atrous";
    EXPECT_EQ(sppNeeded(series, 0.001).kind, Crossing::NotReached);
    EXPECT_EQ(describe(sppNeeded(series, 0.001)), "not reached by 16 spp");
}

}  // namespace
}  // namespace fp::study
