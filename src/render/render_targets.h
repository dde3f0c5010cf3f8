#pragma once
// The accumulation buffers: two framebuffers, each with kAttachments RGBA32F attachments (sums,
// squares, counters, and the first-hit guides of the denoisers). A pass reads the current one and writes the
// other. A full-frame pass then swaps them (ping-pong); a pass over a region (a tile, half of a split view)
// copies that region back instead, so regions can be rendered one at a time without copying the whole frame.
#include <array>

#include "gl/gl.h"
#include "render/accumulation.h"

namespace fp {

// Pixels [x, x + width) x [y, y + height), y counted from the bottom row as in GL.
struct PixelRegion {
    int x = 0, y = 0, width = 0, height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
};

// The attachments, in the order of the trace pass's outputs (glsl/passes/trace.frag.glsl says what each
// channel holds).
enum Attachment : int {
    kSumAttachment,
    kSquaresAttachment,
    kCountersAttachment,
    kNormalDepthAttachment,
    kAlbedoAttachment,
    kAttachmentCount
};

class RenderTargets {
  public:
    static constexpr int kAttachments = kAttachmentCount;

    // Throws fp::Error if the size exceeds the GL limits or the framebuffer is incomplete.
    RenderTargets(int width, int height);
    ~RenderTargets();
    RenderTargets(const RenderTargets&) = delete;
    RenderTargets& operator=(const RenderTargets&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    // GPU memory of both framebuffers' attachments: 2 x kAttachments RGBA32F texels per pixel.
    size_t bytes() const { return size_t(width_) * size_t(height_) * 2 * kAttachments * 16; }
    PixelRegion full() const { return {0, 0, width_, height_}; }
    void clear();
    // Binds the current textures to units firstUnit .. firstUnit + kAttachments - 1 and the other
    // framebuffer for drawing, restricted to `region`.
    void beginPass(int firstUnit, const PixelRegion& region);
    void endPass(const PixelRegion& region);
    Accumulation read() const;
    // Replaces the accumulation by `samples` samples whose per-pixel mean was `mean` (rows top first),
    // to resume a saved render. Sums of squares and guides are not saved, so they restart at zero.
    void restore(const Image& mean, int samples);
    // The current sums (radiance sum, sample count), for display.
    GLuint sumTexture() const { return texture(kSumAttachment); }
    // The current texture of any attachment (the denoisers read them all).
    GLuint texture(Attachment a) const { return textures_[size_t(current_)][size_t(a)]; }

  private:
    int width_, height_;
    int current_ = 0;
    std::array<GLuint, 2> framebuffers_{};
    std::array<std::array<GLuint, kAttachments>, 2> textures_{};
};

}  // namespace fp
