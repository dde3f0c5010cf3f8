#pragma once
// `fragpath bench --suite`: a fixed set of scenes, made in code with exact triangle counts, measured one
// after another in one process with the same settings, so that figures from different machines, Mesa
// versions and commits compare scene by scene.
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_measure.h"

namespace fp::bench {

struct SuiteOptions {
    BenchSettings settings;
    std::optional<long long> maxTriangles;  // scenes with more are skipped
    bool withBunny = false;                 // add the Stanford bunny, fetched with npm
    bool native = false;                    // also measure the native reference (bench_native.h)
    std::vector<std::string> scenes;        // only these (by name); empty: the default set
    std::optional<std::string> jsonPath;
};

// The suite's scene names in the order they run; "bunny" only runs when asked for.
const std::vector<std::string>& suiteSceneNames();

// Runs the suite, printing each scene's figures and a summary table. Returns the exit code.
int runSuite(const SuiteOptions& options);

}  // namespace fp::bench
