// `fragpath compare` as a user runs it: the figure it prints for each metric, the default metric by
// file type, the heat map it writes, and its exit status for bad command lines (2) and bad files (1).
#include <cmath>
#include <cstdlib>
#include <string>

#include "fragpath_runner.h"
#include "image/error_color_map.h"
#include "image/flip.h"
#include "image/image.h"
#include "image/image_stats.h"

namespace fp::test {
namespace {

class CompareTest : public TempDirTest {
  protected:
    // A 16x16 gradient, and the same with a brighter square in the middle.
    std::string writeImages(const std::string& extension) {
        Image reference(16, 16), test(16, 16);
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                reference.at(x, y) = glm::vec3(x / 16.0f, y / 16.0f, 0.25f);
                test.at(x, y) =
                    reference.at(x, y) + glm::vec3(x >= 6 && x < 10 && y >= 6 && y < 10 ? 0.3f : 0.0f);
            }
        writeImage(path("reference" + extension), reference);
        writeImage(path("test" + extension), test);
        return path("test" + extension) + " " + path("reference" + extension);
    }
    // The number after the metric's name on the one line of output.
    static double figure(const CliRun& run, const std::string& metric) {
        EXPECT_EQ(run.output.rfind(metric + " ", 0), 0u) << run.output;
        EXPECT_EQ(run.output.find('\n'), run.output.size() - 1) << run.output;
        return std::atof(run.output.c_str() + metric.size() + 1);
    }
};

TEST_F(CompareTest, PrintsFlipForPngAndHdrFlipForLinearImagesByDefault) {
    const std::string png = writeImages(".png");
    CliRun run = runFragpath("compare " + png);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const double flip = figure(run, "flip");
    // The PNGs' codes decoded back to linear, through the library: the command adds nothing else.
    const double expected =
        ldrFlip(readImageOrPng(path("test.png")), readImageOrPng(path("reference.png"))).mean;
    EXPECT_NEAR(flip, expected, 1e-5 * expected + 1e-6);
    EXPECT_GT(flip, 0.0);

    const std::string exr = writeImages(".exr");
    run = runFragpath("compare " + exr);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const double hdr = figure(run, "hdr-flip");
    const double expectedHdr = hdrFlip(readImage(path("test.exr")), readImage(path("reference.exr"))).mean;
    EXPECT_NEAR(hdr, expectedHdr, 1e-5 * expectedHdr + 1e-6);

    run = runFragpath("compare " + path("reference.exr") + " " + path("reference.exr"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(run.output, "hdr-flip 0\n");
}

TEST_F(CompareTest, OtherMetricsAndViewingDistance) {
    const std::string pfm = writeImages(".pfm");
    CliRun run = runFragpath("compare " + pfm + " --metric rmse");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const double expected = rmse(readImage(path("test.pfm")), readImage(path("reference.pfm")));
    EXPECT_NEAR(figure(run, "rmse"), expected, 1e-5 * expected);
    for (const char* metric : {"relmse", "ssim"}) {
        run = runFragpath("compare " + pfm + " --metric " + metric);
        ASSERT_EQ(run.exitCode, 0) << run.output;
        EXPECT_GT(figure(run, metric), 0.0);
    }
    // --ppd reaches the metric: the figure is the library's at that viewing condition.
    const Image test = readImage(path("test.pfm")), reference = readImage(path("reference.pfm"));
    for (double ppd : {20.0, 200.0}) {
        run = runFragpath("compare " + pfm + " --metric flip --ppd " + std::to_string(ppd));
        ASSERT_EQ(run.exitCode, 0) << run.output;
        const double atPpd = ldrFlip(test, reference, ppd).mean;
        EXPECT_NEAR(figure(run, "flip"), atPpd, 1e-5 * atPpd) << ppd;
        EXPECT_GT(std::abs(atPpd - ldrFlip(test, reference).mean), 1e-3) << ppd;
    }
}

TEST_F(CompareTest, WritesTheHeatMap) {
    const std::string png = writeImages(".png");
    CliRun run = runFragpath("compare " + png + " --heatmap " + path("map.png"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Image map = readImageOrPng(path("map.png"));
    ASSERT_EQ(map.width, 16);
    ASSERT_EQ(map.height, 16);
    // The untouched corner has no error, the start of the scale; the brighter square is lighter.
    const float corner = map.at(0, 15).r + map.at(0, 15).g + map.at(0, 15).b;
    const float square = map.at(8, 8).r + map.at(8, 8).g + map.at(8, 8).b;
    EXPECT_NEAR(corner, 3.0 * errorColor(0.0).r, 0.003);
    EXPECT_GT(square, corner + 0.1f);
}

TEST_F(CompareTest, BadCommandLinesExitWithTwo) {
    const std::string png = writeImages(".png");
    for (const std::string& args :
         {std::string("compare"), "compare " + path("test.png"), "compare " + png + " " + png,
          "compare " + png + " --metric psnr", "compare " + png + " --ppd -3",
          "compare " + png + " --ppd far", "compare " + png + " --metric rmse --heatmap " + path("m.png"),
          "compare " + png + " --heatmap " + path("m.exr"), "compare " + png + " --bogus"}) {
        CliRun run = runFragpath(args);
        EXPECT_EQ(run.exitCode, 2) << args << "\n" << run.output;
        EXPECT_NE(run.output.find("error"), std::string::npos) << run.output;
    }
    CliRun help = runFragpath("compare --help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.output.find("--heatmap"), std::string::npos);
}

TEST_F(CompareTest, UnreadableFilesAndDifferentSizesExitWithOne) {
    writeImages(".png");
    writeImage(path("small.png"), Image(8, 8));
    write("broken.png", "not a png");
    for (const std::string& args :
         {"compare " + path("test.png") + " " + path("missing.png"),
          "compare " + path("broken.png") + " " + path("test.png"),
          "compare " + path("test.png") + " " + path("small.png"),
          "compare " + path("test.png") + " " + path("small.png") + " --metric rmse"}) {
        CliRun run = runFragpath(args);
        EXPECT_EQ(run.exitCode, 1) << args << "\n" << run.output;
        EXPECT_NE(run.output.find("error"), std::string::npos) << run.output;
    }
}

}  // namespace
}  // namespace fp::test
