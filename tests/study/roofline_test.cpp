// The roofline: GPU figures, the FP32 share integer work leaves, bytes per path, which limit binds and
// the first GPU of a class that reaches a need; every expected value worked out in the comments.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "study/feasibility.h"
#include "study/gpus.h"
#include "study/roofline.h"
#include "study/roofline_report.h"

namespace fp::study {
namespace {

const Gpu& gpuNamed(const std::string& name) {
    for (const Gpu& g : gpuTable())
        if (name == g.name) return g;
    throw Error("no GPU " + name);
}

// 10 nodes, 40 triangle tests, 4 rays, 2 surfaces.
PathWork sampleWork(Integrator integrator) {
    PathWork w;
    w.counts.nodesVisited = 10;
    w.counts.trianglesTested = 40;
    w.counts.rays = 4;
    w.counts.surfacesShaded = 2;
    w.integrator = integrator;
    w.lightEntries = 2;
    return w;
}

TEST(Gpus, PeaksClassesAndRayRates) {
    // 2 FLOPs per lane per clock: RTX 2080 Ti 4352 x 2 x 1.545 GHz = 13.44768 TFLOPS.
    EXPECT_NEAR(gpuNamed("RTX 2080 Ti").peakTflops(), 13.44768, 1e-9);
    EXPECT_NEAR(gpuNamed("GTX 1080").peakTflops(), 2560 * 2 * 1.733e-3, 1e-9);
    // Six of each class, each by year.
    for (GpuClass c : {GpuClass::X80, GpuClass::Flagship}) {
        std::vector<Gpu> gpus = gpusOfClass(c);
        ASSERT_EQ(gpus.size(), 6u);
        for (size_t i = 1; i < gpus.size(); ++i) EXPECT_GT(gpus[i].year, gpus[i - 1].year);
    }
    // Turing: published. 34 RT TFLOPS x (68 x 1635 = 111180) / (48 x 1815 = 87120) = 34 x 1.276171 =
    // 43.3898 for the 2080 Ti, so 10 / 43.3898 = 0.230469 giga rays per RT TFLOPS; the RTX 3080's 58 RT
    // TFLOPS: 58 x 0.230469 = 13.367.
    EXPECT_EQ(gpuNamed("RTX 2080 Ti").raySource(), RaySource::Published);
    EXPECT_DOUBLE_EQ(gpuNamed("RTX 2080").gigaRays(), 8.0);
    EXPECT_NEAR(gigaRaysPerRtTflops(), 0.230469, 1e-6);
    EXPECT_EQ(gpuNamed("RTX 3080").raySource(), RaySource::Estimated);
    EXPECT_NEAR(gpuNamed("RTX 3080").gigaRays(), 13.367, 1e-3);
    EXPECT_EQ(gpuNamed("GTX 1080 Ti").raySource(), RaySource::None);
    EXPECT_FALSE(gpuNamed("GTX 1080 Ti").hasRayTracingCores());
}

TEST(Gpus, Fp32FractionLeftByIntegerWork) {
    // Unified lanes: r = 1 halves the FP32 rate.
    EXPECT_DOUBLE_EQ(fp32Fraction(LaneModel::Unified, 1.0), 0.5);
    // Separate INT32 lanes keep up to r = 1, then bind: r = 2 leaves half.
    EXPECT_DOUBLE_EQ(fp32Fraction(LaneModel::SeparateInt, 0.5), 1.0);
    EXPECT_DOUBLE_EQ(fp32Fraction(LaneModel::SeparateInt, 2.0), 0.5);
    // Half shared: r = 0.5 takes 1.5 lane pairs' worth, 1 / 1.5; r = 2 is bound by the one INT32-capable
    // lane of the pair, 2 r = 4 against 1 + r = 3: 1 / 4.
    EXPECT_NEAR(fp32Fraction(LaneModel::HalfShared, 0.5), 1.0 / 1.5, 1e-12);
    EXPECT_DOUBLE_EQ(fp32Fraction(LaneModel::HalfShared, 2.0), 0.25);
    EXPECT_DOUBLE_EQ(fp32Fraction(LaneModel::HalfShared, 0.0), 1.0);
}

TEST(Roofline, BytesAndIntegerWorkPerPath) {
    // bsdf: 10 x 64 + 40 x 48 + 2 x 160 = 640 + 1920 + 320 = 2880.
    PathWork bsdf = sampleWork(Integrator::Bsdf);
    EXPECT_DOUBLE_EQ(bytesPerPath(bsdf.counts, Integrator::Bsdf, 2), 2880.0);
    EXPECT_DOUBLE_EQ(traversalBytesPerPath(bsdf.counts), 2560.0);
    // The light sample: ceil(log2 L) search texels + entry, triangle, entry below, emission:
    // L = 2: 16 + 96 = 112; L = 5: 48 + 96 = 144; L = 1: no search, 96.
    EXPECT_DOUBLE_EQ(lightSampleBytes(2), 112.0);
    EXPECT_DOUBLE_EQ(lightSampleBytes(5), 144.0);
    EXPECT_DOUBLE_EQ(lightSampleBytes(1), 96.0);
    // nee: 2560 + 2 x (160 + 112) = 3104.
    EXPECT_DOUBLE_EQ(bytesPerPath(bsdf.counts, Integrator::Nee, 2), 3104.0);
    // Integer work per surface: 13 + pairs x 127 (+ nee's search 5 x 1 and 4 addresses):
    // bsdf 13 + 254 = 267, nee 13 + 508 + 9 = 530.
    EXPECT_DOUBLE_EQ(intPerSurface(Integrator::Bsdf, 2), 267.0);
    EXPECT_DOUBLE_EQ(intPerSurface(Integrator::Nee, 2), 530.0);
    // bsdf path: 10 x 161 + 40 x 15 + 4 x 8 + 2 x 267 = 1610 + 600 + 32 + 534 = 2776.
    EXPECT_DOUBLE_EQ(intPerPath(bsdf.counts, Integrator::Bsdf, 2), 2776.0);
    // Shading FLOPs: 27 + 2 x 163 = 353.
    EXPECT_DOUBLE_EQ(shadingFlopsPerPath(bsdf.counts, Integrator::Bsdf), 353.0);
}

TEST(Roofline, WhichLimitBinds) {
    PathWork w = sampleWork(Integrator::Bsdf);
    // RTX 2080 Ti (RT cores): memory 616e9 / 2880 = 213.89e6 paths/s; rays 10e9 / 4 = 2.5e9; FP32 on
    // the surfaces only: r = 534 / 353 = 1.513 > 1, separate INT32 lanes bind, fraction 353 / 534,
    // so 13.44768e12 x (353 / 534) / 353 = 13.44768e12 / 534 = 25.18e9. Memory binds.
    RooflineLimits ti = rooflineLimits(gpuNamed("RTX 2080 Ti"), w);
    EXPECT_NEAR(ti.memory, 616e9 / 2880, 1.0);
    EXPECT_NEAR(ti.rays, 2.5e9, 1.0);
    EXPECT_NEAR(ti.fp32Fraction, 353.0 / 534.0, 1e-12);
    EXPECT_NEAR(ti.compute, 13.44768e12 / 534, 1e3);
    EXPECT_EQ(ti.binding(), Limit::Memory);
    // 213.89e6 / (1920 x 1080 x 60 = 124.416e6) = 1.719 spp at 1080p60.
    EXPECT_NEAR(ti.bindingPathsPerSecond() / requiredPathsPerSecond(1.0), 616e9 / 2880 / 124.416e6, 1e-9);
    // GTX 1080 (no RT cores): all of the path's FLOPs, 10 x 106 + 40 x 52 + 4 x 9 + 27 + 2 x 163 = 3529,
    // and integers, 2776; unified lanes leave 3529 / (3529 + 2776) = 3529 / 6305; at 1% efficiency
    // 8.87296e12 x 0.01 / 6305 = 14.07e6 paths/s, below memory's 320e9 / 2880 = 111.1e6: FP32 binds.
    RooflineLimits gtx = rooflineLimits(gpuNamed("GTX 1080"), w, 0.01);
    EXPECT_NEAR(gtx.fp32Fraction, 3529.0 / 6305.0, 1e-12);
    EXPECT_NEAR(gtx.compute, 8.87296e12 * 0.01 / 6305, 1.0);
    EXPECT_EQ(gtx.rays, kUnlimited);
    EXPECT_EQ(gtx.binding(), Limit::Compute);
    // Rays bind where a path is all rays and reads nothing: 100 rays, 10e9 / 100 = 1e8 paths/s against
    // 13.44768e12 / 27 for the camera ray's FLOPs.
    PathWork raysOnly;
    raysOnly.counts.rays = 100;
    raysOnly.integrator = Integrator::Bsdf;
    RooflineLimits r = rooflineLimits(gpuNamed("RTX 2080 Ti"), raysOnly);
    EXPECT_EQ(r.memory, kUnlimited);
    EXPECT_NEAR(r.rays, 1e8, 1e-3);
    EXPECT_EQ(r.binding(), Limit::Rays);
}

TEST(Roofline, FirstGpuOfEachClass) {
    // bsdf at 1 spp: 124.416e6 paths/s. Memory binds on every GPU here (FP32 and rays allow 10x more
    // or better: see WhichLimitBinds), so the need is bandwidth >= 124.416e6 x 2880 = 358.3 GB/s:
    // x80: GTX 980 224, GTX 1080 320, RTX 2080 448 -> 2018; flagship: GTX 980 Ti 336.5, GTX 1080 Ti
    // 484 -> 2017.
    PathWork w = sampleWork(Integrator::Bsdf);
    double need = requiredPathsPerSecond(1.0);
    ClassAnswer x80 = firstReaching(GpuClass::X80, need, w);
    ASSERT_TRUE(x80.year.has_value());
    EXPECT_EQ(*x80.year, 2018);
    EXPECT_EQ(x80.gpu, "RTX 2080");
    ClassAnswer flagship = firstReaching(GpuClass::Flagship, need, w);
    ASSERT_TRUE(flagship.year.has_value());
    EXPECT_EQ(*flagship.year, 2017);
    // The trend is the fit of bandwidth / 2880 by year within the class: doubling the need moves it by
    // the fit's doubling time.
    std::vector<std::pair<double, double>> points;
    for (const Gpu& g : gpusOfClass(GpuClass::X80))
        points.push_back({double(g.year), g.bandwidthGBs * 1e9 / 2880});
    Log2Fit fit = fitLog2(points);
    EXPECT_NEAR(x80.trendYear, fit.yearOf(need), 1e-9);
    EXPECT_NEAR(firstReaching(GpuClass::X80, 2 * need, w).trendYear - x80.trendYear, fit.doublingYears(),
                1e-9);
    // Beyond every GPU: none, and the trend is after 2025.
    ClassAnswer none = firstReaching(GpuClass::X80, 100 * need, w);
    EXPECT_FALSE(none.year.has_value());
    EXPECT_GT(none.trendYear, 2025.0);
}

TEST(Roofline, ReportSectionNamesTheFirstGpus) {
    // nee without a denoiser, relMSE = 0.1 / spp: the threshold 0.05 is met at 2 spp, 248.832e6
    // paths/s. nee reads 3104 bytes a path (BytesAndIntegerWorkPerPath) and memory binds, so it needs
    // 772.4 GB/s: x80 RTX 3080 760 and RTX 4080 716.8 fall short, RTX 5080 960 reaches it (2025);
    // flagship RTX 2080 Ti 616 short, RTX 3090 936 reaches it (2020).
    ReportInput in;
    in.integrators = {"nee"};
    in.denoisers = {"none"};
    in.counts["nee"] = sampleWork(Integrator::Nee).counts;
    in.lightEntries = 2;
    in.relMseThreshold = 0.05;
    in.width = in.height = 8;
    in.plots = false;
    in.cpu.cores = 1;
    in.cpu.ghz = 1.0;
    in.cpu.simdBits = 32;
    for (int n : {1, 2, 4}) {
        StudyRow r;
        r.integrator = "nee";
        r.denoiser = "none";
        r.spp = n;
        r.relMse = 0.1 / n;
        r.renderCpuSeconds = 1.0;
        in.rows.push_back(r);
    }
    std::string md = rooflineMarkdown(in);
    ASSERT_NE(md.find("## Roofline"), std::string::npos);
    size_t row = md.find("| nee | none | 2 |");
    ASSERT_NE(row, std::string::npos) << md;
    std::string line = md.substr(row, md.find('\n', row) - row);
    EXPECT_NE(line.find("| 2025 (RTX 5080) | 2020 (RTX 3090) |"), std::string::npos) << line;
}

}  // namespace
}  // namespace fp::study
