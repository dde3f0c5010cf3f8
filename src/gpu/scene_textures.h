#pragma once
// The packed scene uploaded into buffer textures (layout in pack/layout.h), bound to fixed units.
#include <string>
#include <vector>

#include "gl/gl.h"
#include "pack/pack.h"

namespace fp {

// How the trace shaders read the scene buffers and the environment map (glsl/common/scene_data.glsl).
// On llvmpipe, texelFetch of a buffer texture in any format but RGBA8 is an out-of-line call that makes
// LLVM spill everything live, while imageLoad of an image is generated inline (docs/optimisation-log.md,
// entries 18 and 23); both read the same texels, so the images are bit-identical.
enum class SceneReads {
    Auto,        // images where the context has them, else texel fetches (FRAGPATH_SCENE_READS may force)
    TexelFetch,  // samplerBuffer + texelFetch: plain OpenGL 4.1 (macOS)
    Images,      // readonly imageBuffer + imageLoad: GL_ARB_shader_image_load_store (core in 4.2)
};
const char* sceneReadsName(SceneReads reads);  // "texelFetch", "imageLoad" or "auto"

// Resolves `requested` for the current context. Auto: texelFetch when the environment variable
// FRAGPATH_SCENE_READS is "texelFetch" (for tests and benchmarks), else imageLoad when the context has
// GL_ARB_shader_image_load_store with enough image units for every texture layout::kImageUnits lists,
// else texelFetch. Images: throws fp::Error with the reason when the context cannot. Needs a current
// context.
SceneReads resolveSceneReads(SceneReads requested);

// The limits that decide whether a context can read the scene as images.
struct ImageUnitLimits {
    int imageUnits = 0;      // GL_MAX_IMAGE_UNITS
    int fragmentImages = 0;  // GL_MAX_FRAGMENT_IMAGE_UNIFORMS
    int combined = 0;        // GL_MAX_COMBINED_IMAGE_UNITS_AND_FRAGMENT_OUTPUTS
    int drawBuffers = 0;     // GL_MAX_DRAW_BUFFERS
};
// Why a context with these limits cannot have every texture that layout::kImageUnits lists bound as an
// image (all of them, whichever the scene has, so that the answer is the same for every scene), or ""
// when it can.
std::string imageUnitShortfall(const ImageUnitLimits& limits);

// Binds `texture` (a GL_TEXTURE_BUFFER or GL_TEXTURE_2D, `target`) to texture unit `unit`; with
// SceneReads::Images and a unit that layout::kImageUnits lists, also read-only, level 0, as `format`,
// to the image unit of the same number. Leaves a spare unit active, so that later texture creation
// cannot rebind a scene unit. Every scene texture is bound through this.
void bindSceneTexture(SceneReads reads, int unit, GLenum target, GLuint texture, GLenum format);

// Whether the scene's arrays may be the buffers' storage themselves (GL_AMD_pinned_memory): only when
// the context has the extension and renders on the CPU (llvmpipe, softpipe), whose "GPU memory" is this
// process's memory anyway; a discrete GPU would read pinned memory across the bus at every fetch.
// FRAGPATH_PINNED_UPLOAD=0 forbids it (to measure the copy). Needs a current context.
bool pinnedUploadAllowed();

class SceneTextures {
  public:
    // Takes the packed scene. Where pinnedUploadAllowed(), each array of at least a page that starts on
    // a page boundary (the large ones are HugePageVectors: 2 MiB-aligned) becomes its buffer's storage
    // in place: no copy, and none of the page faults of fresh buffer memory, which dominated a
    // million-triangle scene's upload (docs/optimisation-log.md, entry 37); so the scene lives
    // as long as the buffers. Elsewhere, or when the driver refuses, the buffer gets a copy, and the
    // scene's arrays are freed after the upload. Throws fp::Error if a buffer exceeds
    // GL_MAX_TEXTURE_BUFFER_SIZE (or `maxTexels`, when given, to check the message without a
    // multi-gigabyte scene), before anything is uploaded.
    explicit SceneTextures(PackedScene scene, size_t maxTexels = 0);
    ~SceneTextures();
    SceneTextures(const SceneTextures&) = delete;
    SceneTextures& operator=(const SceneTextures&) = delete;

    // Binds every buffer texture to its unit (layout::Unit), and to its image unit as bindSceneTexture
    // does; the texture buffers only if the scene has any.
    void bind(SceneReads reads) const;

    // Bytes of the scene the buffers read in place (0 when every buffer holds a copy).
    size_t pinnedBytes() const { return pinnedBytes_; }

  private:
    PackedScene scene_;  // the pinned buffers' storage; emptied when nothing is pinned
    size_t pinnedBytes_ = 0;
    std::vector<GLenum> formats_;
    std::vector<int> units_;  // per buffer: the layout::Unit it is bound to
    std::vector<GLuint> buffers_, textures_;
};

}  // namespace fp
