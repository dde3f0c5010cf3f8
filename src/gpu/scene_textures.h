#pragma once
// The packed scene uploaded into buffer textures (layout in gpu/layout.h), bound to fixed units.
#include <array>

#include "gl/gl.h"
#include "gpu/pack.h"

namespace fp {

class SceneTextures {
  public:
    // Throws fp::Error if a buffer exceeds GL_MAX_TEXTURE_BUFFER_SIZE (or `maxTexels`, when given, to
    // check the message without a multi-gigabyte scene), before anything is uploaded.
    explicit SceneTextures(const PackedScene& scene, size_t maxTexels = 0);
    ~SceneTextures();
    SceneTextures(const SceneTextures&) = delete;
    SceneTextures& operator=(const SceneTextures&) = delete;

    // Binds every buffer texture to its unit (layout::Unit).
    void bind() const;

  private:
    static constexpr int kCount = 6;
    std::array<GLuint, kCount> buffers_{}, textures_{};
};

}  // namespace fp
