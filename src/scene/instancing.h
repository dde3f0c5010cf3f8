#pragma once
// Instances: a mesh stored once (Scene::meshes, in its own space) and drawn in several places
// (Scene::instances). The renderer traces them with a two-level BVH (pack/layout.h); everything else
// that needs world-space triangles (the native reference, the viewer's focus picker) flattens them.
#include <string>

#include "core/aabb.h"
#include "scene/scene.h"

namespace fp {

// Triangle t of a mesh placed by objectToWorld: positions transformed, normals by the inverse transpose
// (renormalised), tangents by the linear part (their w kept: no mirroring).
Triangle placedTriangle(const Triangle& t, const glm::mat4& objectToWorld);

// A mesh's bounds in its own space.
Aabb meshBounds(const InstancedMesh& mesh);

// The world bounds of an instance: its mesh's bounds (`local`, from meshBounds) transformed (the box of
// the 8 corners).
Aabb instanceBounds(const Aabb& local, const glm::mat4& objectToWorld);

// `scene` with every instance's triangles (and tangents) appended to its world triangles, in the order
// of the instances, and no meshes or instances.
Scene flattenInstances(Scene scene);

// Throws fp::Error naming the scene if an instance names no mesh, a mesh is empty or holds an
// emitter, or a transform is not finite, not affine or mirrors (determinant <= 0): the renderer's
// two-level BVH relies on each.
void validateInstances(const Scene& scene);

}  // namespace fp
