// `fragpath bench`: the figures it reports exist, are sane and are machine-readable. Speed itself is
// never asserted: it depends on the machine and whatever else runs on it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli/fragpath_runner.h"

namespace fp {
namespace {

namespace fs = std::filesystem;
using test::CliRun;

CliRun fragpath(const std::string& args) { return test::runFragpath(args); }

class Bench : public test::TempDirTest {};

void expectPositive(const nlohmann::json& j, const std::string& key) {
    ASSERT_TRUE(j.contains(key)) << key << " missing in " << j.dump();
    ASSERT_TRUE(j[key].is_number()) << key << " is not a number in " << j.dump();
    double v = j[key].get<double>();
    EXPECT_TRUE(std::isfinite(v) && v > 0.0) << key << " = " << v;
}

TEST_F(Bench, WritesEveryFigureAsJson) {
    std::string file = path("bench.json");
    CliRun r = fragpath("bench --size 16x16 --spp 1 --runs 3 --json " + file);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* text :
         {"llvmpipe", "LP_NUM_THREADS   2", "median", "min", "max", "paths/s", "rays/s", "bench: "})
        EXPECT_NE(r.output.find(text), std::string::npos) << text << " in " << r.output;
    EXPECT_EQ(r.output.find("warning"), std::string::npos) << "LP_NUM_THREADS is set: " << r.output;

    std::ifstream in(file);
    nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_NE(j["renderer"].get<std::string>().find("llvmpipe"), std::string::npos);
    EXPECT_EQ(j["lp_num_threads"], "2");
    EXPECT_TRUE(j.contains("mesa_shader_cache_disable"));
    EXPECT_EQ(j["scene"]["triangles"], 32);
    EXPECT_EQ(j["settings"]["width"], 16);
    EXPECT_EQ(j["settings"]["spp"], 1);
    EXPECT_EQ(j["settings"]["integrator"], "nee");
    expectPositive(j["bvh"], "build_seconds");
    expectPositive(j["bvh"], "sah_cost");
    for (const char* key :
         {"seconds", "context_seconds", "bvh_and_upload_seconds", "compile_seconds", "first_pass_seconds"})
        expectPositive(j["first_frame"], key);

    const char* perRun[] = {"wall_seconds",         "cpu_seconds",     "cpu_per_wall", "paths_per_second",
                            "paths_per_cpu_second", "rays_per_second", "rays_per_path"};
    ASSERT_EQ(j["runs"].size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        const nlohmann::json& run = j["runs"][i];
        EXPECT_EQ(run["seed"], i + 1) << "each timed run has its own seed; the warm-up has 0";
        EXPECT_EQ(run["paths"], 16 * 16);
        for (const char* key : perRun) expectPositive(run, key);
        EXPECT_GE(run["rays_per_path"].get<double>(), 1.0) << "at least the camera ray";
    }
    for (const char* key : perRun) {
        const nlohmann::json& s = j["summary"][key];
        for (const char* stat : {"median", "min", "max"}) expectPositive(s, stat);
        EXPECT_LE(s["min"].get<double>(), s["median"].get<double>()) << key;
        EXPECT_LE(s["median"].get<double>(), s["max"].get<double>()) << key;
    }
}

TEST_F(Bench, WarnsWhenTheThreadCountIsLeftToLlvmpipe) {
    CliRun r = test::runFragpath("bench --size 8x8 --spp 1 --runs 1", "env -u LP_NUM_THREADS");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string& output = r.output;
    EXPECT_NE(output.find("warning: LP_NUM_THREADS is unset"), std::string::npos) << output;
    EXPECT_NE(output.find("LP_NUM_THREADS   unset"), std::string::npos) << output;
}

TEST_F(Bench, HelpListsTheOptions) {
    CliRun r = fragpath("bench --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* flag : {"--size", "--spp", "--runs", "--max-depth", "--integrator", "--json"})
        EXPECT_NE(r.output.find(flag), std::string::npos) << flag;
}

TEST_F(Bench, BadFlagsAreErrors) {
    struct Case {
        const char* args;
        const char* fragment;
    };
    for (const Case& c :
         {Case{"--bogus", "unknown option --bogus"}, Case{"--runs", "needs a value"},
          Case{"--runs 0", "--runs"}, Case{"--spp 0", "--spp"}, Case{"--spp many", "--spp"},
          Case{"--size 16", "WIDTHxHEIGHT"}, Case{"--max-depth -1", "--max-depth"},
          Case{"--integrator magic", "naive, bsdf or nee"}, Case{"a.obj b.obj", "one scene file"},
          Case{"--json /no/such/dir/b.json", "does not exist"}}) {
        CliRun r = fragpath(std::string("bench ") + c.args);
        EXPECT_EQ(r.exitCode, 1) << c.args << ": " << r.output;
        EXPECT_NE(r.output.find("fragpath: error: "), std::string::npos) << c.args << ": " << r.output;
        EXPECT_NE(r.output.find(c.fragment), std::string::npos) << c.args << ": " << r.output;
    }
    CliRun r = fragpath("bench " + path("missing.obj") + " --spp 1 --runs 1");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("missing.obj"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace fp
