#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/scene.h"

namespace fp {

Camera frameBounds(const Aabb& bounds, float fovY, float aspect) {
    Camera camera;
    camera.fovY = fovY;
    camera.up = {0.0f, 1.0f, 0.0f};
    if (bounds.empty()) return camera;
    // From the front (glTF's convention: a model faces +z) and kFrameElevationDegrees above, as model
    // viewers look at a model, aimed at the box's centre.
    const float elevation = glm::radians(kFrameElevationDegrees);
    const glm::vec3 center = bounds.center();
    const glm::vec3 back(0.0f, std::sin(elevation), std::cos(elevation));  // from the centre to the eye
    const glm::vec3 forward = -back;
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    // The distance at which every corner of the box lies inside both fields of view, widened by
    // kFrameMargin. A corner at (x, y) across and z along the view from the centre is in view from the
    // distance d when |x| <= (d + z) tan(fovX / 2) and |y| <= (d + z) tan(fovY / 2).
    const float tanY = std::tan(0.5f * glm::radians(fovY)) / kFrameMargin;
    const float tanX = tanY * std::max(aspect, 1e-3f);
    const float radius = std::max(0.5f * glm::length(bounds.extent()), 1e-3f);
    float distance = radius / std::sin(0.5f * glm::radians(fovY));  // a point-like box: its sphere
    if (glm::length(bounds.extent()) > 0.0f) distance = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? bounds.hi.x : bounds.lo.x, (corner & 2) ? bounds.hi.y : bounds.lo.y,
                          (corner & 4) ? bounds.hi.z : bounds.lo.z);
        const glm::vec3 offset = p - center;
        const float x = glm::dot(offset, right), y = glm::dot(offset, up), z = glm::dot(offset, forward);
        // Never closer than a tenth of the radius in front of any corner (a corner on the view axis).
        distance = std::max({distance, std::abs(x) / tanX - z, std::abs(y) / tanY - z, 0.1f * radius - z});
    }
    camera.target = center;
    camera.eye = center + back * distance;
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
