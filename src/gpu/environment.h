#pragma once
// An environment map prepared for the GPU (layout in gpu/layout.h): radiance texels scaled by the
// intensity, and the CDFs that importance-sample it by luminance times sin(theta), the solid angle a
// texel of an equirectangular map covers (pbrt-v4 section 12.5.2 samples image lights the same way).
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl.h"
#include "gpu/scene_textures.h"
#include "scene/scene.h"

namespace fp {

struct PackedEnvironment {
    int width = 0, height = 0;
    std::vector<glm::vec4> texels;  // row y = 0 first (straight up)
    std::vector<float> cdf;         // H marginal entries, then H rows of W conditional entries
    double totalWeight = 0.0;       // 0: the map is black and cannot be sampled
};

PackedEnvironment packEnvironment(const Environment& environment);

class EnvironmentTextures {
  public:
    // Throws fp::Error when the map exceeds the GPU's texture limits.
    explicit EnvironmentTextures(const PackedEnvironment& environment);
    ~EnvironmentTextures();
    EnvironmentTextures(const EnvironmentTextures&) = delete;
    EnvironmentTextures& operator=(const EnvironmentTextures&) = delete;
    // Binds the map and the CDFs to their units (layout::Unit) through bindSceneTexture.
    void bind(SceneReads reads) const;
    glm::ivec2 size() const { return size_; }  // of the map, in texels

  private:
    GLuint map_ = 0, cdfBuffer_ = 0, cdfTexture_ = 0;
    glm::ivec2 size_{0};
};

}  // namespace fp
