#pragma once
// Click to focus: the distance to put the thin lens's plane of focus at (Camera::focusDistance) so that
// the surface under the cursor is sharp. A CPU ray query (bvh/ray_query.h) through the lens's centre,
// against a BVH of the scene's triangles built at the first query (the renderer's tree lives on the
// GPU), so a session that never focuses pays nothing for it. No GL: unit-tested on its own.
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "bvh/bvh.h"
#include "bvh/ray_query.h"
#include "scene/scene.h"

namespace fp {

class FocusPicker {
  public:
    // Keeps a reference to `scene`, which must outlive the picker; `bvhThreads` as layout::bvhOptions.
    explicit FocusPicker(const Scene& scene, int bvhThreads = 0) : scene_(scene), bvhThreads_(bvhThreads) {}

    // The depth along the view direction (a focus distance) of the first surface that the ray from the
    // eye through the image point `ndc` (normalised device coordinates in [-1, 1]^2, y up) meets, for an
    // image of `aspect` = width / height; nothing when the ray meets no surface.
    std::optional<float> focusDistanceAt(const Camera& camera, float aspect, glm::vec2 ndc);

  private:
    const Scene& scene_;
    int bvhThreads_;
    std::vector<TriangleVerts> triangles_;
    std::optional<Bvh> bvh_;
};

// The normalised device coordinates (y up) of a cursor position in window coordinates (y down, the
// window `size` in the same units).
glm::vec2 cursorToNdc(glm::dvec2 cursor, glm::ivec2 size);

}  // namespace fp
