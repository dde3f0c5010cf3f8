// Every front end reads its settings through the one render request (request/render_request.h): a
// default from the scene file arrives in the renderer, and a flag overrides it. The scene file here
// sets max_depth 0 (only emitters seen directly), which the images and the counters can tell from a
// flag's depth 2 without any tolerance: each comparison is with the bare OBJ given the same depth by
// flag, rendered by `fragpath render`.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "cli/fragpath_runner.h"
#include "image/image.h"
#include "image/image_stats.h"

namespace fp {
namespace {

using test::CliRun;
using test::runFragpath;

const std::string kObj = std::string(FP_SOURCE_DIR) + "/assets/cornell/cornell.obj";
// The Cornell box's own camera (assets/cornell/cornell.json), looking into the room through its open -z
// side: the bare OBJ's default framing is from the front, +z, where the room shows its closed back.
const std::string kIntoTheRoom = " --eye 278,273,-800 --target 278,273,0 --fov 39.3 ";
double mean(const Image& image) {
    glm::dvec3 c = meanColor(image);
    return (c.x + c.y + c.z) / 3.0;
}

const std::string kNative = std::filesystem::path(FP_BINARY).parent_path().string() + "/fragpath_native";

class FrontEndRequest : public test::TempDirTest {
  protected:
    void SetUp() override {
        TempDirTest::SetUp();
        scene_ =
            write("scene.json", R"({"mesh": ")" + kObj +
                                    R"(", "render": {"width": 24, "height": 20, "spp": 2, "max_depth": 0}})");
    }
    // `fragpath render` of the bare OBJ with the depth given by flag: what the scene file should give.
    Image renderObj(int depth, const std::string& more = "") {
        std::string out = path("obj_" + std::to_string(depth) + ".pfm");
        CliRun r = runFragpath("render " + kObj + kIntoTheRoom + " --size 24x20 --spp 2 --max-depth " +
                               std::to_string(depth) + " --quiet " + more + " -o " + out);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return readImage(out);
    }
    Image renderScene(const std::string& flags) {
        std::string out = path("scene.pfm");
        CliRun r = runFragpath("render " + scene_ + kIntoTheRoom + " --quiet " + flags + " -o " + out);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return readImage(out);
    }
    std::string scene_;
};

TEST_F(FrontEndRequest, RenderTakesTheSceneFilesDefaultsAndFlagsOverrideThem) {
    Image fromFile = renderScene("");
    EXPECT_EQ(fromFile.width, 24);  // the file's size and spp too
    EXPECT_EQ(fromFile.pixels, renderObj(0).pixels);
    Image flagged = renderScene("--max-depth 2");
    EXPECT_EQ(flagged.pixels, renderObj(2).pixels);
    EXPECT_NE(flagged.pixels, fromFile.pixels);  // the depths do differ in these images
}

TEST_F(FrontEndRequest, NativeTakesTheSceneFilesDefaultsAndFlagsOverrideThem) {
    // The native reference is another renderer: compare its own two runs, by what depth 0 means (walls
    // unlit: the image's mean is the lamp's few pixels) against depth 2.
    auto native = [&](const std::string& flags) {
        std::string out = path("native.pfm");
        std::string command =
            kNative + " " + scene_ + kIntoTheRoom + flags + " -o " + out + " > /dev/null 2>&1";
        EXPECT_EQ(std::system(command.c_str()), 0) << command;
        return readImage(out);
    };
    Image fromFile = native(""), flagged = native("--max-depth 2");
    EXPECT_EQ(fromFile.width, 24);
    // Walls below the lamp: black when only emitters are seen, lit by one and two bounces at depth 2.
    const PixelRect wall{6, 6, 4, 8};
    EXPECT_EQ(meanColor(renderObj(0), wall), glm::dvec3(0.0));  // the rectangle is wall, not lamp
    EXPECT_GT(meanColor(renderObj(2), wall).x, 0.05);
    EXPECT_EQ(meanColor(fromFile, wall), glm::dvec3(0.0));
    EXPECT_GT(meanColor(flagged, wall).x, 0.05);
}

TEST_F(FrontEndRequest, BenchTakesTheSceneFilesDefaultsAndFlagsOverrideThem) {
    auto bench = [&](const std::string& flags) {
        std::string json = path("bench.json");
        CliRun r =
            runFragpath("bench " + scene_ + " --size 16x16 --spp 1 --runs 1 --json " + json + " " + flags);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return nlohmann::json::parse(std::ifstream(json));
    };
    nlohmann::json fromFile = bench(""), flagged = bench("--max-depth 2");
    EXPECT_EQ(fromFile["settings"]["max_depth"], 0);
    EXPECT_EQ(flagged["settings"]["max_depth"], 2);
    // What the renderer did: at depth 0 a path is its camera ray alone.
    EXPECT_EQ(fromFile["runs"][0]["rays_per_path"].get<double>(), 1.0);
    EXPECT_GT(flagged["runs"][0]["rays_per_path"].get<double>(), 1.5);
}

TEST_F(FrontEndRequest, StudyTakesTheSceneFilesDefaultsAndFlagsOverrideThem) {
    // The study renders its reference (seed S + 1, nee, 16 samples per pass) at the scene's depth.
    auto reference = [&](const std::string& flags) {
        std::string out = path("study");
        CliRun r =
            runFragpath("study " + scene_ + kIntoTheRoom +
                        "--size 24x20 --max-spp 1 --reference-spp 2 --integrators nee " +
                        "--denoisers none --count-spp 1 --no-plots --quiet --out " + out + " " + flags);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return readImage(out + "/reference_scene.exr");  // named after scene.json
    };
    auto close = [](const Image& a, const Image& b) {
        return a.width == b.width && a.height == b.height && rmse(a, b) <= 1e-6 * (1.0 + mean(b));
    };
    Image fromFile = reference(""), flagged = reference("--max-depth 2");
    EXPECT_TRUE(close(fromFile, renderObj(0, "--seed 1")));
    EXPECT_TRUE(close(flagged, renderObj(2, "--seed 1")));
    EXPECT_FALSE(close(fromFile, flagged));
}

// The thin lens of the scene file's camera arrives in the renderer and the flags override it, each
// value on its own: every render equals the bare OBJ rendered with that camera given by flags (the same
// lens points, so bit for bit), and the lens does change the image.
TEST_F(FrontEndRequest, TheLensComesFromTheSceneFileAndFlagsOverrideIt) {
    std::string lens = write("lens.json", R"({"mesh": ")" + kObj + R"(", "camera": {"eye": [278, 273, -800],
        "target": [278, 273, 0], "fov": 39.3, "aperture": 60, "focus_distance": 1000},
        "render": {"width": 24, "height": 20, "spp": 2}})");
    auto render = [&](const std::string& args) {
        std::string out = path("lens.pfm");
        CliRun r = runFragpath("render " + args + " --quiet -o " + out);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return readImage(out).pixels;
    };
    const std::string obj = kObj + " --size 24x20 --spp 2 --eye 278,273,-800 --target 278,273,0 --fov 39.3";
    auto fromFile = render(lens);
    EXPECT_EQ(fromFile, render(obj + " --aperture 60 --focus-distance 1000"));
    auto pinhole = render(obj);
    EXPECT_NE(fromFile, pinhole);
    EXPECT_EQ(render(lens + " --aperture 0"), pinhole);
    auto refocused = render(lens + " --focus-distance 700");
    EXPECT_EQ(refocused, render(obj + " --aperture 60 --focus-distance 700"));
    EXPECT_NE(refocused, fromFile);
    EXPECT_EQ(render(lens + " --aperture 30"), render(obj + " --aperture 30 --focus-distance 1000"));
}

// A bad lens is an input error (exit status 1) that says what is wrong, from a flag or the scene file.
TEST_F(FrontEndRequest, ABadLensIsRefusedWithAClearMessage) {
    CliRun r = runFragpath("render " + kObj + " --aperture -2 -o " + path("x.png"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("option --aperture: must be 0 (a pinhole) or more"), std::string::npos)
        << r.output;
    r = runFragpath("view " + kObj + " --focus-distance 0");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("option --focus-distance: must be above 0"), std::string::npos) << r.output;
    std::string bad = write(
        "bad.json", R"({"mesh": ")" + kObj +
                        R"(", "camera": {"eye": [0, 0, -5], "target": [0, 0, 0], "focus_distance": -1}})");
    r = runFragpath("render " + bad + " -o " + path("x.png"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("camera.focus_distance must be a finite number above 0"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("bad.json"), std::string::npos) << r.output;
}

TEST_F(FrontEndRequest, MergeTakesTheDisplayFlags) {
    // merge has no scene: its shared options are the display's, and they arrive in the PNG it writes.
    std::string part = path("part.exr");
    ASSERT_EQ(runFragpath("render --size 24x20 --spp 2 --quiet -o " + part).exitCode, 0);
    CliRun merged =
        runFragpath("merge " + part + " --exposure -2 --tonemap reinhard -o " + path("merged.png"));
    ASSERT_EQ(merged.exitCode, 0) << merged.output;
    CliRun direct = runFragpath("render --size 24x20 --spp 2 --quiet --exposure -2 --tonemap reinhard -o " +
                                path("direct.png"));
    ASSERT_EQ(direct.exitCode, 0) << direct.output;
    auto bytes = [&](const std::string& name) {
        std::ifstream in(path(name), std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_EQ(bytes("merged.png"), bytes("direct.png"));
    ASSERT_EQ(runFragpath("merge " + part + " -o " + path("plain.png")).exitCode, 0);
    EXPECT_NE(bytes("plain.png"), bytes("merged.png"));
}

}  // namespace
}  // namespace fp
