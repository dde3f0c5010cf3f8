#pragma once
// An environment map prepared for the GPU (layout in pack/layout.h): radiance texels scaled by the
// intensity, and the CDFs that importance-sample it by luminance times sin(theta), the solid angle a
// texel of an equirectangular map covers (pbrt-v4 section 12.5.2 samples image lights the same way).
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace fp {

struct PackedEnvironment {
    int width = 0, height = 0;
    std::vector<glm::vec4> texels;  // row y = 0 first (straight up)
    std::vector<float> cdf;         // H marginal entries, then H rows of W conditional entries
    double totalWeight = 0.0;       // 0: the map is black and cannot be sampled
};

PackedEnvironment packEnvironment(const Environment& environment);

}  // namespace fp
