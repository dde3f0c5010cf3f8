#pragma once
// Scene files: JSON naming a mesh, with an optional camera and render settings, e.g.
//   {"mesh": "cornell.obj",
//    "camera": {"eye": [278, 273, -800], "target": [278, 273, 0], "up": [0, 1, 0], "fov": 39.3},
//    "render": {"width": 512, "height": 512, "spp": 64, "max_depth": 5, "seed": 1, "integrator": "nee"},
//    "lights": [{"type": "point", "position": [278, 500, 279], "intensity": 2e4, "color": [1, 0.9, 0.8]}]}
// "lights" holds point, spot and directional lights (parseLights in scene_file.cpp; units in scene.h).
#include <functional>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace fp {

// Loads the mesh a scene file names (the "mesh" value as written); throws fp::Error if it cannot.
using MeshLoader = std::function<Scene(const std::string& mesh)>;

// Loads the environment map a scene file names (the "environment.map" value as written).
using MapLoader = std::function<Image(const std::string& map)>;

// Parses scene-file `bytes`, naming the file `name` in messages, and loads its mesh and environment map
// through the loaders. Throws fp::Error on anything invalid; warns about unknown keys. Scene::source is
// `name`.
Scene parseSceneFile(std::string_view bytes, const std::string& name, const MeshLoader& loadMesh,
                     const MapLoader& loadMap = nullptr);

// A scene file on disk; its mesh path is relative to the file's directory.
Scene loadSceneFile(const std::string& path);

}  // namespace fp
