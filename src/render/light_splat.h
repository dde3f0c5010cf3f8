#pragma once
// The light-tracing pass of bdpt (strategies t = 1, glsl/integrators/bdpt.glsl) and of nee's caustics
// (--caustics light, glsl/integrators/nee.glsl): light paths traced in a fragment pass
// (glsl/passes/light_trace.frag.glsl, one path per launching pixel) write one record per
// light vertex (its weighted contribution and the pixel it lands on); a point pass
// (light_splat.*.glsl) adds the records with additive blending into the light image, two RGBA32F
// attachments: (sum of contributions, rays traced by the paths launched at the pixel) and (sum of
// squared contributions, non-finite contributions dropped).
//
// Why a fragment pass plus a point pass rather than tracing in a vertex or geometry shader: llvmpipe
// shades fragments on all its threads but runs vertex and geometry shaders in the calling thread, so
// tracing belongs in the fragment stage; the point pass only moves records.
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "gl/program.h"
#include "render/render_targets.h"

namespace fp {

class LightSplat {
  public:
    // Light vertices per path, one record each: the shaders' LIGHT_RECORDS (the renderer passes it to
    // every program, so the two cannot differ). bdpt's light subpaths have 4 (bdpt_subpaths.glsl); nee's
    // caustic light paths two more, so that light through a glass ball can bounce twice past the floor.
    static constexpr int kLightVertices = 6;

    // Throws fp::Error if the splat program does not compile or the targets are incomplete.
    LightSplat(const ShaderLibrary& shaders, int width, int height);
    ~LightSplat();
    LightSplat(const LightSplat&) = delete;
    LightSplat& operator=(const LightSplat&) = delete;

    static ShaderDefines defines();
    int width() const { return width_; }
    int height() const { return height_; }
    // GPU memory of the records (kRecords RGBA32F layers) and the light image (2 RGBA32F attachments).
    size_t bytes() const { return size_t(width_) * size_t(height_) * (kRecords + 2) * 16; }
    void clear();
    // Which pixels launch light paths and which records they fill: every pixel and every record for
    // bdpt; for nee's caustics one pixel in `stride` (light_trace.frag.glsl's launches()), whose
    // records before `firstRecord` are always empty and are not drawn.
    struct Launch {
        int stride = 1;
        int firstRecord = 0;
    };
    // Traces one light path from each launching pixel of `launch` with `tracer` (light_trace.frag.glsl,
    // bound and with every uniform set but uLightSample and uLaunchStride) for sample index
    // `sampleIndex`, and adds the records that land inside `splatRegion` to the light image.
    void trace(Program& tracer, uint32_t sampleIndex, const PixelRegion& launch,
               const PixelRegion& splatRegion, Launch how);
    // The light image, rows top to bottom.
    void read(std::vector<glm::vec4>& sum, std::vector<glm::vec4>& squares) const;
    GLuint sumTexture() const { return image_[0]; }
    GLuint squaresTexture() const { return image_[1]; }

  private:
    static constexpr int kRecords = kLightVertices + 1;  // the vertices' records, then the statistics
    int width_, height_;
    std::unique_ptr<Program> splat_;
    GLuint recordTexture_ = 0, recordFramebuffer_ = 0;
    GLuint image_[2] = {0, 0};
    GLuint imageFramebuffer_ = 0;
    GLuint vertexArray_ = 0;
};

}  // namespace fp
