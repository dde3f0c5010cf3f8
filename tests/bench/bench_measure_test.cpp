// bench/bench_measure.h without a GL context: the spread of several runs, the figures of a run, the JSON
// the benchmark writes and the environment it reports.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/bench_measure.h"
#include "core/error.h"
#include "core/log.h"
#include "render/render_test_util.h"  // ScopedEnv
#include "settings/setting_table.h"

namespace fp::bench {
namespace {

Run makeRun(uint32_t seed, double wall, double cpu, double paths, double rays) {
    Run r;
    r.seed = seed;
    r.wallSeconds = wall;
    r.cpuSeconds = cpu;
    r.paths = paths;
    r.rays = rays;
    return r;
}

// Three timed runs whose medians are all in the middle run (seed 2) except where noted.
SceneMeasurement threeRuns() {
    SceneMeasurement m;
    m.source = "test scene";
    m.stats.triangles = 100;
    m.stats.storedTriangles = 100;  // no instances
    m.stats.emitters = 2;
    m.stats.gpuBytes = 12000;
    m.stats.gpuGeometryBytes = 8000;
    m.stats.bvhBuildSeconds = 0.5;
    m.stats.bvh.nodeCount = 7;
    m.loadSeconds = 0.1;
    m.rendererSeconds = 0.7;  // the BVH build (0.5) and 0.2 more
    m.compileSeconds = 0.3;
    m.firstPassSeconds = 0.4;
    m.warmUp = makeRun(0, 9.0, 9.0, 1000, 3000);
    m.timed = {makeRun(1, 2.0, 3.0, 1000, 4000), makeRun(2, 1.0, 4.0, 1000, 3000),
               makeRun(3, 4.0, 2.0, 1000, 5000)};
    return m;
}

TEST(BenchSpread, MedianMinAndMaxOfAnyOrder) {
    Spread odd = spread({3.0, 1.0, 2.0});
    EXPECT_DOUBLE_EQ(odd.median, 2.0);
    EXPECT_DOUBLE_EQ(odd.min, 1.0);
    EXPECT_DOUBLE_EQ(odd.max, 3.0);
    Spread even = spread({10.0, 4.0, 1.0, 2.0});
    EXPECT_DOUBLE_EQ(even.median, 3.0);
    EXPECT_DOUBLE_EQ(even.min, 1.0);
    EXPECT_DOUBLE_EQ(even.max, 10.0);
    Spread one = spread({5.0});
    EXPECT_DOUBLE_EQ(one.median, 5.0);
    EXPECT_DOUBLE_EQ(one.min, 5.0);
    EXPECT_DOUBLE_EQ(one.max, 5.0);
    EXPECT_THROW(spread({}), std::invalid_argument);
}

TEST(BenchRun, FiguresAreTheirQuotients) {
    bench::Run r = makeRun(1, 2.0, 4.0, 1000, 3000);
    EXPECT_DOUBLE_EQ(r.pathsPerSecond(), 500.0);
    EXPECT_DOUBLE_EQ(r.pathsPerCpuSecond(), 250.0);
    EXPECT_DOUBLE_EQ(r.raysPerSecond(), 1500.0);
    EXPECT_DOUBLE_EQ(r.raysPerCpuSecond(), 750.0);
    EXPECT_DOUBLE_EQ(r.raysPerPath(), 3.0);
    EXPECT_DOUBLE_EQ(r.cpuPerWall(), 2.0);
}

// The JSON keys are what scripts read: each names the figure it claims.
TEST(BenchColumns, EachKeyReadsItsOwnFigure) {
    bench::Run r = makeRun(1, 2.0, 4.0, 1000, 3000);
    std::map<std::string, double> expected = {{"wall_seconds", 2.0},           {"cpu_seconds", 4.0},
                                              {"cpu_per_wall", 2.0},           {"paths_per_second", 500.0},
                                              {"paths_per_cpu_second", 250.0}, {"rays_per_second", 1500.0},
                                              {"rays_per_cpu_second", 750.0},  {"rays_per_path", 3.0}};
    std::set<std::string> seen;
    for (const Column& c : columns()) {
        ASSERT_TRUE(expected.count(c.key)) << c.key;
        EXPECT_DOUBLE_EQ(c.get(r), expected[c.key]) << c.key;
        EXPECT_TRUE(seen.insert(c.key).second) << c.key << " twice";
    }
    EXPECT_EQ(seen.size(), expected.size());
}

TEST(BenchSummary, IsTheSpreadOfTheTimedRunsOnly) {
    SceneMeasurement m = threeRuns();
    Spread wall = m.summary("wall_seconds");  // 2, 1, 4: the warm-up's 9 is not counted
    EXPECT_DOUBLE_EQ(wall.median, 2.0);
    EXPECT_DOUBLE_EQ(wall.min, 1.0);
    EXPECT_DOUBLE_EQ(wall.max, 4.0);
    Spread paths = m.summary("paths_per_second");  // 500, 1000, 250
    EXPECT_DOUBLE_EQ(paths.median, 500.0);
    EXPECT_DOUBLE_EQ(paths.min, 250.0);
    EXPECT_DOUBLE_EQ(paths.max, 1000.0);
    // The median of a quotient is not the quotient of medians: cpu/wall per run is 1.5, 4, 0.5.
    EXPECT_DOUBLE_EQ(m.summary("cpu_per_wall").median, 1.5);
    EXPECT_THROW(m.summary("no_such_figure"), Error);
}

TEST(BenchSummary, FirstFrameSpansLoadStartToFirstPassEnd) {
    SceneMeasurement m;
    m.loadStart = SteadyClock::time_point{};
    m.firstPassEnd = m.loadStart + std::chrono::milliseconds(1250);
    EXPECT_DOUBLE_EQ(m.sceneFirstFrameSeconds(), 1.25);
}

TEST(BenchJson, MeasurementHasEveryRunAndItsSummary) {
    SceneMeasurement m = threeRuns();
    nlohmann::json j = measurementJson(m, 1.5);
    EXPECT_EQ(j["scene"]["source"], "test scene");
    EXPECT_EQ(j["scene"]["triangles"], 100);
    EXPECT_EQ(j["scene"]["emitters"], 2);
    EXPECT_DOUBLE_EQ(j["bvh"]["triangles_per_second"].get<double>(), 200.0);
    EXPECT_EQ(j["bvh"]["nodes"], 7);
    EXPECT_DOUBLE_EQ(j["gpu"]["bytes_per_triangle"].get<double>(), 120.0);
    EXPECT_DOUBLE_EQ(j["gpu"]["geometry_bytes_per_triangle"].get<double>(), 80.0);
    EXPECT_DOUBLE_EQ(j["first_frame"]["seconds"].get<double>(), 1.5);
    EXPECT_DOUBLE_EQ(j["first_frame"]["load_seconds"].get<double>(), 0.1);
    EXPECT_DOUBLE_EQ(j["first_frame"]["bvh_seconds"].get<double>(), 0.5);
    EXPECT_DOUBLE_EQ(j["first_frame"]["pack_and_upload_seconds"].get<double>(), 0.7 - 0.5);
    EXPECT_DOUBLE_EQ(j["first_frame"]["compile_seconds"].get<double>(), 0.3);
    EXPECT_DOUBLE_EQ(j["first_frame"]["first_pass_seconds"].get<double>(), 0.4);
    EXPECT_EQ(j["warm_up"]["seed"], 0);
    EXPECT_DOUBLE_EQ(j["warm_up"]["wall_seconds"].get<double>(), 9.0);

    ASSERT_EQ(j["runs"].size(), m.timed.size());
    for (size_t i = 0; i < m.timed.size(); ++i) {
        const nlohmann::json& run = j["runs"][i];
        EXPECT_EQ(run["seed"], m.timed[i].seed);
        EXPECT_DOUBLE_EQ(run["paths"].get<double>(), m.timed[i].paths);
        EXPECT_DOUBLE_EQ(run["rays"].get<double>(), m.timed[i].rays);
        for (const Column& c : columns()) EXPECT_DOUBLE_EQ(run[c.key].get<double>(), c.get(m.timed[i]));
    }
    for (const Column& c : columns()) {
        Spread s = m.summary(c);
        EXPECT_DOUBLE_EQ(j["summary"][c.key]["median"].get<double>(), s.median) << c.key;
        EXPECT_DOUBLE_EQ(j["summary"][c.key]["min"].get<double>(), s.min) << c.key;
        EXPECT_DOUBLE_EQ(j["summary"][c.key]["max"].get<double>(), s.max) << c.key;
    }
    EXPECT_TRUE(j["other_processes_cpu_share"].is_null());
    m.othersCpuShare = 0.25;
    EXPECT_DOUBLE_EQ(measurementJson(m, 1.5)["other_processes_cpu_share"].get<double>(), 0.25);
}

TEST(BenchJson, SettingsAreTheOnesMeasuredWith) {
    BenchSettings s;
    s.render.width = 320;
    s.render.height = 200;
    s.render.maxDepth = 3;
    s.render.integrator = Integrator::Bdpt;
    s.render.sampler = Sampler::Independent;
    s.render.samplesPerPass = 4;
    s.spp = 6;
    s.runs = 7;
    nlohmann::json j = benchSettingsJson(s);
    // Every row of the settings table, by its name, and the run's spp and runs.
    for (const Setting& row : settingTable()) EXPECT_TRUE(j.contains(row.name)) << row.name;
    EXPECT_EQ(j["width"], 320);
    EXPECT_EQ(j["height"], 200);
    EXPECT_EQ(j["spp"], 6);
    EXPECT_EQ(j["runs"], 7);
    EXPECT_EQ(j["max_depth"], 3);
    EXPECT_EQ(j["integrator"], "bdpt");
    EXPECT_EQ(j["sampler"], "independent");
    EXPECT_EQ(j["samples_per_pass"], 4);
}

TEST(BenchEnvironment, ThreadsTextIsTheVariableOrUnset) {
    BenchEnvironment e;
    EXPECT_EQ(e.threadsText(), "unset");
    e.threads = "2";
    EXPECT_EQ(e.threadsText(), "2");
}

// Mesa's reading of a boolean: 0, n, no, f, false in any case mean false, any other value true.
TEST(BenchEnvironment, ShaderCacheFollowsMesasBooleans) {
    BenchEnvironment e;
    e.renderer = "llvmpipe (test)";
    EXPECT_EQ(e.cacheText(), "enabled (MESA_SHADER_CACHE_DISABLE unset)");
    EXPECT_EQ(environmentJson(e)["shader_cache_disabled"], false);
    EXPECT_TRUE(environmentJson(e)["mesa_shader_cache_disable"].is_null());
    for (const char* off : {"0", "n", "no", "f", "false", "FALSE", "No"}) {
        e.cacheDisable = off;
        EXPECT_EQ(e.cacheText(), std::string("enabled (MESA_SHADER_CACHE_DISABLE=") + off + ")");
        EXPECT_EQ(environmentJson(e)["shader_cache_disabled"], false) << off;
    }
    for (const char* on : {"1", "true", "TRUE", "yes", "y"}) {
        e.cacheDisable = on;
        EXPECT_EQ(e.cacheText(), std::string("disabled (MESA_SHADER_CACHE_DISABLE=") + on + ")");
        EXPECT_EQ(environmentJson(e)["shader_cache_disabled"], true) << on;
        EXPECT_EQ(environmentJson(e)["mesa_shader_cache_disable"], on);
    }
    EXPECT_EQ(environmentJson(e)["renderer"], "llvmpipe (test)");
}

TEST(BenchEnvironment, ReadsLpNumThreadsAndWarnsWhenItIsUnset) {
    {
        test::ScopedEnv threads("LP_NUM_THREADS", nullptr);
        test::ScopedEnv cache("MESA_SHADER_CACHE_DISABLE", "true");
        WarningCapture warnings;
        BenchEnvironment e = readBenchEnvironment();
        EXPECT_FALSE(e.threads);
        EXPECT_EQ(e.cacheDisable, "true");
        EXPECT_TRUE(warnings.contains("LP_NUM_THREADS is unset")) << warnings.messages().size();
        EXPECT_TRUE(environmentJson(e)["lp_num_threads"].is_null());
    }
    {
        test::ScopedEnv threads("LP_NUM_THREADS", "3");
        test::ScopedEnv cache("MESA_SHADER_CACHE_DISABLE", nullptr);
        WarningCapture warnings;
        BenchEnvironment e = readBenchEnvironment();
        EXPECT_EQ(e.threadsText(), "3");
        EXPECT_FALSE(e.cacheDisable);
        EXPECT_TRUE(warnings.messages().empty());
        EXPECT_EQ(environmentJson(e)["lp_num_threads"], "3");
    }
}

TEST(BenchJsonFile, PathIsCheckedBeforeMeasuringAndWrittenAfter) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("fragpath_bench_json_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string file = (dir / "out.json").string();
    EXPECT_NO_THROW(checkJsonPath(file));
    try {
        checkJsonPath((dir / "missing" / "out.json").string());
        ADD_FAILURE() << "accepted a missing directory";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
    }
    try {
        checkJsonPath(dir.string());
        ADD_FAILURE() << "accepted a directory";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
    }

    nlohmann::json j = {{"a", 1}, {"b", {1.5, 2.5}}};
    writeJson(file, j);
    EXPECT_EQ(nlohmann::json::parse(std::ifstream(file)), j);
    EXPECT_THROW(writeJson((dir / "missing" / "out.json").string(), j), Error);
    fs::remove_all(dir);
}

// The table has one row per timed run, named by its seed, then median, min and max.
TEST(BenchPrint, TableHasEveryRunAndTheSpread) {
    SceneMeasurement m = threeRuns();
    testing::internal::CaptureStdout();
    printMeasurement(m, 1.5, 0.25);
    std::string out = testing::internal::GetCapturedStdout();
    EXPECT_NE(out.find("first frame      1.500 s: context 0.250, load 0.100"), std::string::npos) << out;
    for (const char* row : {"\n  1 ", "\n  2 ", "\n  3 ", "\n  median", "\n  min", "\n  max"})
        EXPECT_NE(out.find(row), std::string::npos) << row << " in\n" << out;
    // The median row's first cells: wall seconds, the median of 2, 1 and 4; cpu seconds, of 3, 4 and 2.
    size_t median = out.find("\n  median");
    ASSERT_NE(median, std::string::npos);
    std::istringstream row(out.substr(median, out.find('\n', median + 1) - median));
    std::string label, wall, cpu;
    row >> label >> wall >> cpu;
    EXPECT_EQ(wall, "2.000");
    EXPECT_EQ(cpu, "3.000");
}

}  // namespace
}  // namespace fp::bench
