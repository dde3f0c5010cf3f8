#include "realtime/frame_budget.h"

#include <algorithm>
#include <cmath>

namespace fp {

int adaptSamplesPerFrame(int spp, double traceMs, double fps, double overheadMs) {
    spp = std::clamp(spp, 1, FrameBudget::maxSpp);
    if (!(fps > 0.0) || !(traceMs > 0.0)) return spp;
    double share = std::max(1000.0 / fps - std::max(overheadMs, 0.0), 0.0);  // ms left for tracing
    double perSample = traceMs / double(spp);
    bool over = traceMs > FrameBudget::overrun * share;
    bool room = double(spp + 1) * perSample < FrameBudget::headroom * share;
    if (!over && !room) return spp;
    double fit = std::floor(0.9 * share / perSample);
    int next = int(std::clamp(fit, 1.0, double(FrameBudget::maxSpp)));
    // Never move against the measurement: an overrun only lowers, room only raises.
    return over ? std::min(next, spp) : std::max(next, spp);
}

float adaptResolutionScale(float scale, double frameMs, double fps) {
    // Ladder step k is scale 2^(-k/2), pixel count 2^-k.
    const int lowest = int(std::lround(-2.0 * std::log2(double(FrameBudget::minScale))));
    int step = std::isfinite(scale) && scale > 0.0f ? int(std::lround(-2.0 * std::log2(double(scale)))) : 0;
    step = std::clamp(step, 0, lowest);
    if (fps > 0.0 && frameMs > 0.0 && std::isfinite(frameMs)) {
        const double budget = 1000.0 / fps;
        if (frameMs > FrameBudget::overrun * budget)
            step += std::max(1, int(std::ceil(std::log2(frameMs / (0.9 * budget)))));
        else if (step > 0 && 2.0 * frameMs < FrameBudget::headroom * budget)
            --step;
        step = std::clamp(step, 0, lowest);
    }
    return float(std::exp2(-0.5 * double(step)));
}

}  // namespace fp
