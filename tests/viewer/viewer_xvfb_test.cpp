// `fragpath view` end to end: a real GLFW window on a virtual X display (xvfb-run), as CI has no display
// and no GPU. The viewer drives the same renderer as `fragpath render`, and a pixel's k-th sample depends
// only on (seed, pixel, k), so the same settings must give the same image.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "cli/fragpath_runner.h"
#include "image/image.h"

namespace fp {
namespace {

namespace fs = std::filesystem;
using test::CliRun;

CliRun run(const std::string& command) {
    return test::runCommand(command);
}

// The viewer on its own virtual display (-a picks a free server number).
CliRun view(const std::string& args) {
    return run("LP_NUM_THREADS=2 xvfb-run -a -s \"-screen 0 1280x1024x24\" " + std::string(FP_BINARY) +
               " view " + args);
}

struct Rgb8Image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};

Rgb8Image readPng(const std::string& path) {
    Rgb8Image image;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
    if (!data) {
        ADD_FAILURE() << "cannot read " << path << ": " << stbi_failure_reason();
        return image;
    }
    image.rgb.assign(data, data + size_t(image.width) * size_t(image.height) * 3);
    stbi_image_free(data);
    return image;
}

class ViewerXvfb : public test::TempDirTest {
  protected:
    void SetUp() override {
        TempDirTest::SetUp();
        if (run("command -v xvfb-run").exitCode != 0)
            FAIL() << "xvfb-run is missing: install the xvfb and xauth packages (tools/install-deps.sh)";
    }
};

TEST_F(ViewerXvfb, RendersWhatFragpathRenderRenders) {
    CliRun a = view("--size 64x64 --spp 4 --frames 1 --seed 3 --max-depth 4 --screenshot " + path("A.png") +
                    " --no-ui");
    ASSERT_EQ(a.exitCode, 0) << a.output;
    EXPECT_NE(a.output.find("median frame time"), std::string::npos) << a.output;
    CliRun b =
        test::runFragpath("render --size 64x64 --spp 4 --seed 3 --max-depth 4 --quiet -o " + path("B.png"));
    ASSERT_EQ(b.exitCode, 0) << b.output;

    Rgb8Image imageA = readPng(path("A.png")), imageB = readPng(path("B.png"));
    ASSERT_EQ(imageA.width, 64);
    ASSERT_EQ(imageA.height, 64);
    ASSERT_EQ(imageB.rgb.size(), imageA.rgb.size());

    // Not blank: a lit Cornell box has a clearly non-zero mean and varies across the image.
    double sum = 0.0, sumSquares = 0.0;
    for (unsigned char v : imageA.rgb) sum += v, sumSquares += double(v) * v;
    double n = double(imageA.rgb.size()), mean = sum / n;
    EXPECT_GT(mean, 10.0);
    EXPECT_GT(sumSquares / n - mean * mean, 100.0);

    // The same samples through the same tone mapping: identical up to rounding (in practice, equal).
    int largest = 0;
    for (size_t i = 0; i < imageA.rgb.size(); ++i)
        largest = std::max(largest, std::abs(int(imageA.rgb[i]) - int(imageB.rgb[i])));
    EXPECT_LE(largest, 1);
}

// The lens flags reach the viewer's renderer (its home camera, with the panel's aperture and focus): the
// screenshot through a lens is fragpath render's through the same lens, bit for bit, and not the pinhole's.
TEST_F(ViewerXvfb, RendersThroughALensAsFragpathRenderDoes) {
    const std::string lens = " --aperture 60 --focus-distance 1000";
    CliRun a = view("--size 32x32 --spp 2 --frames 1 --seed 3 --no-ui --screenshot " + path("A.pfm") + lens);
    ASSERT_EQ(a.exitCode, 0) << a.output;
    auto render = [&](const std::string& flags) {
        CliRun b =
            test::runFragpath("render --size 32x32 --spp 2 --seed 3 --quiet -o " + path("B.pfm") + flags);
        EXPECT_EQ(b.exitCode, 0) << b.output;
        return readImage(path("B.pfm")).pixels;
    };
    std::vector<glm::vec3> viewed = readImage(path("A.pfm")).pixels;
    EXPECT_EQ(viewed, render(lens));
    EXPECT_NE(viewed, render(""));
}

// The viewer's denoised screenshot is fragpath render's denoised image: same samples, same passes.
TEST_F(ViewerXvfb, DenoisesWhatFragpathRenderDenoises) {
    CliRun a =
        view("--size 48x48 --spp 4 --frames 1 --denoise atrous --screenshot " + path("A.exr") + " --no-ui");
    ASSERT_EQ(a.exitCode, 0) << a.output;
    CliRun b = test::runFragpath("render --size 48x48 --spp 4 --quiet --denoise atrous -o " +
                                 path("raw.exr") + " --denoised-out " + path("B.exr"));
    ASSERT_EQ(b.exitCode, 0) << b.output;
    Image imageA = readImage(path("A.exr")), imageB = readImage(path("B.exr"));
    EXPECT_EQ(imageA.pixels, imageB.pixels);
    EXPECT_NE(imageA.pixels, readImage(path("raw.exr")).pixels);
}

// The samples per pixel that `wrote FILE (N spp)` reports for the --screenshot, or -1.
int screenshotSpp(const std::string& output, const std::string& file) {
    size_t at = output.find("wrote " + file + " (");
    if (at == std::string::npos) return -1;
    return std::atoi(output.c_str() + at + file.size() + 8);
}

// Issue 17: `view --frames N --screenshot` saved a half-traced first pass (a black band, "0 spp") when the
// frames ran out before a pass did (at 400x300 a pass takes several frames on llvmpipe). Whatever N, the
// screenshot must hold whole passes: at least one, every pixel the same number, which makes it the image
// `fragpath render` gives for that many samples.
TEST_F(ViewerXvfb, ScreenshotHoldsWholePassesWhenTheFramesEndMidPass) {
    for (int frames : {1, 2, 30}) {
        SCOPED_TRACE("--frames " + std::to_string(frames));
        std::string shot = path("view" + std::to_string(frames) + ".pfm");
        CliRun a = view("--size 400x300 --seed 5 --no-ui --frames " + std::to_string(frames) +
                        " --screenshot " + shot);
        ASSERT_EQ(a.exitCode, 0) << a.output;
        int spp = screenshotSpp(a.output, shot);
        if (spp < 1) {
            ADD_FAILURE() << "the screenshot has no whole pass\n" << a.output;
            continue;
        }
        EXPECT_NE(a.output.find(", " + std::to_string(spp) + " spp;"), std::string::npos) << a.output;

        Image image = readImage(shot);
        ASSERT_EQ(image.width, 400);
        ASSERT_EQ(image.height, 300);
        // No black band: the Cornell box is lit in every row, so every block of 30 rows has a clear mean.
        for (int block = 0; block < 10; ++block) {
            double sum = 0.0;
            for (int y = block * 30; y < (block + 1) * 30; ++y)
                for (int x = 0; x < image.width; ++x)
                    sum += double(glm::dot(image.at(x, y), glm::vec3(1.0f)));
            EXPECT_GT(sum / (30.0 * image.width), 0.01) << "rows " << block * 30 << " to " << block * 30 + 29;
        }
        // Whole passes: exactly what render takes with that many samples (a pass in progress would leave
        // some pixels with one sample more).
        CliRun b = test::runFragpath("render --size 400x300 --seed 5 --quiet --spp " + std::to_string(spp) +
                                     " -o " + path("render.pfm"));
        ASSERT_EQ(b.exitCode, 0) << b.output;
        Image rendered = readImage(path("render.pfm"));
        ASSERT_EQ(rendered.pixels.size(), image.pixels.size());
        size_t differing = 0;
        for (size_t i = 0; i < image.pixels.size(); ++i) differing += image.pixels[i] != rendered.pixels[i];
        EXPECT_EQ(differing, 0u) << "pixels unlike render --spp " << spp << "\n" << a.output;
    }
}

TEST_F(ViewerXvfb, PanelSplitViewAndCountViewsRun) {
    CliRun r = view("--size 160x120 --frames 4 --split bsdf --view bounces --screenshot " + path("view.png") +
                    " --screenshot-window " + path("window.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    Rgb8Image window = readPng(path("window.png"));
    EXPECT_EQ(window.width, 160);
    EXPECT_EQ(window.height, 120);
    Rgb8Image image = readPng(path("view.png"));
    EXPECT_EQ(image.width, 160);
}

// Issue 17: the panel covered about 40 % of an 800x600 window. Its default layout (essentials open, the
// rest collapsed, a narrower width) must leave most of the picture visible. The panel's rectangle is
// where the window capture differs from one without the panel (the same samples: --spp 1).
TEST_F(ViewerXvfb, PanelCoversLittleOfTheWindowByDefault) {
    const std::string args = "--size 800x600 --spp 1 --frames 3 --screenshot-window ";
    CliRun a = view(args + path("ui.png"));
    ASSERT_EQ(a.exitCode, 0) << a.output;
    CliRun b = view(args + path("no-ui.png") + " --no-ui");
    ASSERT_EQ(b.exitCode, 0) << b.output;
    Rgb8Image ui = readPng(path("ui.png")), bare = readPng(path("no-ui.png"));
    ASSERT_EQ(ui.width, 800);
    ASSERT_EQ(ui.height, 600);
    ASSERT_EQ(bare.rgb.size(), ui.rgb.size());

    int x0 = ui.width, y0 = ui.height, x1 = -1, y1 = -1;
    for (int y = 0; y < ui.height; ++y)
        for (int x = 0; x < ui.width; ++x) {
            size_t i = (size_t(y) * size_t(ui.width) + size_t(x)) * 3;
            if (std::equal(&ui.rgb[i], &ui.rgb[i] + 3, &bare.rgb[i])) continue;
            x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
        }
    ASSERT_GE(x1, 0) << "no panel in the capture";
    int width = x1 - x0 + 1, height = y1 - y0 + 1;
    double share = double(width) * double(height) / (800.0 * 600.0);
    EXPECT_LE(share, 0.30) << "panel at " << x0 << "," << y0 << ", " << width << "x" << height;
    // Still a panel one can read: its statistics and the main settings.
    EXPECT_GE(width, 200);
    EXPECT_GE(height, 200);
}

TEST_F(ViewerXvfb, WithoutADisplayNamesTheWaysOut) {
    CliRun r = run("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(FP_BINARY) + " view --frames 1");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("fragpath: error: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("xvfb-run"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("fragpath render"), std::string::npos) << r.output;
}

TEST_F(ViewerXvfb, BadFlagsFailBeforeOpeningAWindow) {
    CliRun r = run("env -u DISPLAY " + std::string(FP_BINARY) + " view --screenshot " + path("shot.txt"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("--screenshot"), std::string::npos) << r.output;
    r = run("env -u DISPLAY " + std::string(FP_BINARY) + " view --help");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    for (const char* text : {"--frames", "--screenshot", "--shader-dir", "orbit", "fly mode"})
        EXPECT_NE(r.output.find(text), std::string::npos) << text;
}

// The viewer reads its settings through the render request (request/render_request.h) like every front
// end: the scene file's max_depth 0 arrives in the renderer, and --max-depth overrides it. Each
// screenshot (linear) must equal `fragpath render` of the bare OBJ given that depth by flag.
TEST_F(ViewerXvfb, TakesTheSceneFilesDefaultsAndFlagsOverrideThem) {
    const std::string obj = std::string(FP_SOURCE_DIR) + "/assets/cornell/cornell.obj";
    const std::string scene =
        write("scene.json", R"({"mesh": ")" + obj + R"(", "render": {"max_depth": 0, "seed": 5}})");
    // The box's own camera (assets/cornell/cornell.json) by flags: the bare OBJ's default framing looks
    // from +z at the room's closed back.
    const std::string intoTheRoom = " --eye 278,273,-800 --target 278,273,0 --fov 39.3";
    auto screenshot = [&](const std::string& flags) {
        CliRun r = view(scene + intoTheRoom + " --size 32x32 --spp 2 --frames 1 --no-ui --screenshot " +
                        path("v.pfm") + " " + flags);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return readImage(path("v.pfm"));
    };
    auto render = [&](int depth) {
        CliRun r = test::runFragpath("render " + obj + intoTheRoom +
                                     " --size 32x32 --spp 2 --seed 5 --quiet --max-depth " +
                                     std::to_string(depth) + " -o " + path("r.pfm"));
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return readImage(path("r.pfm"));
    };
    Image fromFile = screenshot(""), flagged = screenshot("--max-depth 2");
    EXPECT_EQ(fromFile.pixels, render(0).pixels);
    EXPECT_EQ(flagged.pixels, render(2).pixels);
    EXPECT_NE(fromFile.pixels, flagged.pixels);
}

// Real-time mode (--realtime): a still camera's frames accumulate into the pipeline's history, so its
// image must approach a progressive render's, frame after frame (at the window's resolution: dynamic
// resolution, which would drop it on a loaded machine, is off). The tolerance is derived, not tuned:
// - noise: two independent 1-spp screenshots give the per-pixel sample variance s2 (half the mean squared
//   difference), so the image mean of k spp over P pixels has standard error sqrt(s2 / (k P)); the
//   real-time image holds at least one sample per pixel per frame (the filter only averages, which lowers
//   its variance), the reference 64: 4 standard errors of the difference;
// - the filter's bias (edge-stopping weights do not preserve the mean): measured 6 % of the mean on this
//   box at 10 frames of 1 spp, allowed 8 %, times the weight the output pass keeps on the filtered
//   image, min(1, maxHistorySamples / N) <= 32 / frames (TemporalSettings' default cap).
// Run at 10 and 100 frames: the longer run's pixels must also be closer to the reference's, by half
// (fails if the history never grows). Per pixel, not the image means: the means of both runs are within
// the reference's own noise of it, so which of the two is closer is chance (it failed so under load),
// while the pixels' noise falls as the history grows (RMSE 0.03-0.11 at 10 frames, 0.010 at 100).
TEST_F(ViewerXvfb, RealtimeModeConvergesToTheProgressiveImage) {
    auto luma = [](glm::vec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
    auto shot = [&](const std::string& flags) {
        CliRun r = view("--size 64x64 --max-depth 4 --no-ui --screenshot " + path("shot.pfm") + " " + flags);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return readImage(path("shot.pfm"));
    };
    Image ref = shot("--spp 64 --frames 1 --seed 7");
    Image a = shot("--spp 1 --frames 1 --seed 11"), b = shot("--spp 1 --frames 1 --seed 12");
    ASSERT_EQ(ref.width, 64);
    ASSERT_EQ(a.pixels.size(), ref.pixels.size());
    ASSERT_EQ(b.pixels.size(), ref.pixels.size());
    const double pixels = double(ref.pixels.size());
    double refMean = 0.0, s2 = 0.0;
    for (size_t i = 0; i < ref.pixels.size(); ++i) {
        refMean += luma(ref.pixels[i]) / pixels;
        double d = luma(a.pixels[i]) - luma(b.pixels[i]);
        s2 += 0.5 * d * d / pixels;
    }
    double previousError = 1e30;
    for (int frames : {10, 100}) {
        Image rt =
            shot("--realtime --fps 30 --dynamic-resolution off --seed 3 --frames " + std::to_string(frames));
        ASSERT_EQ(rt.pixels.size(), ref.pixels.size());
        double mean = 0.0, squaredError = 0.0;
        for (size_t i = 0; i < rt.pixels.size(); ++i) {
            ASSERT_TRUE(std::isfinite(luma(rt.pixels[i])));
            mean += luma(rt.pixels[i]) / pixels;
            double d = luma(rt.pixels[i]) - luma(ref.pixels[i]);
            squaredError += d * d / pixels;
        }
        double se = std::sqrt(s2 / (double(frames) * pixels) + s2 / (64.0 * pixels));
        double tolerance = 4.0 * se + 0.08 * std::min(1.0, 32.0 / frames) * refMean;
        double error = std::sqrt(squaredError);
        std::printf(
            "%d frames: real-time mean %.5f, progressive %.5f, tolerance %.5f (standard error %.5f); "
            "pixels' RMSE against it %.5f\n",
            frames, mean, refMean, tolerance, se, error);
        EXPECT_GT(mean, 0.05);  // not black
        EXPECT_NEAR(mean, refMean, tolerance) << frames << " frames";
        EXPECT_LT(error, 0.5 * previousError) << frames << " frames";
        previousError = error;
    }
}

// Real-time mode with its panel: it runs, and a generous budget (2 fps for a 160x120 box that traces a
// sample in milliseconds) raises the samples per frame above 1 within a few frames (realtime/frame_budget).
// The first frames pay for compiling the shaders (llvmpipe compiles at the first draw), which under a
// heavy load (load average 7) kept the samples at 1 through 4 frames: 8 leave room for that.
TEST_F(ViewerXvfb, RealtimeModeRunsWithThePanelAndFillsTheFrameBudget) {
    CliRun r = view("--size 160x120 --realtime --fps 2 --frames 8 --screenshot-window " + path("w.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    size_t at = r.output.find("real-time: ");
    ASSERT_NE(at, std::string::npos) << r.output;
    int spp = std::atoi(r.output.c_str() + at + 11);
    EXPECT_GT(spp, 1) << r.output;
    EXPECT_EQ(readPng(path("w.png")).width, 160);
}

// Dynamic resolution: a budget that one sample per pixel cannot meet (240 fps: 4.2 ms, while llvmpipe
// takes several ms to trace 160x120 and more to filter it) makes real-time mode render fewer pixels;
// switched off, the image keeps the window's size whatever the frame time.
TEST_F(ViewerXvfb, RealtimeModeDropsPixelsWhereOneSampleOverrunsTheBudget) {
    auto size = [&](const std::string& flags) {
        CliRun r = view("--size 160x120 --no-ui --realtime --fps 240 --frames 6 " + flags);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        size_t at = r.output.find("real-time: ");
        EXPECT_NE(at, std::string::npos) << r.output;
        at = r.output.find(" at ", at);
        EXPECT_NE(at, std::string::npos) << r.output;
        int w = 0, h = 0;
        if (at != std::string::npos) std::sscanf(r.output.c_str() + at, " at %dx%d", &w, &h);
        return glm::ivec2(w, h);
    };
    glm::ivec2 dynamic = size(""), fixed = size("--dynamic-resolution off");
    EXPECT_LT(dynamic.x, 160);
    EXPECT_LT(dynamic.y, 120);
    EXPECT_EQ(fixed, glm::ivec2(160, 120));
}

}  // namespace
}  // namespace fp
