// render --stats and --json FILE: the statistics for people and for scripts, from one source
// (src/app/render_stats.h), so the two must agree.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/fragpath_runner.h"

namespace fp {
namespace {

class RenderStatsCli : public test::TempDirTest {
  protected:
    nlohmann::json readJson(const std::string& file) {
        std::ifstream in(path(file));
        return nlohmann::json::parse(in);  // throws (failing the test) unless it is valid JSON
    }
};

// The first match of `pattern`'s groups in `text`, or a failure.
std::smatch find(const std::string& text, const std::string& pattern) {
    std::smatch match;
    EXPECT_TRUE(std::regex_search(text, match, std::regex(pattern))) << pattern << " in\n" << text;
    return match;
}

TEST_F(RenderStatsCli, JsonIsConsistentAndMatchesThePrintedStats) {
    test::CliRun r = test::runFragpath(
        "render --size 20x10 --spp 3 --seed 5 --max-depth 3 --integrator bsdf --sampler independent --stats "
        "--json " +
        path("stats.json") + " -o " + path("out.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    nlohmann::json j = readJson("stats.json");

    // Consistent in itself.
    EXPECT_EQ(j["spp"], 3);
    EXPECT_EQ(j["paths"].get<uint64_t>(), 20u * 10u * 3u);
    EXPECT_GE(j["rays"].get<uint64_t>(), j["paths"].get<uint64_t>()) << "every path traces its camera ray";
    EXPECT_NEAR(j["rays_per_path"].get<double>(), j["rays"].get<double>() / j["paths"].get<double>(), 1e-9);
    EXPECT_EQ(j["dropped_samples"], 0);
    EXPECT_EQ(j["triangles"], 32);
    EXPECT_EQ(j["emitters"], 2);
    EXPECT_EQ(j["scene"], "built-in cornell.json");
    EXPECT_EQ(j["output"], path("out.png"));
    EXPECT_EQ(j["bvh"]["nodes"].get<int>(), 2 * j["bvh"]["leaves"].get<int>() - 1) << "a binary tree";
    EXPECT_GT(j["bvh"]["sah_cost"].get<double>(), 0.0);
    EXPECT_GE(j["bvh"]["build_seconds"].get<double>(), 0.0);
    EXPECT_GT(j["memory"]["gpu_bytes"].get<uint64_t>(), j["memory"]["gpu_geometry_bytes"].get<uint64_t>());
    EXPECT_GT(j["memory"]["image_bytes"].get<uint64_t>(), 0u);
    EXPECT_GT(j["seconds"].get<double>(), 0.0);
    EXPECT_GT(j["first_frame_seconds"].get<double>(), 0.0);
    // The first frame's stages follow one another inside it.
    double stages = 0.0;
    for (const char* key : {"load_seconds", "context_seconds", "bvh_seconds", "pack_and_upload_seconds",
                            "compile_seconds", "first_pass_seconds"}) {
        EXPECT_GE(j["first_frame"][key].get<double>(), 0.0) << key;
        stages += j["first_frame"][key].get<double>();
    }
    EXPECT_GT(j["first_frame"]["first_pass_seconds"].get<double>(), 0.0);
    EXPECT_LE(stages, j["first_frame_seconds"].get<double>() + 1e-9);
    EXPECT_GT(j["first_frame"]["cpu_seconds"].get<double>(), 0.0);
    EXPECT_NEAR(j["throughput"]["paths_per_second"].get<double>() * j["seconds"].get<double>(),
                j["paths"].get<double>(), 1e-6 * j["paths"].get<double>());
    EXPECT_NEAR(j["throughput"]["rays_per_second"].get<double>() * j["seconds"].get<double>(),
                j["rays"].get<double>(), 1e-6 * j["rays"].get<double>());
    const nlohmann::json& s = j["settings"];
    EXPECT_EQ(s["integrator"], "bsdf");
    EXPECT_EQ(s["sampler"], "independent");
    EXPECT_EQ(s["max_depth"], 3);
    EXPECT_EQ(s["width"], 20);
    EXPECT_EQ(s["height"], 10);
    EXPECT_EQ(s["seed"], 5);

    // The same figures as --stats prints.
    std::smatch m = find(r.output, R"(triangles +(\d+) \((\d+) emissive\))");
    EXPECT_EQ(std::stoi(m[1]), j["triangles"].get<int>());
    EXPECT_EQ(std::stoi(m[2]), j["emitters"].get<int>());
    m = find(r.output, R"(bvh +(\d+) nodes, (\d+) leaves, depth (\d+), .*SAH cost ([0-9.]+))");
    EXPECT_EQ(std::stoi(m[1]), j["bvh"]["nodes"].get<int>());
    EXPECT_EQ(std::stoi(m[2]), j["bvh"]["leaves"].get<int>());
    EXPECT_EQ(std::stoi(m[3]), j["bvh"]["depth"].get<int>());
    EXPECT_NEAR(std::stod(m[4]), j["bvh"]["sah_cost"].get<double>(), 0.005);
    m = find(r.output, R"(gpu memory +(\d+) bytes)");
    EXPECT_EQ(std::stoull(m[1]), j["memory"]["gpu_bytes"].get<uint64_t>());
    m = find(r.output, R"(samples +(\d+) per pixel in (\d+) passes, (\d+) paths, (\d+) rays)");
    EXPECT_EQ(std::stoi(m[1]), j["spp"].get<int>());
    EXPECT_EQ(std::stoi(m[2]), j["passes"].get<int>());
    EXPECT_EQ(std::stoull(m[3]), j["paths"].get<uint64_t>());
    EXPECT_EQ(std::stoull(m[4]), j["rays"].get<uint64_t>());
    // The default chooses the samples per pass: the first pass takes one, so 3 samples need 2 or 3.
    EXPECT_EQ(j["settings"]["samples_per_pass"], "auto");
    EXPECT_GE(j["passes"].get<int>(), 2);
    EXPECT_LE(j["passes"].get<int>(), 3);
    m = find(r.output, R"(dropped samples +(\d+))");
    EXPECT_EQ(std::stoull(m[1]), j["dropped_samples"].get<uint64_t>());
    m = find(r.output, R"(first frame +([0-9.]+) s)");
    EXPECT_NEAR(std::stod(m[1]), j["first_frame_seconds"].get<double>(), 0.0005);
}

// --json alone writes the file and prints no statistics; a file that cannot be written fails before
// the render.
TEST_F(RenderStatsCli, JsonWithoutStatsAndUnwritablePaths) {
    test::CliRun r = test::runFragpath("render --size 8x6 --spp 2 --quiet --json " + path("s.json") + " -o " +
                                       path("out.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("triangles"), std::string::npos) << r.output;
    EXPECT_EQ(readJson("s.json")["paths"], 8 * 6 * 2);

    r = test::runFragpath("render --size 8x6 --spp 2 --quiet --json " + path("missing/s.json") + " -o " +
                          path("late.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("--json " + path("missing/s.json") + ": directory"), std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(path("late.exr"))) << "refused before rendering";
}

}  // namespace
}  // namespace fp
