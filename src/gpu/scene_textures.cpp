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
    int unit;
};

}  // namespace

SceneTextures::SceneTextures(const PackedScene& s, size_t maxTexels) {
    // A zero-size buffer texture is not allowed; empty lists (no lights) get one unused texel.
    static const glm::vec4 kUnused(0.0f);
    auto spec = [](const char* name, const auto& v, GLenum format, int unit, size_t texelBytes = 0) {
        using T = typename std::decay_t<decltype(v)>::value_type;
        if (texelBytes == 0) texelBytes = sizeof(T);
        return BufferSpec{name,
                          v.empty() ? static_cast<const void*>(&kUnused) : v.data(),
                          v.empty() ? 1 : v.size() * sizeof(T) / texelBytes,
                          texelBytes,
                          format,
                          unit};
    };
    std::vector<BufferSpec> specs = {spec("triangles", s.triangles, GL_RGBA32F, layout::kTrianglesUnit),
                                     spec("normals", s.normals, GL_RGBA32F, layout::kNormalsUnit),
                                     spec("BVH nodes", s.nodes, GL_RGBA32UI, layout::kNodesUnit),
                                     spec("materials", s.materials, GL_RGBA32F, layout::kMaterialsUnit),
                                     spec("lights", s.lights, GL_RGBA32F, layout::kLightsUnit)};
    if (s.hasTextures()) {
        specs.push_back(spec("texture coordinates", s.texcoords, GL_RG32F, layout::kTexcoordsUnit));
        specs.push_back(spec("texture texels", s.textureTexels, GL_RGBA8, layout::kTextureTexelsUnit, 4));
        specs.push_back(spec("texture table", s.textureTable, GL_RGBA32I, layout::kTextureTableUnit));
    }

    if (maxTexels == 0) {
        GLint limit = 0;
        glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &limit);
        maxTexels = size_t(limit);
    }
    for (const BufferSpec& b : specs)
        if (b.texels > maxTexels)
            throw Error("scene too large for this GPU: the " + std::string(b.name) + " buffer needs " +
                        std::to_string(b.texels) + " texels, GL_MAX_TEXTURE_BUFFER_SIZE is " +
                        std::to_string(maxTexels) + " (" + std::to_string(s.triangleCount) + " triangles, " +
                        std::to_string(s.textureTable.size()) + " textures)");

    const size_t count = specs.size();
    buffers_.resize(count);
    textures_.resize(count);
    glGenBuffers(GLsizei(count), buffers_.data());
    glGenTextures(GLsizei(count), textures_.data());
    for (size_t i = 0; i < count; ++i) {
        const BufferSpec& b = specs[i];
        units_.push_back(b.unit);
        glBindBuffer(GL_TEXTURE_BUFFER, buffers_[i]);
        glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(b.texels * b.texelBytes), b.data, GL_STATIC_DRAW);
        if (glGetError() == GL_OUT_OF_MEMORY)
            throw Error("out of GPU memory uploading the " + std::string(b.name) + " buffer (" +
                        std::to_string(b.texels * b.texelBytes) + " bytes)");
        glActiveTexture(GLenum(GL_TEXTURE0 + b.unit));
        glBindTexture(GL_TEXTURE_BUFFER, textures_[i]);
        glTexBuffer(GL_TEXTURE_BUFFER, b.format, buffers_[i]);
    }
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kFirstFreeUnit));
}

SceneTextures::~SceneTextures() {
    glDeleteTextures(GLsizei(textures_.size()), textures_.data());
    glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
}

void SceneTextures::bind() const {
    for (size_t i = 0; i < textures_.size(); ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + units_[i]));
        glBindTexture(GL_TEXTURE_BUFFER, textures_[i]);
    }
    // Leave a spare unit active so that later texture creation cannot rebind a scene unit.
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kFirstFreeUnit));
}

}  // namespace fp
