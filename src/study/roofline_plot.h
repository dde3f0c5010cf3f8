#pragma once
// The roofline chart, one per scene and integrator the report's Roofline section shows: the rays per second
// that 1080p60 needs at the threshold's spp (one line per denoiser) against each GPU's limits by year, in
// rays per second (paths per second x rays per path), x80 and flagship cards as separate lines.
#include <string>

#include "study/report.h"

namespace fp::study {

// One scene's files: "cornell_roofline_nee.png", drawn by "cornell_roofline.gp".
std::string rooflinePlotName(const std::string& scene, const std::string& integrator);
std::string rooflineScriptName(const std::string& scene);

// The gnuplot script (its data inline) that draws every chart of `input` (one scene) in the current
// directory.
std::string rooflineGnuplotScript(const ReportInput& input);

// Writes DIR/rooflineScriptName(input.sceneName) and runs gnuplot there (plots.h runGnuplotScript);
// nothing to draw, no file.
void drawRooflinePlots(const std::string& dir, const ReportInput& input);

}  // namespace fp::study
