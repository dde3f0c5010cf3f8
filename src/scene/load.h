#pragma once
// Loading scenes from files: the first pipeline stage. Everything that reaches the BVH builder has
// passed through here, so this is where bad input is rejected (fp::Error, naming the file and line) or
// repaired (fp::warn, one warning per kind of repair).
#include <string>

#include "scene/scene.h"

namespace fp {

// By extension (case-insensitive): .obj loads an OBJ with its MTL libraries (no camera); .gltf and .glb
// load a glTF 2.0 file (scene/gltf.h; its camera, if it has one); .json loads a scene file naming a mesh,
// camera and render settings. The result always has at least one valid
// triangle and one material.
Scene loadScene(const std::string& path);

// An OBJ file and the MTL libraries it names (looked up next to it).
Scene loadObj(const std::string& path);

// A glTF 2.0 file (.gltf or .glb) and the buffers and images it names (looked up next to it).
Scene loadGltf(const std::string& path);

}  // namespace fp
