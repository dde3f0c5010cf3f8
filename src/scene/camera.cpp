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
    auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (!finite(c.eye) || !finite(c.target) || !finite(c.up) || !std::isfinite(c.fovY))
        throw Error(where + ": camera values must be finite numbers");
    if (c.eye == c.target) throw Error(where + ": camera eye and target are the same point");
    if (glm::length(c.up) == 0.0f) throw Error(where + ": camera up vector is zero");
    glm::vec3 forward = glm::normalize(c.target - c.eye);
    if (glm::length(glm::cross(forward, glm::normalize(c.up))) < 1e-6f)
        throw Error(where + ": camera up vector is parallel to the viewing direction");
    if (!(c.fovY > 0.0f && c.fovY < 180.0f))
        throw Error(where + ": field of view must be between 0 and 180 degrees, got " + std::to_string(c.fovY));
}

}  // namespace fp
