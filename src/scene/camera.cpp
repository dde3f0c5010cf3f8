#include <algorithm>
#include <cmath>

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
