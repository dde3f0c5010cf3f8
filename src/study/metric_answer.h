#pragma once
// The feasibility answer by each metric, with its sensitivity band: the cheapest combination of
// integrator and denoiser under the metric's threshold, the samples it needs at half, at and at double
// the threshold, and the year a GPU reaches each (feasibility.h).
#include <optional>
#include <string>
#include <vector>

#include "study/feasibility.h"
#include "study/report.h"
#include "study/spp_needed.h"

namespace fp::study {

struct MetricAnswer {
    std::string integrator, denoiser;  // empty: no combination reaches the threshold
    SppBand band;
    // The year a GPU reaches the need at each end of the band, at the efficiency measured here; empty
    // where that end is not reached.
    std::optional<YearAnswer> lenientYear, year, strictYear;
};

// Of the combinations in `feasibility` (raw ones if `denoised` is false, else denoised ones) whose
// series in `rows` reach `threshold` by `metric` (measured or extrapolated), the one that needs the least
// GPU peak at the threshold (spp x FLOPs per path / efficiency).
MetricAnswer cheapestAnswer(const std::vector<FeasibilityRow>& feasibility, const std::vector<StudyRow>& rows,
                            const StudyMetric& metric, double threshold, bool denoised);

// "2031" (a GPU of that year), "~2035" (the trend line), "-" (not reached); and a band as "2031 [2029,
// 2033]": at the threshold, then at double and at half of it.
std::string yearShort(const std::optional<YearAnswer>& year);
std::string yearBandText(const MetricAnswer& answer);

}  // namespace fp::study
