#include "viewer/accumulation_policy.h"

#include <algorithm>
#include <cmath>

#include "settings/setting_table.h"

namespace fp {

bool sameAccumulation(const RenderSettings& a, const RenderSettings& b) {
    bool sameSplit =
        a.split.has_value() == b.split.has_value() &&
        (!a.split || (a.split->integrator == b.split->integrator && a.split->maxDepth == b.split->maxDepth));
    return sameSettings(a, b, kRestartsAccumulation) && sameSplit;
}

glm::ivec2 AccumulationPolicy::scaled(glm::ivec2 window, float scale) {
    return glm::max(glm::ivec2(1), glm::ivec2(glm::round(glm::vec2(window) * scale)));
}

bool AccumulationPolicy::moving(double now) const {
    return now - lastChange_ < options_.settleSeconds;
}

AccumulationPolicy::Decision AccumulationPolicy::update(const Request& request) {
    Decision decision;
    bool visible = request.windowSize.x > 0 && request.windowSize.y > 0;
    // Motion: a new camera, or a new window size (a resize drag sends many). The first frame is neither.
    if (seenAny_ && (request.cameraVersion != seenCamera_ || (visible && request.windowSize != seenWindow_)))
        lastChange_ = request.now;
    seenAny_ = true;
    seenCamera_ = request.cameraVersion;
    if (visible) seenWindow_ = request.windowSize;
    if (!visible) return decision;  // minimised: keep the accumulation for when it comes back

    auto clampScale = [this](float scale) {
        return std::isfinite(scale) ? std::clamp(scale, options_.minScale, 1.0f) : 1.0f;
    };
    float still = clampScale(request.resolutionScale), movingScale = clampScale(request.movingScale);
    decision.reduced = request.reduceWhileMoving && moving(request.now) && movingScale < still;
    glm::ivec2 size = scaled(request.windowSize, decision.reduced ? movingScale : still);
    decision.render = true;
    decision.settings = request.settings;
    decision.settings.width = size.x;
    decision.settings.height = size.y;
    decision.restart = !configuredAny_ || request.cameraVersion != configuredCamera_ ||
                       !sameAccumulation(decision.settings, configured_);
    if (decision.restart) {
        configuredAny_ = true;
        configuredCamera_ = request.cameraVersion;
        configured_ = decision.settings;
        ++restarts_;
    }
    return decision;
}

void AccumulationPolicy::restartFailed(const RenderSettings& settings) {
    configured_ = settings;
}

}  // namespace fp
