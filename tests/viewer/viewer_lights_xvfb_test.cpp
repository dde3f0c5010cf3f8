// `fragpath view` with point, spot and directional lights (under xvfb-run, as viewer_xvfb_test.cpp): the
// window renders what `fragpath render` renders from the same scene file, and its panel, which lists the
// lights in an open "lights" section, draws without trouble.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/fragpath_runner.h"

namespace fp {
namespace {

using test::CliRun;

CliRun view(const std::string& args) {
    return test::runCommand("LP_NUM_THREADS=2 xvfb-run -a -s \"-screen 0 1280x1024x24\" " +
                            std::string(FP_BINARY) + " view " + args);
}

std::vector<unsigned char> readRgb(const std::string& path, int& width, int& height) {
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &width, &height, &channels, 3);
    if (!data) {
        ADD_FAILURE() << "cannot read " << path;
        return {};
    }
    std::vector<unsigned char> rgb(data, data + size_t(width) * size_t(height) * 3);
    stbi_image_free(data);
    return rgb;
}

class ViewerLights : public test::TempDirTest {};

TEST_F(ViewerLights, RendersWhatFragpathRenderRendersAndListsTheLights) {
    write("floor.mtl", "newmtl white\nKd 0.8 0.8 0.8\n");
    write("floor.obj",
          "mtllib floor.mtl\nusemtl white\nv -5 0 -5\nv -5 0 5\nv 5 0 5\nv 5 0 -5\nf 1 2 3\nf 1 3 4\n");
    std::string scene = write("lights.json", R"({"mesh": "floor.obj",
        "camera": {"eye": [0, 4, -4], "target": [0, 0, 0], "fov": 50},
        "lights": [{"type": "spot", "name": "key", "position": [0, 2, 0], "direction": [0, -1, 0],
                    "intensity": 10, "inner_cone": 20, "outer_cone": 40},
                   {"type": "directional", "direction": [1, -1, 0], "irradiance": 0.5}]})");
    CliRun a = view(scene + " --size 48x48 --spp 2 --frames 1 --seed 3 --screenshot " + path("A.png") +
                    " --screenshot-window " + path("window.png"));
    ASSERT_EQ(a.exitCode, 0) << a.output;
    CliRun b =
        test::runFragpath("render " + scene + " --size 48x48 --spp 2 --seed 3 --quiet -o " + path("B.png"));
    ASSERT_EQ(b.exitCode, 0) << b.output;
    int wa = 0, ha = 0, wb = 0, hb = 0, ww = 0, hw = 0;
    std::vector<unsigned char> imageA = readRgb(path("A.png"), wa, ha),
                               imageB = readRgb(path("B.png"), wb, hb);
    ASSERT_EQ(imageA.size(), imageB.size());
    ASSERT_EQ(wa, 48);
    int largest = 0, lit = 0;
    for (size_t i = 0; i < imageA.size(); ++i) {
        largest = std::max(largest, std::abs(int(imageA[i]) - int(imageB[i])));
        lit += imageA[i] > 20;
    }
    EXPECT_LE(largest, 1) << "the same samples through the same tone map";
    EXPECT_GT(lit, int(imageA.size()) / 4) << "the lights light the floor";
    EXPECT_FALSE(readRgb(path("window.png"), ww, hw).empty());
    EXPECT_EQ(ww, 48);
}

}  // namespace
}  // namespace fp
