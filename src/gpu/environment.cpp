#include "gpu/environment.h"

#include <string>

#include "core/error.h"
#include "pack/layout.h"

namespace fp {

EnvironmentTextures::EnvironmentTextures(const PackedEnvironment& e) : size_(e.width, e.height) {
    const GLint maxSize = glInteger(GL_MAX_TEXTURE_SIZE), maxTexels = glInteger(GL_MAX_TEXTURE_BUFFER_SIZE);
    if (e.width > maxSize || e.height > maxSize || e.cdf.size() > size_t(maxTexels))
        throw Error("environment map " + std::to_string(e.width) + "x" + std::to_string(e.height) +
                    " is larger than this GPU's textures (" + std::to_string(maxSize) + " per side)");
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kEnvironmentMapUnit));
    glGenTextures(1, &map_);
    glBindTexture(GL_TEXTURE_2D, map_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, e.width, e.height, 0, GL_RGBA, GL_FLOAT, e.texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenBuffers(1, &cdfBuffer_);
    glBindBuffer(GL_TEXTURE_BUFFER, cdfBuffer_);
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(e.cdf.size() * sizeof(float)), e.cdf.data(), GL_STATIC_DRAW);
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kEnvironmentCdfUnit));
    glGenTextures(1, &cdfTexture_);
    glBindTexture(GL_TEXTURE_BUFFER, cdfTexture_);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_R32F, cdfBuffer_);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kFirstFreeUnit));
}

EnvironmentTextures::~EnvironmentTextures() {
    glDeleteTextures(1, &map_);
    glDeleteTextures(1, &cdfTexture_);
    glDeleteBuffers(1, &cdfBuffer_);
}

void EnvironmentTextures::bind(SceneReads reads) const {
    bindSceneTexture(reads, layout::kEnvironmentMapUnit, GL_TEXTURE_2D, map_, GL_RGBA32F);
    bindSceneTexture(reads, layout::kEnvironmentCdfUnit, GL_TEXTURE_BUFFER, cdfTexture_, GL_R32F);
}

}  // namespace fp
