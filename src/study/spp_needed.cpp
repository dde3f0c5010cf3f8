#include "study/spp_needed.h"

#include <cmath>
#include <cstdio>

namespace fp::study {

SppNeeded sppNeeded(const std::vector<StudyRow>& series, double threshold) {
    SppNeeded needed;
    if (series.empty()) return needed;
    needed.maxSpp = series.back().spp;
    for (size_t i = 0; i < series.size(); ++i) {
        if (series[i].relMse > threshold) continue;
        needed.kind = Crossing::Measured;
        needed.spp = series[i].spp;
        if (i > 0 && series[i].relMse < threshold) {
            double x0 = std::log(series[i - 1].spp), x1 = std::log(series[i].spp);
            double y0 = std::log(series[i - 1].relMse), y1 = std::log(series[i].relMse);
            needed.spp = std::exp(x0 + (std::log(threshold) - y0) * (x1 - x0) / (y1 - y0));
        }
        return needed;
    }
    const StudyRow& last = series.back();
    if (last.denoiser == "none" && last.relMse > 0.0) {
        needed.kind = Crossing::Extrapolated;
        needed.spp = last.spp * last.relMse / threshold;
    }
    return needed;
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

}  // namespace fp::study
