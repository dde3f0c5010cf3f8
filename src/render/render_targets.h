#pragma once
// Two ping-pong framebuffers, each with kAttachments RGBA32F attachments (sums, squares, counters):
// a pass reads the current one and writes the other, then they swap.
#include <array>

#include "gl/gl.h"
#include "render/accumulation.h"

namespace fp {

class RenderTargets {
  public:
    // Throws fp::Error if the size exceeds the GL limits or the framebuffer is incomplete.
    RenderTargets(int width, int height);
    ~RenderTargets();
    RenderTargets(const RenderTargets&) = delete;
    RenderTargets& operator=(const RenderTargets&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    void clear();
    static constexpr int kAttachments = 3;
    // Binds the current targets' textures to units firstUnit .. firstUnit + kAttachments - 1, and the
    // other framebuffer for drawing.
    void beginPass(int firstUnit);
    void endPass() { current_ ^= 1; }
    Accumulation read() const;
    GLuint sumTexture() const { return textures_[size_t(current_)][0]; }

  private:
    int width_, height_;
    int current_ = 0;
    std::array<GLuint, 2> framebuffers_{};
    std::array<std::array<GLuint, kAttachments>, 2> textures_{};
};

}  // namespace fp
