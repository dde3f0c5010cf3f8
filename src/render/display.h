#pragma once
// The display pass: draws an accumulation into the bound framebuffer (a window, or an 8-bit target),
// tone-mapped like the PNG writer, or as a heat map for the count views.
#include <memory>

#include "gl/program.h"
#include "image/image.h"
#include "render/accumulation.h"

namespace fp {

struct DisplayOptions {
    DisplaySettings tone;    // exposure and tone curve
    float heatMax = 0.0f;    // > 0: heat map of the red channel from 0 to heatMax (count views)
    bool splitLine = false;  // a line down the middle, for the split view
};

class Display {
  public:
    explicit Display(ShaderLibrary shaders = ShaderLibrary());
    ~Display();
    // Draws the estimate of `image` (radiance sum / samples, plus bdpt's light image / N) over the whole
    // viewport of the bound draw framebuffer.
    void draw(const AccumulationTextures& image, int viewportWidth, int viewportHeight,
              const DisplayOptions& options);
    // Recompiles from the library; throws fp::Error and keeps the previous program.
    void reloadShaders();

  private:
    ShaderLibrary shaders_;
    std::unique_ptr<Program> program_;
    GLuint vertexArray_ = 0;
};

}  // namespace fp
