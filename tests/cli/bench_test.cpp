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

CliRun fragpath(const std::string& args) {
    return test::runFragpath(args);
}

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
    EXPECT_EQ(j["settings"]["samples_per_pass"], 8);
    expectPositive(j["bvh"], "build_seconds");
    expectPositive(j["bvh"], "sah_cost");
    for (const char* key : {"seconds", "context_seconds", "bvh_seconds", "pack_and_upload_seconds",
                            "compile_seconds", "first_pass_seconds"})
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

TEST_F(Bench, NativeReferenceGivesTheRatioInTheSameRun) {
    std::string file = path("native.json");
    CliRun r = fragpath("bench --size 16x16 --spp 1 --runs 3 --native --json " + file);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("gpu / native"), std::string::npos) << r.output;
    std::ifstream in(file);
    nlohmann::json j = nlohmann::json::parse(in);
    const nlohmann::json& native = j["native"];
    ASSERT_EQ(native["runs"].size(), 3u);
    for (const nlohmann::json& run : native["runs"]) {
        EXPECT_EQ(run["paths"], 16 * 16);
        expectPositive(run, "paths_per_cpu_second");
        EXPECT_GE(run["rays"].get<double>(), 16 * 16) << "at least the camera rays";
    }
    expectPositive(native["paths_per_cpu_second"], "median");
    double expected = j["summary"]["paths_per_cpu_second"]["median"].get<double>() /
                      native["paths_per_cpu_second"]["median"].get<double>();
    EXPECT_NEAR(native["gpu_over_native"].get<double>(), expected, 1e-9 * expected);
}

TEST_F(Bench, NativeReferenceRefusesWhatItDoesNotImplement) {
    // A ratio of the shader over the reference means something only for the same algorithm: another
    // integrator or a material the reference lacks is an error, never a skip note beside GPU figures
    // that could pass for a comparison. The suite's scenes are Lambertian; a metal OBJ is not.
    std::string obj = path("metal.obj"), mtl = path("metal.mtl"), file = path("refused.json");
    std::ofstream(mtl) << "newmtl m\nKd 0.5 0.5 0.5\nPm 1\n";
    std::ofstream(obj) << "mtllib metal.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    struct Case {
        std::string args, fragment;
    };
    for (const Case& c : {Case{obj, "not Lambertian"}, Case{"--integrator bdpt", "only the nee integrator"},
                          Case{"--integrator bsdf", "only the nee integrator"},
                          Case{"--suite --scenes cornell --integrator naive", "only the nee integrator"}}) {
        CliRun r = fragpath("bench " + c.args + " --size 8x8 --spp 1 --runs 1 --native --json " + file);
        EXPECT_EQ(r.exitCode, 1) << c.args << ": " << r.output;
        EXPECT_NE(r.output.find("fragpath: error: --native: "), std::string::npos)
            << c.args << ": " << r.output;
        EXPECT_NE(r.output.find(c.fragment), std::string::npos) << c.args << ": " << r.output;
        EXPECT_EQ(r.output.find("gpu / native"), std::string::npos) << c.args << ": " << r.output;
        EXPECT_FALSE(fs::exists(file)) << c.args << ": wrote figures";
    }
    // Without --native the same scene and integrators are measured as usual.
    EXPECT_EQ(fragpath("bench " + obj + " --size 8x8 --spp 1 --runs 1").exitCode, 0);
}

TEST_F(Bench, SuiteGivesEachScenesShareOfTheCornellBoxForBothRenderers) {
    std::string file = path("shares.json");
    CliRun r = fragpath(
        "bench --suite --native --scenes cornell,sphere-1k --size 8x8 --spp 1 --runs 1 --json " + file);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(file);
    nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_EQ(j["scenes"].size(), 2u);
    auto native = [&](int scene) {
        return j["scenes"][scene]["native"]["paths_per_cpu_second"]["median"].get<double>();
    };
    EXPECT_DOUBLE_EQ(j["scenes"][1]["native"]["share_of_cornell"].get<double>(), native(1) / native(0));
    char text[64];
    std::snprintf(text, sizeof text, ", native reference %.1f %%", 100.0 * native(1) / native(0));
    EXPECT_NE(r.output.find(text), std::string::npos) << text << " in " << r.output;
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
    for (const char* flag : {"--size", "--spp", "--runs", "--max-depth", "--integrator", "--json", "--suite",
                             "--max-triangles", "--scenes", "--with-bunny", "--native",
                             "256x256 with --suite", "--study caustic", "--budget", "--reference-spp"})
        EXPECT_NE(r.output.find(flag), std::string::npos) << flag;
}

// The figures every suite scene must have, each positive and finite.
void expectSceneFigures(const nlohmann::json& scene) {
    for (const char* key : {"build_seconds", "sah_cost", "nodes", "depth"}) expectPositive(scene["bvh"], key);
    for (const char* key : {"bytes", "geometry_bytes", "bytes_per_triangle", "geometry_bytes_per_triangle"})
        expectPositive(scene["gpu"], key);
    // Read in place (tests/render/pinned_upload_test.cpp): a part of the whole.
    EXPECT_LE(scene["gpu"]["pinned_bytes"].get<double>(), scene["gpu"]["bytes"].get<double>())
        << scene["gpu"];
    for (const char* key : {"seconds", "load_seconds", "bvh_seconds", "pack_and_upload_seconds",
                            "compile_seconds", "first_pass_seconds"})
        expectPositive(scene["first_frame"], key);
    const char* perRun[] = {"wall_seconds",        "cpu_seconds",          "cpu_per_wall",
                            "paths_per_second",    "paths_per_cpu_second", "rays_per_second",
                            "rays_per_cpu_second", "rays_per_path"};
    ASSERT_EQ(scene["runs"].size(), 1u);
    for (const char* key : perRun) {
        expectPositive(scene["runs"][0], key);
        for (const char* stat : {"median", "min", "max"}) expectPositive(scene["summary"][key], stat);
    }
    const nlohmann::json& others = scene["other_processes_cpu_share"];
    EXPECT_TRUE(others.is_null() || (others.is_number() && others.get<double>() >= 0.0)) << others;
}

TEST_F(Bench, SuiteWritesOneJsonObjectPerScene) {
    std::string file = path("suite.json");
    CliRun r = fragpath("bench --suite --size 8x8 --spp 1 --runs 1 --max-triangles 2000 --json " + file);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* text : {"== cornell ==", "== sphere-1k ==", "skipping sphere-100k", "suite: 8x8"})
        EXPECT_NE(r.output.find(text), std::string::npos) << text << " in " << r.output;

    std::ifstream in(file);
    nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_NE(j["renderer"].get<std::string>().find("llvmpipe"), std::string::npos);
    EXPECT_EQ(j["lp_num_threads"], "2");
    EXPECT_EQ(j["settings"]["width"], 8);
    EXPECT_EQ(j["settings"]["runs"], 1);
    expectPositive(j, "context_seconds");
    // Only the scenes of at most 2000 triangles; the others are listed as skipped, with the reason.
    ASSERT_EQ(j["scenes"].size(), 2u) << j.dump(1);
    EXPECT_EQ(j["scenes"][0]["name"], "cornell");
    EXPECT_EQ(j["scenes"][0]["scene"]["triangles"], 32);
    EXPECT_EQ(j["scenes"][1]["name"], "sphere-1k");
    EXPECT_EQ(j["scenes"][1]["scene"]["triangles"], 1000);
    for (const nlohmann::json& scene : j["scenes"]) {
        SCOPED_TRACE(scene["name"].get<std::string>());
        EXPECT_GE(scene["scene"]["emitters"].get<int>(), 1);
        expectSceneFigures(scene);
    }
    ASSERT_EQ(j["skipped"].size(), 4u);
    for (const nlohmann::json& s : j["skipped"])
        EXPECT_NE(s["reason"].get<std::string>().find("--max-triangles 2000"), std::string::npos) << s;

    // Issue #5's figure: each scene's paths per CPU-second as a share of the Cornell box's, same run.
    auto median = [&](int scene) {
        return j["scenes"][scene]["summary"]["paths_per_cpu_second"]["median"].get<double>();
    };
    EXPECT_DOUBLE_EQ(j["scenes"][0]["share_of_cornell"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(j["scenes"][1]["share_of_cornell"].get<double>(), median(1) / median(0));
    char line[64];
    std::snprintf(line, sizeof line, "  %-12s %5.1f %%", "sphere-1k", 100.0 * median(1) / median(0));
    EXPECT_NE(r.output.find("share of the Cornell box's paths per CPU-second"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(line), std::string::npos) << line << " in " << r.output;
}

TEST_F(Bench, SuiteSkipsTheBunnyWithANoteWithoutNpm) {
    // No PATH, so no npm: the bunny is skipped and the suite still succeeds.
    std::string file = path("suite.json");
    CliRun r = test::runFragpath(
        "bench --suite --scenes cornell --with-bunny --size 8x8 --spp 1 --runs 1 --json " + file,
        "LP_NUM_THREADS=2 PATH=/nonexistent");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("note: skipping bunny: npm is not installed"), std::string::npos) << r.output;
    std::ifstream in(file);
    nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_EQ(j["scenes"].size(), 1u);
    EXPECT_EQ(j["scenes"][0]["name"], "cornell");
    ASSERT_EQ(j["skipped"].size(), 1u);
    EXPECT_EQ(j["skipped"][0]["name"], "bunny");
}

TEST_F(Bench, BadFlagsAreErrors) {
    struct Case {
        const char* args;
        const char* fragment;
        int exitCode = 1;  // 2 for a command line that cannot be read
    };
    for (const Case& c :
         {Case{"--bogus", "unknown option --bogus", 2}, Case{"--runs", "needs a value", 2},
          Case{"--runs 0", "--runs"}, Case{"--spp 0", "--spp"}, Case{"--spp many", "--spp"},
          Case{"--size 16", "WIDTHxHEIGHT"}, Case{"--max-depth -1", "--max-depth"},
          Case{"--integrator magic", "naive, bsdf, nee or bdpt"}, Case{"a.obj b.obj", "one scene file"},
          Case{"--json /no/such/dir/b.json", "does not exist"},
          Case{"--max-triangles 10", "only goes with --suite"},
          Case{"--with-bunny", "only goes with --suite"}, Case{"--suite a.obj", "takes no scene file"},
          Case{"--suite --max-triangles 0", "--max-triangles"},
          Case{"--suite --scenes cornell,teapot", "no suite scene 'teapot'"},
          Case{"--study glass", "the only study is 'caustic'"},
          Case{"--budget 5", "only goes with --study"}}) {
        CliRun r = fragpath(std::string("bench ") + c.args);
        EXPECT_EQ(r.exitCode, c.exitCode) << c.args << ": " << r.output;
        EXPECT_NE(r.output.find("fragpath: error: "), std::string::npos) << c.args << ": " << r.output;
        EXPECT_NE(r.output.find(c.fragment), std::string::npos) << c.args << ": " << r.output;
    }
    CliRun r = fragpath("bench " + path("missing.obj") + " --spp 1 --runs 1");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("missing.obj"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace fp
