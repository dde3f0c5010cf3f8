#pragma once
// A scene's triangles as a binary glTF (.glb), so that the benchmark can time loading a large glTF file
// that the project makes itself (bench --suite, sphere-1m-glb) instead of one downloaded.
#include <string>

#include "scene/scene.h"

namespace fp::bench {

// Writes `scene` to `path` as glTF 2.0 binary: one mesh under one node, a primitive per material that
// some triangle uses, vertices shared where position and normal agree (indexed, 32-bit), positions and
// normals only (no texture coordinates); each material as a metallic-roughness one with base colour
// Material::diffuse, metallic 0, roughness 1, its emission (above 1 through
// KHR_materials_emissive_strength) and doubleSided, so that it renders as one-sided emitters and
// double-sided surfaces as the OBJ path does. No camera, lights or environment. Throws fp::Error if
// the file cannot be written.
void writeGlb(const Scene& scene, const std::string& path);

}  // namespace fp::bench
