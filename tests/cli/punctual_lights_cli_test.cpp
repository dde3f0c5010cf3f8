// Point, spot and directional lights from the command line: a scene file's "lights" reach the renderer
// (--stats, --json), a bad one is refused with exit status 1, the integrators that cannot see them
// warn, a resumed or merged render must have the same lights (the fingerprint), and the native reference
// refuses them rather than compare a different image.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/fragpath_runner.h"
#include "image/image.h"

namespace fp {
namespace {

using test::CliRun;
using test::runFragpath;

class PunctualLightsCli : public test::TempDirTest {
  protected:
    void SetUp() override {
        TempDirTest::SetUp();
        // A white floor (y = 0, facing up) and nothing else: only the lights light it.
        write("floor.mtl", "newmtl white\nKd 0.8 0.8 0.8\n");
        write("floor.obj",
              "mtllib floor.mtl\nusemtl white\nv -5 0 -5\nv -5 0 5\nv 5 0 5\nv 5 0 -5\nf 1 2 3\nf 1 3 4\n");
    }
    // A scene file of the floor with `lights` as its "lights" value.
    std::string scene(const std::string& name, const std::string& lights) {
        return write(name, R"({"mesh": "floor.obj",
            "camera": {"eye": [0, 4, -4], "target": [0, 0, 0], "fov": 50},
            "lights": )" + lights +
                               "}");
    }
};

const std::string kPoint = R"([{"type": "point", "position": [0, 2, 0], "intensity": 10}])";

TEST_F(PunctualLightsCli, SceneFileLightsReachTheRenderer) {
    std::string file = scene("point.json", kPoint);
    CliRun r = runFragpath("render " + file + " --size 16x16 --spp 2 --stats --json " + path("stats.json") +
                           " -o " + path("lit.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("punctual lights  1\n"), std::string::npos) << r.output;
    nlohmann::json j;
    std::ifstream(path("stats.json")) >> j;
    EXPECT_EQ(j["punctual_lights"], 1);
    EXPECT_EQ(j["emitters"], 0);
    Image lit = readImage(path("lit.exr"));
    double sum = 0.0;
    for (const glm::vec3& p : lit.pixels) sum += double(p.y);
    EXPECT_GT(sum / double(lit.pixels.size()), 0.05) << "the point light lights the floor";

    // Without lights the statistics say nothing of them, and the floor is black.
    CliRun dark = runFragpath("render " + scene("dark.json", "[]") + " --size 16x16 --spp 1 --stats -o " +
                              path("dark.png"));
    ASSERT_EQ(dark.exitCode, 0) << dark.output;
    EXPECT_EQ(dark.output.find("punctual lights"), std::string::npos) << dark.output;
}

TEST_F(PunctualLightsCli, NaiveAndBsdfWarnThatTheyCannotSeeThem) {
    std::string file = scene("point.json", kPoint);
    for (const char* integrator : {"naive", "bsdf"}) {
        CliRun r = runFragpath("render " + file + " --size 8x8 --spp 1 --quiet --integrator " + integrator +
                               " -o " + path("out.png"));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find(std::string("warning: the ") + integrator +
                                " integrator cannot see the scene's 1 point, spot or directional light"),
                  std::string::npos)
            << r.output;
    }
    for (const char* integrator : {"nee", "bdpt"}) {
        CliRun r = runFragpath("render " + file + " --size 8x8 --spp 1 --quiet --integrator " + integrator +
                               " -o " + path("out.png"));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
    }
}

TEST_F(PunctualLightsCli, ABadLightIsAnErrorNamingIt) {
    std::string file = scene("bad.json", R"([{"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0],
        "intensity": 10, "inner_cone": 40, "outer_cone": 30}])");
    CliRun r = runFragpath("render " + file + " --size 8x8 --spp 1 -o " + path("out.png"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("lights[0].inner_cone must be at least 0 and less than outer_cone"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(path("out.png")));
}

// The fingerprint covers the lights: a part rendered with another light is not the same render.
TEST_F(PunctualLightsCli, ResumeRefusesARenderWithOtherLights) {
    std::string a = scene("a.json", kPoint);
    std::string b = scene("b.json", R"([{"type": "point", "position": [0, 2, 0], "intensity": 11}])");
    CliRun first = runFragpath("render " + a + " --size 8x8 --spp 2 --quiet -o " + path("part.exr"));
    ASSERT_EQ(first.exitCode, 0) << first.output;
    CliRun same = runFragpath("render " + a + " --size 8x8 --spp 4 --quiet --resume " + path("part.exr") +
                              " -o " + path("more.exr"));
    EXPECT_EQ(same.exitCode, 0) << same.output;
    CliRun other = runFragpath("render " + b + " --size 8x8 --spp 4 --quiet --resume " + path("part.exr") +
                               " -o " + path("other.exr"));
    EXPECT_EQ(other.exitCode, 1) << other.output;
    EXPECT_NE(other.output.find("different scene or settings"), std::string::npos) << other.output;
}

TEST_F(PunctualLightsCli, TheNativeReferenceRefusesThem) {
    std::string file = scene("point.json", kPoint);
    CliRun bench = runFragpath("bench " + file + " --size 8x8 --spp 1 --runs 1 --native");
    EXPECT_EQ(bench.exitCode, 1) << bench.output;
    EXPECT_NE(bench.output.find("fragpath: error: --native: "), std::string::npos) << bench.output;
    EXPECT_NE(bench.output.find("point, spot or directional lights"), std::string::npos) << bench.output;
    // fragpath_native (the reference on its own) refuses the scene the same way, with exit status 1.
    const std::string native = std::filesystem::path(FP_BINARY).parent_path().string() + "/fragpath_native";
    CliRun r = test::runCommand(native + " " + file + " --size 8x8 --spp 1 -o " + path("native.png"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("point, spot or directional lights"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(path("native.png")));
}

}  // namespace
}  // namespace fp
