// The practice section (study/practice.h) and the seed's claim (study/seed_claim.h) on made-up inputs,
// with the expected values worked out by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "study/practice.h"
#include "study/report.h"
#include "study/roofline.h"
#include "study/seed_claim.h"

namespace fp::study {
namespace {

TEST(Practice, EqualTimeSppIsThePipelinesTimeOverASamplesRoundedDownAtLeastOne) {
    EXPECT_EQ(equalTimeSpp(7.9, 2.0), 3);  // 3.95 -> 3
    EXPECT_EQ(equalTimeSpp(6.0, 2.0), 3);  // exactly 3: not 2 by rounding
    EXPECT_EQ(equalTimeSpp(0.3, 0.1), 3);  // 0.3 / 0.1 = 2.9999999999999996 in doubles: still 3
    EXPECT_EQ(equalTimeSpp(1.5, 2.0), 1);  // 0.75 -> 0, but brute force traces at least 1
    EXPECT_THROW(equalTimeSpp(0.0, 2.0), Error);
    EXPECT_THROW(equalTimeSpp(4.0, -1.0), Error);
    EXPECT_THROW(equalTimeSpp(NAN, 1.0), Error);
}

TEST(Practice, SummaryTakesTheMedianTimeTheMeansAndTheSteadyFlipFromFrameTen) {
    // 12 frames: ms 1..12 (median (6 + 7) / 2 = 6.5); FLIP 0.5 on frames 0-9, 0.2 on 10 and 11 (mean
    // (10 x 0.5 + 2 x 0.2) / 12 = 5.4 / 12 = 0.45, steady (frames 10+) 0.2); history i + 1 frames (mean
    // 78 / 12 = 6.5); flicker 0.03 from frame 1 (mean 0.03; frame 0 has none).
    std::vector<PracticeFrame> frames;
    for (int i = 0; i < 12; ++i) {
        PracticeFrame f;
        f.ms = i + 1;
        f.flip = i < 10 ? 0.5 : 0.2;
        f.history = i + 1;
        if (i > 0) f.flicker = 0.03;
        frames.push_back(f);
    }
    PracticeRun r = summarisePractice("moving", PracticeMethod::Pipeline, 1, frames);
    EXPECT_EQ(r.frames, 12);
    EXPECT_DOUBLE_EQ(r.msPerFrame, 6.5);
    EXPECT_NEAR(r.meanFlip, 0.45, 1e-12);
    ASSERT_TRUE(r.steadyFlip.has_value());
    EXPECT_NEAR(*r.steadyFlip, 0.2, 1e-12);
    EXPECT_NEAR(r.judgedFlip(), 0.2, 1e-12);
    EXPECT_NEAR(r.flicker, 0.03, 1e-12);
    EXPECT_NEAR(r.meanHistory, 6.5, 1e-12);
    // Ten frames have no steady part: the judged FLIP is the mean, 0.5.
    frames.resize(10);
    PracticeRun shorter = summarisePractice("still", PracticeMethod::BruteForce, 1, frames);
    EXPECT_FALSE(shorter.steadyFlip.has_value());
    EXPECT_NEAR(shorter.judgedFlip(), 0.5, 1e-12);
    EXPECT_THROW(summarisePractice("still", PracticeMethod::Pipeline, 1, {}), Error);
    frames[3].flip = NAN;
    EXPECT_THROW(summarisePractice("still", PracticeMethod::Pipeline, 1, frames), Error);
}

PracticeRun run(const std::string& camera, PracticeMethod method, int spp, double flip,
                bool equalTime = false) {
    PracticeRun r;
    r.camera = camera;
    r.method = method;
    r.spp = spp;
    r.frames = 30;
    r.msPerFrame = 10.0 * spp;
    r.meanFlip = flip + 0.05;
    r.steadyFlip = flip;
    r.equalTime = equalTime;
    return r;
}

// A made-up measurement: the pipeline beats brute force at 1 spp on both cameras and at equal time (3
// spp) only on the still one; on the moving camera it misses the threshold 0.1 at 1 and 2 spp (0.15,
// 0.12) and gets under it at 4 (0.09).
PracticeInput madeUpPractice() {
    PracticeInput in;
    in.width = in.height = 64;
    in.frames = 30;
    in.referenceSpp = 256;
    in.settledSamples = 16.0;
    in.integrator = "nee";
    in.flipThreshold = 0.1;
    in.outDir = "practice";
    in.runs = {run("still", PracticeMethod::BruteForce, 1, 0.40),
               run("still", PracticeMethod::Pipeline, 1, 0.08),
               run("still", PracticeMethod::BruteForce, 3, 0.30, true),
               run("moving", PracticeMethod::BruteForce, 1, 0.30),
               run("moving", PracticeMethod::Pipeline, 1, 0.15),
               run("moving", PracticeMethod::BruteForce, 3, 0.14, true),
               run("moving", PracticeMethod::Pipeline, 2, 0.12),
               run("moving", PracticeMethod::Pipeline, 4, 0.09)};
    return in;
}

TEST(Practice, SectionTabulatesEveryRunAndSaysWhichWins) {
    PracticeInput in = madeUpPractice();
    EXPECT_EQ(practiceSppReachingThreshold(in), 4);
    std::string md = practiceMarkdown(in);
    EXPECT_NE(md.find("## Practice: temporal reuse and a filter against brute force"), std::string::npos);
    EXPECT_NE(md.find("a-trous filter that pixels whose history holds 16 samples skip"), std::string::npos);
    // The still pipeline row: 1 spp, 10 ms, mean 0.13, steady 0.08, flicker 0, history 0.
    EXPECT_NE(md.find("| still | reuse + a-trous | 1 | 10.0 | 0.1300 | 0.0800 | 0.0000 | 0.0 |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| moving | brute force, equal time | 3 | 30.0 | 0.1900 | 0.1400 |"), std::string::npos)
        << md;
    // Still: 0.08 against 0.40 is 0.20x; against 0.30, 0.27x. Moving: 0.15 / 0.30 = 0.50x (beats);
    // 0.15 / 0.14 = 1.07x (does not beat).
    EXPECT_NE(
        md.find("still camera, FLIP from frame 10: the pipeline beats brute force at 1 spp (0.080 against "
                "0.400 at 1 spp (0.20x)) and beats it at equal time (0.080 against 0.300 at 3 spp (0.27x))"),
        std::string::npos)
        << md;
    EXPECT_NE(
        md.find("moving camera, FLIP from frame 10: the pipeline beats brute force at 1 spp (0.150 against "
                "0.300 at 1 spp (0.50x)) and does not beat it at equal time (0.150 against 0.140 at 3 spp "
                "(1.07x))"),
        std::string::npos)
        << md;
    EXPECT_NE(md.find("gets under it at 4 spp per frame"), std::string::npos);
    in.runs.pop_back();  // without the 4-spp run nothing reaches 0.1
    EXPECT_FALSE(practiceSppReachingThreshold(in).has_value());
    EXPECT_NE(practiceMarkdown(in).find("does not get under it at up to 16 spp"), std::string::npos);
}

// A made-up study of nee in which every path visits 10 nodes and nothing else (1 ray, no triangle test,
// no surface), so the limits are simple:
// - bytes per path 10 x 64 = 640, so the memory limit is bandwidth / 640;
// - on GPUs with RT cores only the camera ray's 27 FLOPs and no INT32 stay on the SMs: the FP32 limit
//   is in the hundreds of giga paths/s, and the RT-core limit is giga rays / 1 ray (8 and more): memory
//   binds (RTX 2080: 448e9 / 640 = 0.7 giga paths/s);
// - before RT cores: FLOPs 10 x 106 + 9 + 27 = 1096, INT32 10 x 161 + 8 = 1618, unified lanes leave
//   1 / (1 + 1618/1096) = 0.404 of the peak: GTX 980 4.98e12 x 0.404 / 1096 = 1.8 giga paths/s against
//   memory 224e9 / 640 = 0.35: memory binds there too.
// 1080p60 needs 1920 x 1080 x 60 = 124 416 000 paths/s per spp:
// - 1 spp, 0.124e9: the GTX 980 (2014, 0.35e9) already;
// - 4 spp, 0.498e9: x80: GTX 980 0.35 no, GTX 1080 320e9 / 640 = 0.5 yes (2016); flagship: GTX 980 Ti
//   336.5e9 / 640 = 0.526 yes (2015); the earlier is the 980 Ti of 2015;
// - 16 spp, 1.99e9: x80: RTX 3080 760 / 640 = 1.19, 4080 716.8 / 640 = 1.12, 5080 960 / 640 = 1.5: none;
//   flagship: 3090 936 / 640 = 1.46, 4090 1008 / 640 = 1.575, RTX 5090 1792 / 640 = 2.8 (2025).
// The efficiency: the raw series' last level, 64 x 64 x 32 paths in 131.072 CPU-seconds, is 1000 paths
// per CPU-second, 1096 x 1000 FLOP/s against this made-up CPU's 2 GFLOPS per core (1 core, 1 GHz, one
// 32-bit lane, no FMA: 2 FLOPs a cycle): 5.48e-4. With FP32 at that efficiency the GPUs without RT cores
// allow about 1e6 paths/s (GTX 1080 Ti: 11.34e12 x 0.404 x 5.48e-4 / 1096 = 2.3e6), but with RT cores the
// SMs only shade the camera ray, 27 FLOPs and no INT32: RTX 2080 10.07e12 x 5.48e-4 / 27 = 0.204e9 and
// RTX 2080 Ti 13.45e12 x 5.48e-4 / 27 = 0.273e9 reach 1 spp's 0.124e9: both 2018.
ReportInput madeUpStudy() {
    ReportInput in;
    in.width = in.height = 64;
    in.integrators = {"nee"};
    in.denoisers = {"none", "bilateral"};
    in.counts["nee"] = PathCounts{10.0, 0.0, 0.0, 1.0};
    in.lightEntries = 2;
    in.cpu.cores = 1;
    in.cpu.ghz = 1.0;
    in.cpu.simdBits = 32;
    // relMSE = threshold x 16 / spp: exactly at the threshold at 16 spp; the made-up "bilateral" series
    // at 32 spp (3.98e9 paths/s, which no GPU of the table reaches), so (a) takes the raw series.
    for (const std::string denoiser : {"none", "bilateral"})
        for (int spp = 1; spp <= 32; spp *= 2) {
            StudyRow r;
            r.integrator = "nee";
            r.denoiser = denoiser;
            r.spp = spp;
            r.renderSeconds = r.renderCpuSeconds = 4.096 * spp;
            r.relMse = in.relMseThreshold * (denoiser == "none" ? 16.0 : 32.0) / spp;
            in.rows.push_back(r);
        }
    return in;
}

TEST(SeedClaim, AnswersBothCriteriaWithTheFirstGpuAndYear) {
    ReportInput in = madeUpStudy();
    std::optional<SeedAnswer> converged = convergedAnswer(in);
    ASSERT_TRUE(converged.has_value());
    EXPECT_DOUBLE_EQ(converged->spp, 16.0);
    EXPECT_FALSE(converged->x80.year.has_value());
    ASSERT_TRUE(converged->flagship.year.has_value());
    EXPECT_EQ(*converged->flagship.year, 2025);
    EXPECT_EQ(converged->gpu(), "RTX 5090");
    EXPECT_EQ(converged->binding, "memory");
    EXPECT_FALSE(converged->heldBy(2020));

    std::optional<SeedAnswer> one = practiceAnswer(in, "nee", 1.0);
    ASSERT_TRUE(one.has_value());
    EXPECT_EQ(one->year(), 2014);
    EXPECT_EQ(one->gpu(), "GTX 980");
    EXPECT_NEAR(one->efficiency, 5.48e-4, 1e-9);
    EXPECT_EQ(one->x80Measured.gpu, "RTX 2080");
    EXPECT_EQ(one->flagshipMeasured.gpu, "RTX 2080 Ti");
    std::optional<SeedAnswer> four = practiceAnswer(in, "nee", 4.0);
    ASSERT_TRUE(four.has_value());
    EXPECT_EQ(four->x80.gpu, "GTX 1080");
    EXPECT_EQ(four->year(), 2015);
    EXPECT_EQ(four->gpu(), "GTX 980 Ti");
    EXPECT_FALSE(practiceAnswer(in, "bdpt", 1.0).has_value());  // no path counts of bdpt

    in.practice = madeUpPractice();  // the pipeline gets under the threshold at 4 spp
    std::string md = seedClaimMarkdown(in);
    EXPECT_NE(md.find("## The seed's claim, in both senses"), std::string::npos);
    EXPECT_NE(md.find("The earliest: nee at 16 spp per frame, 1.99 giga paths per second. First x80 card: "
                      "none up to 2025"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("first flagship: RTX 5090 (2025)"), std::string::npos) << md;
    EXPECT_NE(md.find("By 2020: **no, not before the RTX 5090 of 2025**"), std::string::npos) << md;
    EXPECT_NE(
        md.find("At 1 spp per frame of nee, 0.124 giga paths per second. First x80 card: GTX 980 (2014)"),
        std::string::npos)
        << md;
    EXPECT_NE(
        md.find("With FP32 at the 0.05% efficiency measured here: RTX 2080 (2018) and RTX 2080 Ti (2018)"),
        std::string::npos)
        << md;
    EXPECT_NE(md.find("the pipeline's FLIP on the moving camera is 0.150, over the FLIP threshold 0.1"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("It gets under it at 4 spp per frame: 0.498 giga paths per second. First x80 card: GTX "
                      "1080 (2016); first flagship: GTX 980 Ti (2015)"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("So, under (a): **no**; under (b): **yes at 1 spp, yes at 4 spp**."), std::string::npos)
        << md;
    EXPECT_NE(md.find("Quake II RTX"), std::string::npos);
}

// A study of two scenes: the practice was measured on the first only, and the report gives it and the
// seed's claim once, after both scenes, with the first scene's numbers. The second scene's nee path
// visits 1000 nodes: 64 000 bytes, so 1 spp at 1080p60 needs 0.124e9 x 64 000 = 8e12 B/s, more than
// any GPU of the table moves (RTX 5090: 1.79e12): with its counts, (b) at 1 spp would find no GPU.
TEST(SeedClaim, ReportGivesPracticeAndTheClaimOnceForTheFirstScene) {
    ReportInput first = madeUpStudy();
    first.sceneName = "first";
    first.practice = madeUpPractice();
    first.practice->scene = "first";
    ReportInput second = madeUpStudy();
    second.sceneName = "second";
    second.counts["nee"] = PathCounts{1000.0, 0.0, 0.0, 1.0};
    std::string md = reportMarkdown({first, second});
    size_t secondScene = md.find("## Scene: second");
    ASSERT_NE(secondScene, std::string::npos);
    size_t practice = md.find("## Practice:");
    ASSERT_NE(practice, std::string::npos);
    EXPECT_GT(practice, secondScene);
    EXPECT_EQ(md.find("## Practice:", practice + 1), std::string::npos);
    EXPECT_NE(md.find("once per study, on `first` (the first scene studied)", practice), std::string::npos)
        << md.substr(practice);
    EXPECT_NE(md.find("- FLIP threshold: 0.1, the study's (`--flip-threshold`).", practice),
              std::string::npos);
    size_t claim = md.find("## The seed's claim, in both senses");
    ASSERT_NE(claim, std::string::npos);
    EXPECT_GT(claim, practice);
    EXPECT_EQ(md.find("## The seed's claim", claim + 1), std::string::npos);
    EXPECT_NE(md.find("for `first`, the first scene studied", claim), std::string::npos) << md.substr(claim);
    // The first scene's counts: the GTX 980 of 2014 at 1 spp (SeedClaim.AnswersBothCriteria...).
    EXPECT_NE(
        md.find("At 1 spp per frame of nee, 0.124 giga paths per second. First x80 card: GTX 980 (2014)",
                claim),
        std::string::npos)
        << md.substr(claim);
    EXPECT_NE(md.find("over the FLIP threshold 0.1.", claim), std::string::npos) << md.substr(claim);
}

}  // namespace
}  // namespace fp::study
