#include "scene/studio_environment.h"

#include <algorithm>
#include <cmath>

namespace fp {

namespace {

constexpr float kPi = 3.14159265358979f;

// 1 within `inner` degrees of `axis`, 0 beyond `outer`, and a smoothstep between: a soft-edged disc.
float softDisc(const glm::vec3& d, const glm::vec3& axis, float inner, float outer) {
    const float cosInner = std::cos(glm::radians(inner)), cosOuter = std::cos(glm::radians(outer));
    const float t = std::clamp((glm::dot(d, axis) - cosOuter) / (cosInner - cosOuter), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

glm::vec3 studioRadiance(const glm::vec3& d) {
    // Sky and ground blend over +-3 degrees about the horizon, so the map has no hard edge there.
    const float up = std::clamp((d.y + 0.05f) / 0.1f, 0.0f, 1.0f);
    const float sky = kStudioHorizon + (kStudioZenith - kStudioHorizon) * std::max(d.y, 0.0f);
    float radiance = kStudioGround + (sky - kStudioGround) * up * up * (3.0f - 2.0f * up);
    radiance = std::max(radiance, kStudioKey * softDisc(d, kStudioKeyDirection, 20.0f, 30.0f));
    radiance = std::max(radiance, kStudioFill * softDisc(d, kStudioFillDirection, 30.0f, 45.0f));
    return glm::vec3(radiance);
}

Environment studioEnvironment() {
    Environment environment;
    environment.map = Image(kStudioMapWidth, kStudioMapHeight);
    for (int y = 0; y < kStudioMapHeight; ++y)
        for (int x = 0; x < kStudioMapWidth; ++x) {
            // The inverse of u = 0.5 + atan2(d.x, -d.z) / 2pi, v = acos(d.y) / pi at the texel's centre.
            const float theta = kPi * (float(y) + 0.5f) / float(kStudioMapHeight);
            const float phi = 2.0f * kPi * ((float(x) + 0.5f) / float(kStudioMapWidth) - 0.5f);
            const glm::vec3 d(std::sin(theta) * std::sin(phi), std::cos(theta),
                              -std::sin(theta) * std::cos(phi));
            environment.map.at(x, y) = studioRadiance(d);
        }
    return environment;
}

}  // namespace fp
