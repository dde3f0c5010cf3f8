// Renders split into sample ranges: parts rendered apart (on other machines, or resumed later) and
// merged give the image one render of all the samples gives, up to float summation order.
#include <gtest/gtest.h>

#include <fstream>

#include "cli/fragpath_runner.h"
#include "image/image.h"
#include "render/partial_render.h"

namespace fp {
namespace {

class PartialRenders : public test::TempDirTest {
  protected:
    void render(const std::string& options, const std::string& out) {
        test::CliRun r =
            test::runFragpath("render --size 24x16 --max-depth 3 --quiet " + options + " -o " + path(out));
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    void expectClose(const Image& a, const Image& b) {
        ASSERT_EQ(a.pixels.size(), b.pixels.size());
        for (size_t i = 0; i < a.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(a.pixels[i][c], b.pixels[i][c], 1e-5f * (1.0f + b.pixels[i][c])) << "pixel " << i;
    }

    void fourPartsMergedEqualOneRender(const std::string& options);
    void resumeEqualsOneRender(const std::string& options);
};

// bdpt's parts carry their light image inside the mean (light image / N, N = the part's samples), so
// the sample-weighted merge adds the light images and divides them by the total, as one render does.
TEST_F(PartialRenders, FourPartsMergedEqualOneRender) {
    fourPartsMergedEqualOneRender("");
}
TEST_F(PartialRenders, FourBdptPartsMergedEqualOneRender) {
    fourPartsMergedEqualOneRender("--integrator bdpt ");
}

// Through a thin lens: the lens points are a function of (seed, pixel, sample) like every other number,
// bdpt's light-tracing lens points included.
TEST_F(PartialRenders, FourPartsThroughALensMergedEqualOneRender) {
    fourPartsMergedEqualOneRender("--aperture 60 --focus-distance 1000 ");
}
TEST_F(PartialRenders, FourBdptPartsThroughALensMergedEqualOneRender) {
    fourPartsMergedEqualOneRender("--integrator bdpt --aperture 60 --focus-distance 1000 ");
}

// The lens is part of what a render is (its fingerprint): parts of other apertures or focus distances
// are refused. A pinhole's fingerprint is what it was before there were lenses (675824206562f27d is the
// fingerprint the commit before depth of field wrote for these settings of the built-in Cornell box), so
// that renders saved then still resume and merge; the focus distance of a pinhole changes nothing.
TEST_F(PartialRenders, TheLensIsPartOfTheFingerprint) {
    auto fingerprint = [&](const std::string& options) {
        std::string out = path("f.exr");
        test::CliRun r = test::runFragpath(
            "render --size 48x40 --spp 1 --integrator nee --sampler sobol --quiet " + options + " -o " + out);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return readPartial(out).fingerprint;
    };
    EXPECT_EQ(fingerprint(""), "675824206562f27d");
    EXPECT_EQ(fingerprint("--focus-distance 300"), "675824206562f27d");
    std::string lens = fingerprint("--aperture 20");
    EXPECT_NE(lens, "675824206562f27d");
    EXPECT_NE(fingerprint("--aperture 20 --focus-distance 300"), lens);
    EXPECT_NE(fingerprint("--aperture 30"), lens);
    // The default focus distance is the eye-target distance (800 for this camera): the same render.
    EXPECT_EQ(fingerprint("--aperture 20 --focus-distance 800"), lens);

    render("--spp 2 --aperture 20", "lens.exr");
    render("--spp 2 --sample-offset 2 --aperture 20 --focus-distance 300", "other_focus.exr");
    render("--spp 2 --sample-offset 2", "pinhole.exr");
    for (const char* other : {"other_focus.exr", "pinhole.exr"}) {
        test::CliRun r =
            test::runFragpath("merge " + path("lens.exr") + " " + path(other) + " -o " + path("m.exr"));
        EXPECT_EQ(r.exitCode, 1) << other;
        EXPECT_NE(r.output.find("different scene or settings"), std::string::npos) << r.output;
    }
}

void PartialRenders::fourPartsMergedEqualOneRender(const std::string& options) {
    render(options + "--spp 10", "whole.exr");
    render(options + "--spp 3", "a.exr");
    render(options + "--spp 2 --sample-offset 3", "b.exr");
    render(options + "--spp 4 --sample-offset 5", "c.exr");
    render(options + "--spp 1 --sample-offset 9", "d.exr");
    // In any order.
    test::CliRun r = test::runFragpath("merge " + path("c.exr") + " " + path("a.exr") + " " + path("d.exr") +
                                       " " + path("b.exr") + " -o " + path("merged.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    PartialRender merged = readPartial(path("merged.exr")), whole = readPartial(path("whole.exr"));
    EXPECT_EQ(merged.samples(), 10u);
    ASSERT_EQ(merged.ranges.size(), 1u) << "adjacent ranges join";
    EXPECT_EQ(merged.ranges[0].first, 0u);
    EXPECT_EQ(merged.fingerprint, whole.fingerprint);
    expectClose(merged.mean, whole.mean);
}

// merge writes the format its output's extension names (issue 17: -o merged.pfm got EXR bytes): a
// .pfm or .png gets the merged image, the .exr the same image with its sample ranges.
TEST_F(PartialRenders, MergeWritesTheFormatOfItsOutput) {
    render("--spp 2", "a.exr");
    render("--spp 2 --sample-offset 2", "b.exr");
    for (const char* out : {"merged.exr", "merged.pfm", "merged.png"}) {
        test::CliRun r =
            test::runFragpath("merge " + path("a.exr") + " " + path("b.exr") + " -o " + path(out));
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    std::ifstream pfm(path("merged.pfm"), std::ios::binary), png(path("merged.png"), std::ios::binary);
    char pfmMagic[2] = {}, pngMagic[4] = {};
    pfm.read(pfmMagic, 2);
    png.read(pngMagic, 4);
    EXPECT_EQ(std::string(pfmMagic, 2), "PF") << "a .pfm output is a PFM file";
    EXPECT_EQ(std::string(pngMagic + 1, 3), "PNG") << "a .png output is a PNG file";
    EXPECT_EQ(readImage(path("merged.pfm")).pixels, readPartial(path("merged.exr")).mean.pixels);
    EXPECT_EQ(readPartial(path("merged.exr")).samples(), 4u);
}

TEST_F(PartialRenders, OverlapsAndDifferentSettingsAreRefused) {
    render("--spp 3", "a.exr");
    render("--spp 3 --sample-offset 2", "overlapping.exr");
    render("--spp 3 --sample-offset 3 --seed 7", "other_seed.exr");
    test::CliRun r =
        test::runFragpath("merge " + path("a.exr") + " " + path("overlapping.exr") + " -o " + path("m.exr"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("overlap"), std::string::npos) << r.output;
    r = test::runFragpath("merge " + path("a.exr") + " " + path("other_seed.exr") + " -o " + path("m.exr"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("different scene or settings"), std::string::npos) << r.output;
    render("--spp 2 --view depth", "png_source.exr");
    r = test::runFragpath("merge " + path("a.exr") + " " + path("png_source.exr") + " -o " + path("m.exr"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_FALSE(std::filesystem::exists(path("m.exr")));
}

void PartialRenders::resumeEqualsOneRender(const std::string& options) {
    render(options + "--spp 8", "whole.exr");
    render(options + "--spp 3", "start.exr");
    render(options + "--spp 8 --resume " + path("start.exr"), "resumed.exr");
    PartialRender resumed = readPartial(path("resumed.exr"));
    EXPECT_EQ(resumed.samples(), 8u);
    expectClose(resumed.mean, readPartial(path("whole.exr")).mean);
}

// A resumed bdpt mean counts as that many light paths per pixel (Renderer::restore).
TEST_F(PartialRenders, BdptResumeEqualsOneRender) {
    resumeEqualsOneRender("--integrator bdpt ");
}

TEST_F(PartialRenders, ResumeContinuesWhereTheSavedRenderStopped) {
    resumeEqualsOneRender("");
    // A saved render of other settings cannot be continued.
    test::CliRun r = test::runFragpath("render --size 24x16 --max-depth 4 --spp 8 --resume " +
                                       path("start.exr") + " -o " + path("x.exr"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("different scene or settings"), std::string::npos) << r.output;
}

TEST_F(PartialRenders, TimeBudgetRendersWhatFitsAndRecordsTheCount) {
    render("--time-budget 1s", "budget.exr");
    PartialRender p = readPartial(path("budget.exr"));
    EXPECT_GE(p.samples(), 1u);
    EXPECT_LT(p.samples(), 1u << 24);
    test::CliRun r = test::runFragpath("render --time-budget soon -o " + path("x.exr"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("duration"), std::string::npos);
}

// A bdpt render stopped by its budget divides its light image by the samples it did, not those asked.
TEST_F(PartialRenders, BdptStoppedByItsBudgetEqualsARenderOfItsSamples) {
    render("--integrator bdpt --spp 1000000 --samples-per-pass 1 --time-budget 1s", "budget.exr");
    PartialRender p = readPartial(path("budget.exr"));
    ASSERT_GE(p.samples(), 1u);
    render("--integrator bdpt --samples-per-pass 1 --spp " + std::to_string(p.samples()), "same.exr");
    expectClose(p.mean, readPartial(path("same.exr")).mean);
}

}  // namespace
}  // namespace fp
