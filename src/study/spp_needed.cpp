#include "study/spp_needed.h"

#include <cmath>
#include <cstdio>

namespace fp::study {

const StudyMetric& relMseMetric() {
    static const StudyMetric m{"relMSE", &StudyRow::relMse, 0.0, false, true};
    return m;
}
const StudyMetric& ssimMetric() {
    static const StudyMetric m{"SSIM", &StudyRow::ssim, 1.0, true, false};
    return m;
}
const StudyMetric& flipMetric() {
    static const StudyMetric m{"FLIP", &StudyRow::flip, 0.0, false, false};
    return m;
}

double distanceFromPerfect(const StudyMetric& metric, double value) {
    return std::abs(value - metric.perfect);
}

double scaledThreshold(const StudyMetric& metric, double threshold, double factor) {
    return metric.perfect + (threshold - metric.perfect) * factor;
}

SppNeeded sppNeeded(const std::vector<StudyRow>& series, const StudyMetric& metric, double threshold) {
    SppNeeded needed;
    if (series.empty()) return needed;
    needed.maxSpp = series.back().spp;
    const double target = distanceFromPerfect(metric, threshold);
    auto meets = [&](const StudyRow& r) {
        double v = r.*metric.value;
        return metric.higherIsBetter ? v >= threshold : v <= threshold;
    };
    for (size_t i = 0; i < series.size(); ++i) {
        if (!meets(series[i])) continue;
        needed.kind = Crossing::Measured;
        needed.spp = series[i].spp;
        const double d0 = i > 0 ? distanceFromPerfect(metric, series[i - 1].*metric.value) : 0.0;
        const double d1 = distanceFromPerfect(metric, series[i].*metric.value);
        // Interpolate only strictly between levels; an exact match (d1 = 0) has no logarithm.
        if (i > 0 && d1 < target && d1 > 0.0 && target > 0.0) {
            double x0 = std::log(series[i - 1].spp), x1 = std::log(series[i].spp);
            double y0 = std::log(d0), y1 = std::log(d1);
            needed.spp = std::exp(x0 + (std::log(target) - y0) * (x1 - x0) / (y1 - y0));
        }
        return needed;
    }
    const StudyRow& last = series.back();
    const double dLast = distanceFromPerfect(metric, last.*metric.value);
    if (metric.fallsAsOneOverN && last.denoiser == "none" && dLast > 0.0 && target > 0.0) {
        needed.kind = Crossing::Extrapolated;
        needed.spp = last.spp * dLast / target;
    }
    return needed;
}

SppNeeded sppNeeded(const std::vector<StudyRow>& series, double relMseThreshold) {
    return sppNeeded(series, relMseMetric(), relMseThreshold);
}

SppBand sppBand(const std::vector<StudyRow>& series, const StudyMetric& metric, double threshold) {
    return {sppNeeded(series, metric, scaledThreshold(metric, threshold, kLenientFactor)),
            sppNeeded(series, metric, threshold),
            sppNeeded(series, metric, scaledThreshold(metric, threshold, kStrictFactor))};
}

std::string describe(const SppNeeded& needed) {
    char text[128];
    switch (needed.kind) {
        case Crossing::Measured:
            std::snprintf(text, sizeof text, "%.3g", needed.spp);
            break;
        case Crossing::Extrapolated:
            std::snprintf(text, sizeof text, "~%.3g (not reached by %d spp; extrapolated, MSE ~ 1/N)",
                          needed.spp, needed.maxSpp);
            break;
        case Crossing::NotReached:
            std::snprintf(text, sizeof text, "not reached by %d spp", needed.maxSpp);
            break;
    }
    return text;
}

std::string describeShort(const SppNeeded& needed) {
    char text[64];
    switch (needed.kind) {
        case Crossing::Measured:
            std::snprintf(text, sizeof text, "%.3g", needed.spp);
            break;
        case Crossing::Extrapolated:
            std::snprintf(text, sizeof text, "~%.3g", needed.spp);
            break;
        case Crossing::NotReached:
            std::snprintf(text, sizeof text, ">%d", needed.maxSpp);
            break;
    }
    return text;
}

std::string describe(const SppBand& band) {
    return describeShort(band.atThreshold) + " [" + describeShort(band.lenient) + ", " +
           describeShort(band.strict) + "]";
}

}  // namespace fp::study
