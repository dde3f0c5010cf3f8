#pragma once
// Scenes made by code rather than read from files: test objects with known answers, and benchmark
// meshes with exact triangle counts.
#include <cstdint>

#include "scene/scene.h"

namespace fp {

// Appends a UV sphere of 2 * segments * (rings - 1) triangles, wound counter-clockwise seen from
// outside; `smooth` gives vertex normals (the sphere's own), otherwise the flat facet normals.
void appendSphere(Scene& scene, const glm::vec3& center, float radius, int rings, int segments, uint32_t material,
                  bool smooth);

}  // namespace fp
