#pragma once
// The packed scene uploaded into buffer textures (layout in gpu/layout.h), bound to fixed units.
#include <vector>

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

    // Binds every buffer texture to its unit (layout::Unit); the texture buffers only if the scene has any.
    void bind() const;

  private:
    std::vector<int> units_;  // per buffer: the layout::Unit it is bound to
    std::vector<GLuint> buffers_, textures_;
};

}  // namespace fp
