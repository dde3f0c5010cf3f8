#pragma once
// The count views' colour scale on the CPU, for the panel's legend and for screenshots. It must match
// heatMap() in glsl/common/tone_map.glsl stop for stop: the window shows the GLSL one.
#include <algorithm>
#include <array>

#include <glm/glm.hpp>

namespace fp {

// Display code values in [0, 1] (no sRGB encoding is applied to them, as in the display pass).
constexpr std::array<glm::vec3, 6> kHeatMapStops = {glm::vec3(0.0f),
                                                    glm::vec3(0.0f, 0.2f, 1.0f),
                                                    glm::vec3(0.0f, 0.8f, 0.3f),
                                                    glm::vec3(1.0f, 0.9f, 0.0f),
                                                    glm::vec3(1.0f, 0.1f, 0.0f),
                                                    glm::vec3(1.0f)};

// t = count / heat-map maximum; clamped to [0, 1], as the shader does.
inline glm::vec3 heatMapColor(float t) {
    float x = std::clamp(t, 0.0f, 1.0f) * 5.0f;
    if (!(x >= 0.0f)) x = 0.0f;  // NaN
    int i = std::min(int(x), 4);
    return glm::mix(kHeatMapStops[size_t(i)], kHeatMapStops[size_t(i) + 1], x - float(i));
}

}  // namespace fp
