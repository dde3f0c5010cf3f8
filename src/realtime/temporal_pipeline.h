#pragma once
// Real-time path tracing as practised since SVGF (Schied et al. 2017): a few samples per pixel each
// frame, reprojected history, and a variance-guided a-trous filter. After the renderer has traced a
// frame's samples into a fresh accumulation (with guides), run() reprojects the previous frame's
// history to this camera (glsl/realtime/temporal.frag.glsl), rejects it where the first hit's depth,
// normal or pixel class disagree (disocclusion), blends the new samples in, and filters the history's
// mean with the `atrous` denoiser driven by the history's temporal variance. Temporal anti-aliasing
// comes from the history itself: each frame's samples are jittered differently.
//
// The history is the mean radiance of every sample behind it, capped at maxHistorySamples only while
// the camera moves; beyond that many samples the image fades from the filtered history to its plain
// mean (glsl/realtime/output.frag.glsl), so a still camera converges to exactly the progressive image.
#include <array>
#include <memory>

#include "denoise/denoise_passes.h"
#include "gl/program.h"
#include "image/image.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace fp {

struct TemporalSettings {
    bool reuse = true;                   // off: every frame alone (still filtered, unless filter is None)
    Denoiser filter = Denoiser::Atrous;  // None: the history's mean, unfiltered
    float maxHistorySamples = 32.0f;     // per pixel, while the camera moves
    float minNormalCos = 0.9f;           // history whose first-hit normal turned further is rejected
    // Pixels whose history holds this many samples skip the filter (DenoisePasses::filter); 0: none do.
    // Measured on the Cornell orbit (BENCHMARKS.md, "Real time"): 16 lowers mean FLIP slightly (0.141
    // against 0.145: a long history's mean is clean, and filtering it only blurs), and since the stencil
    // keeps the filter's passes from shading them, the filter's time about 9-fold at 256x256.
    float settledSamples = 16.0f;
};

// What the pipeline can show instead of the image, for the classroom.
enum class RealtimeView { Image, HistoryLength, Deviation, Disocclusion };

struct TemporalTimings {
    double temporalSeconds = 0.0, filterSeconds = 0.0;  // each stage to glFinish
};

class TemporalPipeline {
  public:
    explicit TemporalPipeline(ShaderLibrary shaders = ShaderLibrary());
    ~TemporalPipeline();
    TemporalPipeline(const TemporalPipeline&) = delete;
    TemporalPipeline& operator=(const TemporalPipeline&) = delete;

    // One frame: the renderer's accumulation holds only this frame's samples, traced with `camera`
    // (its settings must have guides). Throws fp::Error without guides or when a pass does not compile.
    void run(const Renderer& renderer, const Camera& camera, const TemporalSettings& settings,
             RealtimeView view = RealtimeView::Image);
    // Forgets the history: the next frame starts afresh (a changed scene, or a jump of the camera).
    void reset() { frames_ = 0; }

    // The last frame's image (or debug view), (radiance, 1) per pixel: for a display pass.
    GLuint resultTexture() const { return outputTexture_; }
    Image result() const;  // rows top first
    // The history's mean radiance before filtering (rows top first), and its samples per pixel.
    Image historyMean() const;
    std::vector<float> historySamples() const;  // rows top first
    const TemporalTimings& timings() const { return timings_; }
    void reloadShaders();

  private:
    enum Target { kRadiance, kAlbedo, kMoments, kGuide, kFilter, kModulate, kTargetCount };
    void resize(int width, int height);
    Program& program(int which);
    std::vector<glm::vec4> read(GLuint framebuffer, int attachment) const;

    ShaderLibrary shaders_;
    DenoisePasses denoise_;
    std::array<std::unique_ptr<Program>, 2> programs_;  // temporal, output
    int width_ = 0, height_ = 0;
    // Two sets of targets: the frame writes one and reads the previous frame's from the other.
    std::array<std::array<GLuint, kTargetCount>, 2> textures_{};
    std::array<GLuint, 2> framebuffers_{};
    GLuint outputTexture_ = 0, outputFramebuffer_ = 0;  // the image or debug view
    int current_ = 0;                                   // the set the last frame wrote
    int frames_ = 0;                                    // frames in the history; 0: none
    Camera previousCamera_;
    TemporalTimings timings_;
    GLuint vertexArray_ = 0;
};

}  // namespace fp
