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

}  // namespace fp
