#include "gpu/scene_textures.h"

#include <string>

#include "core/error.h"
#include "gpu/layout.h"

namespace fp {

namespace {

struct BufferSpec {
    const char* name;
    const void* data;
    size_t texels;
    size_t texelBytes;
    GLenum format;
};

}  // namespace

SceneTextures::SceneTextures(const PackedScene& s, size_t maxTexels) {
    // A zero-size buffer texture is not allowed; empty lists (no lights) get one unused texel.
    static const glm::vec4 kUnused(0.0f);
    auto spec = [](const char* name, const auto& v, GLenum format) {
        using T = typename std::decay_t<decltype(v)>::value_type;
        return BufferSpec{name, v.empty() ? static_cast<const void*>(&kUnused) : v.data(),
                          v.empty() ? 1 : v.size(), sizeof(T), format};
    };
    const BufferSpec specs[kCount] = {
        spec("triangles", s.triangles, GL_RGBA32F),        spec("normals", s.normals, GL_RGBA32F),
        spec("BVH node bounds", s.nodeBounds, GL_RGBA32F), spec("BVH node links", s.nodeLinks, GL_RG32UI),
        spec("materials", s.materials, GL_RGBA32F),        spec("lights", s.lights, GL_RGBA32F)};

    if (maxTexels == 0) {
        GLint limit = 0;
        glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &limit);
        maxTexels = size_t(limit);
    }
    for (const BufferSpec& b : specs)
        if (b.texels > maxTexels)
            throw Error("scene too large for this GPU: the " + std::string(b.name) + " buffer needs " +
                        std::to_string(b.texels) + " texels, GL_MAX_TEXTURE_BUFFER_SIZE is " +
                        std::to_string(maxTexels) + " (" + std::to_string(s.triangleCount) + " triangles)");

    glGenBuffers(kCount, buffers_.data());
    glGenTextures(kCount, textures_.data());
    for (int i = 0; i < kCount; ++i) {
        const BufferSpec& b = specs[i];
        glBindBuffer(GL_TEXTURE_BUFFER, buffers_[size_t(i)]);
        glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(b.texels * b.texelBytes), b.data, GL_STATIC_DRAW);
        if (glGetError() == GL_OUT_OF_MEMORY)
            throw Error("out of GPU memory uploading the " + std::string(b.name) + " buffer (" +
                        std::to_string(b.texels * b.texelBytes) + " bytes)");
        glActiveTexture(GLenum(GL_TEXTURE0 + layout::kTrianglesUnit + i));
        glBindTexture(GL_TEXTURE_BUFFER, textures_[size_t(i)]);
        glTexBuffer(GL_TEXTURE_BUFFER, b.format, buffers_[size_t(i)]);
    }
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kFirstFreeUnit));
}

SceneTextures::~SceneTextures() {
    glDeleteTextures(kCount, textures_.data());
    glDeleteBuffers(kCount, buffers_.data());
}

void SceneTextures::bind() const {
    for (int i = 0; i < kCount; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + layout::kTrianglesUnit + i));
        glBindTexture(GL_TEXTURE_BUFFER, textures_[size_t(i)]);
    }
    // Leave a spare unit active so that later texture creation cannot rebind a scene unit.
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kFirstFreeUnit));
}

}  // namespace fp
