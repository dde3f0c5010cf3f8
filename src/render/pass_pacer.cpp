#include "render/pass_pacer.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace fp {

PassPacer::PassPacer(int fixedCount, int maxCount, double targetSeconds)
    : fixed_(fixedCount), max_(maxCount), target_(targetSeconds) {
    if (maxCount < 1 || fixedCount < 0 || fixedCount > maxCount || !(targetSeconds > 0.0))
        throw Error("internal: PassPacer(" + std::to_string(fixedCount) + ", " + std::to_string(maxCount) +
                    ")");
}

int PassPacer::next(int remaining) const {
    return std::max(0, std::min(fixed_ > 0 ? fixed_ : count_, remaining));
}

void PassPacer::record(int samples, double seconds) {
    if (fixed_ > 0 || samples < 1) return;
    // The count that would have taken the target time at this pass's rate: every sample of a pixel costs
    // the same in expectation, so one pass's rate predicts the next's. A pass slowed by something else (the
    // first one's shader JIT, another process) only makes the next pass shorter.
    double fitting = seconds > 0.0 ? double(samples) * target_ / seconds : double(max_);
    count_ = int(std::clamp(std::floor(fitting), 1.0, double(max_)));
}

}  // namespace fp
