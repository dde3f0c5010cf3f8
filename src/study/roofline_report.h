#pragma once
// The report's roofline: the GPU table once, and per scene a "Roofline" section with the bytes and
// integer work per path, each GPU's limits per integrator and the first GPU of each class that reaches
// the samples the threshold needs.
#include <string>
#include <vector>

#include "study/report.h"
#include "study/roofline.h"

namespace fp::study {

// The integrators of `input` that have path counts and at least one denoiser whose series reaches the
// threshold (measured or extrapolated): the ones the section and the chart show.
std::vector<std::string> rooflineIntegrators(const ReportInput& input);

// What `integrator`'s average path costs in `input`'s scene; throws std::out_of_range without its counts.
PathWork workOf(const ReportInput& input, const std::string& integrator);

// A class's answer when no GPU of the table reaches the rate: the table's last year and the year the
// class's trend line gets there ("none up to 2025 (trend ~2031)").
std::string noGpuReachesText(const ClassAnswer& answer);

// The GPU table with its ray-rate and integer-lane notes: the same for every scene, so the report gives
// it once, in its common part.
std::string rooflineGpuMarkdown();
// One scene's section (headed "### Roofline", within the scene's section).
std::string rooflineMarkdown(const ReportInput& input);

}  // namespace fp::study
