#pragma once
// MTL material libraries: only the Lambertian reflectance Kd and the emission Ke matter to us.
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace fp {

// tinyobjloader's MTL reader takes `Kd 0.14` as (0.14, 0, 0) where the MTL spec means grey, reads "nan"
// and "abc" as 0, keeps values outside [0, 1], and takes the name of `newmtl  x` (two blanks) as " x".
// This rewrites the newmtl, Kd and Ke statements so that it reads exactly what we mean, keeping line
// numbers, and warns once per kind of repair, naming `name` and the first line.
std::string sanitizeMtl(std::string_view text, const std::string& name);

// The materials of one MTL library, in file order (sanitized as above, then read by tinyobjloader).
// Never throws for bad content: problems in a library only cost materials, with warnings.
std::vector<Material> parseMtl(std::string_view text, const std::string& name);

}  // namespace fp
