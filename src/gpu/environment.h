#pragma once
// The environment map (pack/environment.h) uploaded: a 2D texture and a buffer texture of its CDFs.
#include <glm/glm.hpp>

#include "gl/gl.h"
#include "gpu/scene_textures.h"
#include "pack/environment.h"

namespace fp {

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
