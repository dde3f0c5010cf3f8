#include "render/display.h"

#include "pack/layout.h"

static_assert(int(fp::ToneMap::Clamp) == 0 && int(fp::ToneMap::Reinhard) == 1 && int(fp::ToneMap::Aces) == 2,
              "glsl/common/tone_map.glsl numbers the tone maps the same way");

namespace fp {

Display::Display(ShaderLibrary shaders) : shaders_(std::move(shaders)) {
    reloadShaders();
    glGenVertexArrays(1, &vertexArray_);
}

Display::~Display() {
    glDeleteVertexArrays(1, &vertexArray_);
}

void Display::reloadShaders() {
    program_ = std::make_unique<Program>(shaders_, "passes/fullscreen.vert.glsl", "passes/display.frag.glsl");
}

void Display::draw(const AccumulationTextures& image, int viewportWidth, int viewportHeight,
                   const DisplayOptions& options) {
    // Units the scene textures do not use, so drawing never disturbs the trace pass's bindings.
    const int unit = layout::kFirstFreeUnit + 7;
    bool splats = image.splatSum != 0 && image.lightPathsPerPixel > 0.0f;
    glActiveTexture(GLenum(GL_TEXTURE0 + unit + 1));
    glBindTexture(GL_TEXTURE_2D, splats ? image.splatSum : image.sum);  // unread without splats
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, image.sum);
    Program& p = *program_;
    p.use();
    p.set("uSum", unit);
    p.set("uSplatSum", unit + 1);
    p.set("uLightPaths", splats ? image.lightPathsPerPixel : 0.0f);
    p.set("uViewport", glm::vec2(viewportWidth, viewportHeight));
    p.set("uExposure", options.tone.exposure);
    p.set("uToneMap", int(options.tone.toneMap));
    p.set("uHeatMax", options.heatMax);
    p.set("uSplitLine", options.splitLine ? 1 : 0);
    glViewport(0, 0, viewportWidth, viewportHeight);
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace fp
