#include "gpu/scene_textures.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "pack/layout.h"

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

// Why the context cannot read the scene as images, or "" when it can.
std::string imagesUnavailable() {
    if (!GLAD_GL_ARB_shader_image_load_store || !glBindImageTexture)
        return "the context lacks GL_ARB_shader_image_load_store";
    return imageUnitShortfall({glInteger(GL_MAX_IMAGE_UNITS), glInteger(GL_MAX_FRAGMENT_IMAGE_UNIFORMS),
                               glInteger(GL_MAX_COMBINED_IMAGE_UNITS_AND_FRAGMENT_OUTPUTS),
                               glInteger(GL_MAX_DRAW_BUFFERS)});
}

// Gives `buffer` (bound to GL_TEXTURE_BUFFER) its storage: `data` itself where `pin` and the driver
// accepts it, else a copy. Returns whether it is pinned.
bool uploadBuffer(GLuint buffer, const void* data, size_t bytes, bool pin) {
    constexpr uintptr_t kPage = 4096;
    if (pin && bytes >= kPage && reinterpret_cast<uintptr_t>(data) % kPage == 0) {
        glBindBuffer(GL_EXTERNAL_VIRTUAL_MEMORY_BUFFER_AMD, buffer);
        glBufferData(GL_EXTERNAL_VIRTUAL_MEMORY_BUFFER_AMD, GLsizeiptr(bytes), data, GL_STATIC_DRAW);
        glBindBuffer(GL_EXTERNAL_VIRTUAL_MEMORY_BUFFER_AMD, 0);
        glBindBuffer(GL_TEXTURE_BUFFER, buffer);
        if (glGetError() == GL_NO_ERROR) return true;
    }
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(bytes), data, GL_STATIC_DRAW);
    return false;
}

}  // namespace

bool pinnedUploadAllowed() {
    const char* forced = std::getenv("FRAGPATH_PINNED_UPLOAD");
    if (forced && std::string(forced) == "0") return false;
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string name = renderer ? renderer : "";
    return GLAD_GL_AMD_pinned_memory &&
           (name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos);
}

std::string imageUnitShortfall(const ImageUnitLimits& limits) {
    const int images = int(std::size(layout::kImageUnits));
    // Images share a budget with the fragment outputs; light tracing may use every draw buffer.
    if (limits.imageUnits < layout::kImageUnitsNeeded || limits.fragmentImages < images ||
        limits.combined < images + limits.drawBuffers)
        return "the context has too few image units for " + std::to_string(images) +
               " images (GL_MAX_IMAGE_UNITS " + std::to_string(limits.imageUnits) +
               ", GL_MAX_FRAGMENT_IMAGE_UNIFORMS " + std::to_string(limits.fragmentImages) +
               ", GL_MAX_COMBINED_IMAGE_UNITS_AND_FRAGMENT_OUTPUTS " + std::to_string(limits.combined) + ")";
    return "";
}

const char* sceneReadsName(SceneReads reads) {
    switch (reads) {
        case SceneReads::TexelFetch:
            return "texelFetch";
        case SceneReads::Images:
            return "imageLoad";
        case SceneReads::Auto:
            break;
    }
    return "auto";
}

SceneReads resolveSceneReads(SceneReads requested) {
    if (requested == SceneReads::TexelFetch) return requested;
    std::string reason = imagesUnavailable();
    if (requested == SceneReads::Images) {
        if (!reason.empty()) throw Error("cannot read the scene with imageLoad: " + reason);
        return requested;
    }
    const char* forced = std::getenv("FRAGPATH_SCENE_READS");
    if (forced && std::string(forced) == sceneReadsName(SceneReads::TexelFetch))
        return SceneReads::TexelFetch;
    if (forced && *forced && std::string(forced) != sceneReadsName(SceneReads::Auto))
        throw Error(std::string("FRAGPATH_SCENE_READS=") + forced + ": expected texelFetch or auto");
    return reason.empty() ? SceneReads::Images : SceneReads::TexelFetch;
}

SceneTextures::SceneTextures(PackedScene scene, size_t maxTexels) : scene_(std::move(scene)) {
    const PackedScene& s = scene_;
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
        if (!s.tangents.empty())
            specs.push_back(spec("tangents", s.tangents, GL_RGBA32F, layout::kTangentsUnit));
    }
    if (!s.colors.empty()) specs.push_back(spec("vertex colours", s.colors, GL_RGBA32F, layout::kColorsUnit));

    if (maxTexels == 0) maxTexels = size_t(glInteger(GL_MAX_TEXTURE_BUFFER_SIZE));
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
    const bool pin = pinnedUploadAllowed();
    for (int i = 0; i < 64 && glGetError() != GL_NO_ERROR; ++i) {
    }  // earlier errors cleared, so that one below is the upload's own
    for (size_t i = 0; i < count; ++i) {
        const BufferSpec& b = specs[i];
        units_.push_back(b.unit);
        formats_.push_back(b.format);
        glBindBuffer(GL_TEXTURE_BUFFER, buffers_[i]);
        if (uploadBuffer(buffers_[i], b.data, b.texels * b.texelBytes, pin))
            pinnedBytes_ += b.texels * b.texelBytes;
        else if (glGetError() == GL_OUT_OF_MEMORY)
            throw Error("out of GPU memory uploading the " + std::string(b.name) + " buffer (" +
                        std::to_string(b.texels * b.texelBytes) + " bytes)");
        glActiveTexture(GLenum(GL_TEXTURE0 + b.unit));
        glBindTexture(GL_TEXTURE_BUFFER, textures_[i]);
        glTexBuffer(GL_TEXTURE_BUFFER, b.format, buffers_[i]);
    }
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kFirstFreeUnit));
    if (pinnedBytes_ == 0) scene_ = PackedScene{};  // every buffer holds a copy
}

SceneTextures::~SceneTextures() {
    glDeleteTextures(GLsizei(textures_.size()), textures_.data());
    glDeleteBuffers(GLsizei(buffers_.size()), buffers_.data());
}

void bindSceneTexture(SceneReads reads, int unit, GLenum target, GLuint texture, GLenum format) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(target, texture);
    const auto* images = std::end(layout::kImageUnits);
    if (reads == SceneReads::Images && std::find(std::begin(layout::kImageUnits), images, unit) != images)
        glBindImageTexture(GLuint(unit), texture, 0, GL_FALSE, 0, GL_READ_ONLY, format);
    glActiveTexture(GLenum(GL_TEXTURE0 + layout::kFirstFreeUnit));
}

void SceneTextures::bind(SceneReads reads) const {
    for (size_t i = 0; i < textures_.size(); ++i)
        bindSceneTexture(reads, units_[i], GL_TEXTURE_BUFFER, textures_[i], formats_[i]);
}

}  // namespace fp
