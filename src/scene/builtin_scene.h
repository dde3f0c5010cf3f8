#pragma once
// The built-in Cornell box: assets/cornell/ compiled into the binary, so `fragpath render` with no
// scene works from any directory. The asset files stay the one source of its data.
#include <map>
#include <string>

#include "scene/scene.h"

namespace fp {

// assets/cornell/* as text, keyed by file name (cornell.obj, cornell.mtl, cornell.json).
const std::map<std::string, std::string>& embeddedCornellBox();

// The Cornell box scene (geometry, materials and camera) parsed from the embedded files.
Scene builtinCornellBox();

}  // namespace fp
