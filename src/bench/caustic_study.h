#pragma once
// `fragpath bench --study caustic`: bdpt against nee at equal process CPU time on causticScene
// (scene/procedural.h), the figures of BENCHMARKS.md ("BDPT vs NEE on a caustic scene").
namespace fp::bench {

struct CausticStudyOptions {
    double budgetSeconds = 40.0;  // process CPU seconds per integrator and scene
    int referenceSpp = 16384;     // bdpt samples per pixel of the reference
};

// Prints the table; returns the exit code.
int runCausticStudy(const CausticStudyOptions& options);

}  // namespace fp::bench
