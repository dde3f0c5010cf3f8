#pragma once
// The study's plots, drawn by gnuplot from study.csv: a script is written next to the CSV (so that a
// user can edit it and run `gnuplot plots.gp` there again) and run as a subprocess.
#include <string>
#include <vector>

#include "study/sweep.h"

namespace fp::study {

// 60 frames per second.
constexpr double kFrameBudgetSeconds = 1.0 / 60.0;

// The plot files the script writes for one scene, in its directory: <scene>_error_vs_spp.png, ...
std::vector<std::string> plotFileNames(const std::string& scene);

// The gnuplot script for `rows` (read back from study.csv in the same directory): for each scene,
// relative MSE against samples per pixel and against time (log-log, the 60 FPS budget marked, the
// noise threshold drawn), and SSIM against samples per pixel.
std::string gnuplotScript(const std::vector<StudyRow>& rows, double relMseThreshold);

// Throws fp::Error with install instructions if gnuplot is not on PATH; checked before rendering.
void requireGnuplot();
// Writes DIR/FILE with `script` and runs gnuplot on it in DIR; throws fp::Error with gnuplot's output if
// it fails.
void runGnuplotScript(const std::string& dir, const std::string& file, const std::string& script);
// Writes DIR/plots.gp and runs gnuplot in DIR; throws fp::Error with gnuplot's output if it fails.
void drawPlots(const std::string& dir, const std::vector<StudyRow>& rows, double relMseThreshold);

}  // namespace fp::study
