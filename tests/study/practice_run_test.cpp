// The study's practice measurement (study/practice_run.h) on real shaders through OSMesa, tiny: the
// runs exist, their figures are finite, and on a still camera reuse + filter beats 1-spp brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../render/render_test_util.h"
#include "study/practice_run.h"

namespace fp::test {
namespace {

const study::PracticeRun* find(const study::PracticeInput& in, const std::string& camera,
                               study::PracticeMethod method, bool equalTime, int spp) {
    for (const study::PracticeRun& r : in.runs)
        if (r.camera == camera && r.method == method && r.equalTime == equalTime && r.spp == spp) return &r;
    return nullptr;
}

TEST(PracticeRun, ReuseAndFilterBeatOneSppBruteForceOnAStillCamera) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    study::PracticeOptions o;
    o.settings.width = o.settings.height = 32;
    o.settings.maxDepth = 4;
    o.camera = *scene.camera;
    o.sceneKey = "built-in Cornell box (test)";
    o.frames = 4;
    o.referenceSpp = 64;
    o.flipThreshold = 0.0;  // never reached: the moving camera tries 2, 4, 8 and 16 spp too
    o.outDir = (std::filesystem::temp_directory_path() / "fp_practice_run_test").string();
    std::filesystem::remove_all(o.outDir);
    study::PracticeInput in = study::measurePractice(renderer, o);

    // Per camera brute force 1 spp, the pipeline at 1 spp, brute force at equal time; then the moving
    // pipeline at 2, 4, 8, 16: 3 + 3 + 4 = 10 runs.
    ASSERT_EQ(in.runs.size(), 10u);
    for (const study::PracticeRun& r : in.runs) {
        EXPECT_EQ(r.frames, 4);
        EXPECT_TRUE(std::isfinite(r.msPerFrame) && r.msPerFrame > 0.0) << r.camera << " " << r.spp;
        EXPECT_TRUE(std::isfinite(r.meanFlip) && r.meanFlip > 0.0 && r.meanFlip < 1.0) << r.camera;
        EXPECT_TRUE(std::isfinite(r.flicker) && r.flicker >= 0.0);
        EXPECT_FALSE(r.steadyFlip.has_value());  // 4 frames: none from frame 10
    }
    for (const char* camera : {"still", "moving"}) {
        const study::PracticeRun* one = find(in, camera, study::PracticeMethod::BruteForce, false, 1);
        const study::PracticeRun* pipeline = find(in, camera, study::PracticeMethod::Pipeline, false, 1);
        ASSERT_TRUE(one && pipeline) << camera;
        bool equalTimeFound = false;
        for (const study::PracticeRun& r : in.runs)
            equalTimeFound |= r.camera == camera && r.equalTime && r.spp >= 1;
        EXPECT_TRUE(equalTimeFound) << camera;
        EXPECT_NEAR(one->meanHistory, 1.0, 1e-6) << camera;  // no reuse: every frame alone
    }
    for (int spp : {2, 4, 8, 16})
        EXPECT_NE(find(in, "moving", study::PracticeMethod::Pipeline, false, spp), nullptr) << spp;
    // On a still camera the pipeline's history grows by one frame a frame, 1 + 2 + 3 + 4 over 4 frames:
    // 2.5 on average, and its FLIP is below brute force's at 1 spp. 32x32 pixels of 1-spp noise against
    // a 4-sample mean, then filtered: far apart, so a plain < is a safe margin.
    const study::PracticeRun* still = find(in, "still", study::PracticeMethod::Pipeline, false, 1);
    const study::PracticeRun* stillBrute = find(in, "still", study::PracticeMethod::BruteForce, false, 1);
    EXPECT_NEAR(still->meanHistory, 2.5, 1e-6);
    EXPECT_LT(still->meanFlip, 0.8 * stillBrute->meanFlip);
    // The still camera's references are shared: one file per frame, all from frame 0's render.
    EXPECT_TRUE(std::filesystem::exists(o.outDir + "/still/references/reference_0003.exr"));
    EXPECT_TRUE(std::filesystem::exists(o.outDir + "/moving/pipeline_16spp/frames.csv"));
    std::filesystem::remove_all(o.outDir);
}

}  // namespace
}  // namespace fp::test
