#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/scene.h"

namespace fp {

Camera frameBounds(const Aabb& bounds, float fovY) {
    Camera camera;
    camera.fovY = fovY;
    camera.up = {0.0f, 1.0f, 0.0f};
    if (bounds.empty()) return camera;
    // Back off along -z until the bounding sphere fits in the vertical field of view.
    glm::vec3 center = bounds.center();
    float radius = std::max(0.5f * glm::length(bounds.extent()), 1e-3f);
    float distance = radius / std::sin(0.5f * glm::radians(fovY));
    camera.target = center;
    camera.eye = center + glm::vec3(0.0f, 0.0f, -distance);
    return camera;
}

float resolvedFocusDistance(const Camera& camera) {
    return camera.focusDistance.value_or(glm::length(camera.target - camera.eye));
}

// The same operations, in the same order, as the renderer has always used for its uniforms, so that a
// pinhole's rays stay bit for bit what they were.
CameraFrame cameraFrame(const Camera& camera, float aspect) {
    CameraFrame f;
    f.eye = camera.eye;
    f.forward = glm::normalize(camera.target - camera.eye);
    glm::vec3 right = glm::normalize(glm::cross(f.forward, camera.up));
    glm::vec3 up = glm::cross(right, f.forward);
    float tanHalf = std::tan(0.5f * glm::radians(camera.fovY));
    f.right = right * tanHalf * aspect;
    f.up = up * tanHalf;
    f.lensRadius = 0.5f * camera.aperture;
    f.focusDistance = resolvedFocusDistance(camera);
    return f;
}

glm::vec2 concentricDisk(glm::vec2 u) {
    // The square [-1, 1]^2 in concentric squares onto concentric circles: in the wedges |x| > |y| the
    // radius is x and the angle grows linearly with y / x over [-pi/4, pi/4]; elsewhere the same with
    // the axes exchanged.
    glm::vec2 s = 2.0f * u - 1.0f;
    if (s.x == 0.0f && s.y == 0.0f) return glm::vec2(0.0f);
    constexpr float kQuarterPi = 0.785398163397448f;
    float r, phi;
    if (std::abs(s.x) > std::abs(s.y)) {
        r = s.x;
        phi = kQuarterPi * (s.y / s.x);
    } else {
        r = s.y;
        phi = 2.0f * kQuarterPi - kQuarterPi * (s.x / s.y);
    }
    return r * glm::vec2(std::cos(phi), std::sin(phi));
}

}  // namespace fp

namespace fp {

void validateCamera(const Camera& c, const std::string& where) {
    auto finite = [](const glm::vec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    if (!finite(c.eye) || !finite(c.target) || !finite(c.up) || !std::isfinite(c.fovY))
        throw Error(where + " values must be finite numbers");
    // In double: target - eye of two huge floats would overflow in float and slip past the checks.
    glm::dvec3 view = glm::dvec3(c.target) - glm::dvec3(c.eye), up(c.up);
    if (glm::length(view) == 0.0) throw Error(where + ".eye and " + where + ".target are the same point");
    if (glm::length(up) == 0.0) throw Error(where + ".up must not be the zero vector");
    double sine = glm::length(glm::cross(view, up)) / (glm::length(view) * glm::length(up));
    if (!(sine > 1e-6)) throw Error(where + ".up is parallel to the view direction (target - eye)");
    if (!(c.fovY > 0.0f && c.fovY < 180.0f))
        throw Error(where + ".fov must be in (0, 180) degrees (the vertical field of view), got " +
                    std::to_string(c.fovY));
    if (!(c.aperture >= 0.0f) || !std::isfinite(c.aperture))
        throw Error(where +
                    ".aperture must be a finite number, 0 (a pinhole) or more (the lens diameter), got " +
                    std::to_string(c.aperture));
    if (c.focusDistance && (!(*c.focusDistance > 0.0f) || !std::isfinite(*c.focusDistance)))
        throw Error(
            where +
            ".focus_distance must be a finite number above 0 (the distance to the plane in focus), got " +
            std::to_string(*c.focusDistance));
}

}  // namespace fp
