#include "study/metric_answer.h"

#include <algorithm>
#include <cstdio>

namespace fp::study {

namespace {

std::optional<YearAnswer> yearOf(const SppNeeded& needed, const FeasibilityRow& f) {
    if (needed.kind == Crossing::NotReached) return std::nullopt;
    return yearReached(requiredFlopsPerSecond(std::max(needed.spp, 1.0), f.flopsPerPath), f.efficiency);
}

}  // namespace

MetricAnswer cheapestAnswer(const std::vector<FeasibilityRow>& feasibility, const std::vector<StudyRow>& rows,
                            const StudyMetric& metric, double threshold, bool denoised) {
    MetricAnswer best;
    double bestPeak = 0.0;
    for (const FeasibilityRow& f : feasibility) {
        if ((f.denoiser != "none") != denoised || !(f.efficiency > 0.0)) continue;
        std::vector<StudyRow> series;
        for (const StudyRow& r : rows)
            if (r.integrator == f.integrator && r.denoiser == f.denoiser) series.push_back(r);
        SppBand band = sppBand(series, metric, threshold);
        if (band.atThreshold.kind == Crossing::NotReached) continue;
        double peak =
            requiredFlopsPerSecond(std::max(band.atThreshold.spp, 1.0), f.flopsPerPath) / f.efficiency;
        if (!best.integrator.empty() && peak >= bestPeak) continue;
        bestPeak = peak;
        best.integrator = f.integrator;
        best.denoiser = f.denoiser;
        best.band = band;
        best.lenientYear = yearOf(band.lenient, f);
        best.year = yearOf(band.atThreshold, f);
        best.strictYear = yearOf(band.strict, f);
    }
    return best;
}

std::string yearShort(const std::optional<YearAnswer>& year) {
    if (!year) return "-";
    char text[32];
    if (year->firstGpuYear)
        std::snprintf(text, sizeof text, "%d", *year->firstGpuYear);
    else
        std::snprintf(text, sizeof text, "~%.0f", year->extrapolatedYear);
    return text;
}

std::string yearBandText(const MetricAnswer& answer) {
    return yearShort(answer.year) + " [" + yearShort(answer.lenientYear) + ", " +
           yearShort(answer.strictYear) + "]";
}

}  // namespace fp::study
