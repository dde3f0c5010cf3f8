#pragma once
// Runs a denoiser's GLSL passes (glsl/denoise/) over a Renderer's current accumulation on the GPU.
// The result stays in a texture of its own, so that a front end can display it (Display::draw shows
// it like an accumulation of one sample) or read it back; the accumulation is only read.
//
//   prepare   accumulation -> colour (divided by the albedo for atrous), its variance, guides
//   variance  atrous only: a spatial variance where a pixel has fewer than 4 samples
//   filter    bilateral: one pass; atrous: 5 iterations with taps 1, 2, 4, 8, 16 pixels apart
//   finish    multiply the albedo back: (radiance, 1)
#include <array>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "denoise/denoiser.h"
#include "gl/program.h"

namespace fp {

class DenoisePasses {
  public:
    // Needs a current GL context; compiles each pass when first needed.
    explicit DenoisePasses(ShaderLibrary shaders = ShaderLibrary());
    ~DenoisePasses();
    DenoisePasses(const DenoisePasses&) = delete;
    DenoisePasses& operator=(const DenoisePasses&) = delete;

    // Denoises the renderer's current accumulation with `which` (not None). Throws fp::Error if the
    // render has no guides (RenderSettings::guides) or a pass does not compile.
    void run(const Renderer& renderer, Denoiser which);
    // The prepare pass alone (what run() does first), and its output read back, rows top first:
    // (colour, divided by the albedo for atrous; luminance variance of its mean, or -1 below 4 samples).
    // For tests: what the filters are given.
    void prepare(const Renderer& renderer, Denoiser which);
    std::vector<glm::vec4> prepared() const;
    // The filter and finish passes alone, for a front end that prepares its own input (the real-time
    // pipeline, src/realtime/temporal_pipeline.h): `color` holds (demodulated colour, luminance variance
    // of its mean, or -1 to estimate it), `guide` and `modulate` what the prepare pass writes; none is
    // changed. `which` is not None. With `settled` (the real-time history: (mean, samples) per pixel) and
    // settledSamples > 0, pixels whose history holds at least that many samples pass through unfiltered:
    // their mean is already as clean as the filter would make it (glsl/denoise/unsettled.frag.glsl). The
    // stencil buffer keeps the variance and a-trous passes from shading them at all, which on a moving
    // camera is most of the filter's cost.
    void filter(GLuint color, GLuint guide, GLuint modulate, int width, int height, Denoiser which,
                GLuint settled = 0, float settledSamples = 0.0f);
    // The last result, (denoised radiance, 1) per pixel, at the accumulation's size.
    GLuint resultTexture() const { return textures_[kResult]; }
    Image result() const;  // rows top first
    // Recompiles from the library (hot reload); throws fp::Error and keeps the previous programs.
    void reloadShaders();

    static constexpr int kAtrousIterations = 5;  // Dammertz et al.: 5 levels cover a 61-pixel footprint

  private:
    enum Texture { kColorA, kColorB, kGuide, kAlbedo, kResult, kTextureCount };
    enum Pass { kPrepare, kVariance, kBilateral, kAtrous, kFinish, kUnsettled, kPassCount };
    void resize(int width, int height);
    Program& program(Pass pass);
    std::vector<glm::vec4> read(Texture texture) const;  // rows top first
    // Draws `pass` into framebuffer `target`, with `inputs` bound to units in order, named `names`.
    void draw(Pass pass, GLuint target, std::initializer_list<std::pair<const char*, GLuint>> inputs);
    // Copies `color` into both colour textures and leaves the stencil test on, passing only the pixels
    // whose history holds fewer than settledSamples samples.
    void shadeOnlyUnsettled(GLuint color, GLuint settled, float settledSamples);

    ShaderLibrary shaders_;
    std::array<std::unique_ptr<Program>, kPassCount> programs_;
    int width_ = 0, height_ = 0;
    std::array<GLuint, kTextureCount> textures_{};
    GLuint prepareFramebuffer_ = 0;                     // writes colour A, guide and albedo
    std::array<GLuint, kTextureCount> framebuffers_{};  // one per texture, for the other passes
    GLuint stencil_ = 0;          // renderbuffer shared by the colour A and B framebuffers
    GLuint copyFramebuffer_ = 0;  // reads the filter's input for shadeOnlyUnsettled
    GLuint vertexArray_ = 0;
};

}  // namespace fp
