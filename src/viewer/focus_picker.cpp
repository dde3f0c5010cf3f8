#include "viewer/focus_picker.h"

#include <algorithm>

#include "pack/layout.h"
#include "scene/instancing.h"

namespace fp {

std::optional<float> FocusPicker::focusDistanceAt(const Camera& camera, float aspect, glm::vec2 ndc) {
    if (!bvh_) {
        triangles_.reserve(scene_.triangleCount());
        for (const Triangle& t : scene_.triangles) triangles_.push_back({t.p[0], t.p[1], t.p[2]});
        for (const Instance& instance : scene_.instances)  // in the world, as the renderer sees them
            for (const Triangle& local : scene_.meshes[instance.mesh].triangles) {
                Triangle t = placedTriangle(local, instance.objectToWorld);
                triangles_.push_back({t.p[0], t.p[1], t.p[2]});
            }
        bvh_ = triangles_.empty()
                   ? Bvh{}
                   : buildBinnedSah(triangleBounds(triangles_), layout::bvhOptions(bvhThreads_));
    }
    if (triangles_.empty()) return std::nullopt;
    CameraFrame frame = cameraFrame(camera, aspect);
    // Not normalised: the direction's component along forward is 1, so the hit's t is its depth along
    // the view direction, which is what the plane of focus is measured in.
    Ray ray;
    ray.origin = frame.eye;
    ray.dir = frame.forward + ndc.x * frame.right + ndc.y * frame.up;
    RayHit hit = closestHit(*bvh_, triangles_, ray);
    if (!hit.hit() || !(hit.t > 0.0f)) return std::nullopt;
    return hit.t;
}

glm::vec2 cursorToNdc(glm::dvec2 cursor, glm::ivec2 size) {
    glm::dvec2 s = glm::max(glm::dvec2(size), glm::dvec2(1.0));
    return glm::vec2(float(2.0 * cursor.x / s.x - 1.0), float(1.0 - 2.0 * cursor.y / s.y));
}

}  // namespace fp
