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
}

}  // namespace fp
