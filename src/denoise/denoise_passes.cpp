#include "denoise/denoise_passes.h"

#include <algorithm>

#include "core/error.h"
#include "pack/layout.h"

namespace fp {

namespace {

// Units above the renderer's (scene buffers, accumulation) and the display pass's, so that denoising
// disturbs no binding the trace pass relies on.
constexpr int kFirstUnit = layout::kFirstFreeUnit + 8;
constexpr int kSpareUnit = kFirstUnit + 7;

const char* const kPassFiles[] = {"denoise/prepare.frag.glsl",   "denoise/variance.frag.glsl",
                                  "denoise/bilateral.frag.glsl", "denoise/atrous.frag.glsl",
                                  "denoise/finish.frag.glsl",    "denoise/unsettled.frag.glsl"};

}  // namespace

DenoisePasses::DenoisePasses(ShaderLibrary shaders) : shaders_(std::move(shaders)) {
    glGenVertexArrays(1, &vertexArray_);
}

DenoisePasses::~DenoisePasses() {
    resize(0, 0);
    glDeleteVertexArrays(1, &vertexArray_);
}

void DenoisePasses::reloadShaders() {
    std::array<std::unique_ptr<Program>, kPassCount> programs;
    for (int p = 0; p < kPassCount; ++p)
        if (programs_[size_t(p)])
            programs[size_t(p)] =
                std::make_unique<Program>(shaders_, "passes/fullscreen.vert.glsl", kPassFiles[p]);
    for (int p = 0; p < kPassCount; ++p)  // only once all compiled
        if (programs[size_t(p)]) programs_[size_t(p)] = std::move(programs[size_t(p)]);
}

Program& DenoisePasses::program(Pass pass) {
    std::unique_ptr<Program>& p = programs_[size_t(pass)];
    if (!p) p = std::make_unique<Program>(shaders_, "passes/fullscreen.vert.glsl", kPassFiles[pass]);
    return *p;
}

void DenoisePasses::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    if (width_ > 0) {
        glDeleteFramebuffers(1, &prepareFramebuffer_);
        glDeleteFramebuffers(kTextureCount, framebuffers_.data());
        glDeleteTextures(kTextureCount, textures_.data());
        glDeleteRenderbuffers(1, &stencil_);
        glDeleteFramebuffers(1, &copyFramebuffer_);
    }
    width_ = width;
    height_ = height;
    if (width == 0) return;
    glActiveTexture(GLenum(GL_TEXTURE0 + kSpareUnit));  // never rebind a unit someone else uses
    glGenTextures(kTextureCount, textures_.data());
    glGenFramebuffers(kTextureCount, framebuffers_.data());
    for (int t = 0; t < kTextureCount; ++t) {
        glBindTexture(GL_TEXTURE_2D, textures_[size_t(t)]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_[size_t(t)]);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, textures_[size_t(t)], 0);
    }
    glGenFramebuffers(1, &copyFramebuffer_);
    glGenRenderbuffers(1, &stencil_);
    glBindRenderbuffer(GL_RENDERBUFFER, stencil_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    for (Texture t : {kColorA, kColorB}) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_[t]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, stencil_);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Error("the denoiser's float render targets with a stencil buffer are not supported here");
    }
    glGenFramebuffers(1, &prepareFramebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, prepareFramebuffer_);
    const GLuint outputs[] = {textures_[kColorA], textures_[kGuide], textures_[kAlbedo]};
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    for (int a = 0; a < 3; ++a)
        glFramebufferTexture2D(GL_FRAMEBUFFER, buffers[a], GL_TEXTURE_2D, outputs[a], 0);
    glDrawBuffers(3, buffers);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("the denoiser's float render targets are not supported here");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void DenoisePasses::draw(Pass pass, GLuint target,
                         std::initializer_list<std::pair<const char*, GLuint>> inputs) {
    Program& p = program(pass);
    p.use();
    int unit = kFirstUnit;
    for (const auto& [name, texture] : inputs) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(GL_TEXTURE_2D, texture);
        p.set(name, unit++);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, width_, height_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void DenoisePasses::run(const Renderer& renderer, Denoiser which) {
    prepare(renderer, which);
    filter(textures_[kColorA], textures_[kGuide], textures_[kAlbedo], width_, height_, which);
}

void DenoisePasses::prepare(const Renderer& renderer, Denoiser which) {
    if (which == Denoiser::None) throw Error("internal: DenoisePasses::prepare with no denoiser");
    if (!renderer.settings().guides)
        throw Error(std::string("the ") + denoiserName(which) +
                    " denoiser needs the first-hit guides: render with RenderSettings::guides set");
    resize(renderer.settings().width, renderer.settings().height);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(vertexArray_);

    program(kPrepare).use();
    program(kPrepare).set("uDemodulate", which == Denoiser::Atrous ? 1 : 0);
    AccumulationTextures image = renderer.textures();
    bool splats = image.splatSum != 0 && image.lightPathsPerPixel > 0.0f;
    program(kPrepare).set("uLightPaths", splats ? image.lightPathsPerPixel : 0.0f);
    draw(kPrepare, prepareFramebuffer_,
         {{"uSum", renderer.accumulationTexture(kSumAttachment)},
          {"uSquares", renderer.accumulationTexture(kSquaresAttachment)},
          {"uCounters", renderer.accumulationTexture(kCountersAttachment)},
          {"uNormalDepth", renderer.accumulationTexture(kNormalDepthAttachment)},
          {"uAlbedoSum", renderer.accumulationTexture(kAlbedoAttachment)},
          {"uSplatSum", splats ? image.splatSum : image.sum},
          {"uSplatSquares", splats ? image.splatSquares : image.sum}});  // unread without splats
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glActiveTexture(GLenum(GL_TEXTURE0 + kSpareUnit));
}

void DenoisePasses::filter(GLuint color, GLuint guide, GLuint modulate, int width, int height, Denoiser which,
                           GLuint settled, float settledSamples) {
    if (which == Denoiser::None) throw Error("internal: DenoisePasses::filter with no denoiser");
    resize(width, height);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);  // colours A and B have a depth-stencil buffer, for the stencil alone
    glBindVertexArray(vertexArray_);
    // The first pass reads `color`, the others ping-pong between colours A and B (B first, so that
    // `color` may be colour A).
    GLuint current = color;
    Texture next = kColorB;
    if (settled && settledSamples > 0.0f) shadeOnlyUnsettled(color, settled, settledSamples);
    auto pass = [&](Pass p) {
        draw(p, framebuffers_[next], {{"uColor", current}, {"uGuide", guide}});
        current = textures_[next];
        next = next == kColorA ? kColorB : kColorA;
    };
    if (which == Denoiser::Bilateral) {
        pass(kBilateral);
    } else {
        pass(kVariance);
        for (int i = 0; i < kAtrousIterations; ++i) {
            program(kAtrous).use();
            program(kAtrous).set("uStep", 1 << i);
            pass(kAtrous);
        }
    }
    glDisable(GL_STENCIL_TEST);
    draw(kFinish, framebuffers_[kResult], {{"uColor", current}, {"uAlbedo", modulate}});
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glActiveTexture(GLenum(GL_TEXTURE0 + kSpareUnit));
}

void DenoisePasses::shadeOnlyUnsettled(GLuint color, GLuint settled, float settledSamples) {
    // A pass-through pixel is never written: both colour textures hold its input from the start.
    if (color == textures_[kColorA] || color == textures_[kColorB])
        throw Error("internal: DenoisePasses::filter passes pixels through only from an input of its own");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, copyFramebuffer_);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    for (Texture t : {kColorA, kColorB}) {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffers_[t]);
        glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_[kColorA]);
    glStencilMask(0xff);  // glClear writes only the bits the mask lets through
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    program(kUnsettled).use();
    program(kUnsettled).set("uSettledSamples", settledSamples);
    draw(kUnsettled, framebuffers_[kColorA], {{"uSettled", settled}});
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
}

std::vector<glm::vec4> DenoisePasses::read(Texture texture) const {
    std::vector<glm::vec4> rows(size_t(width_) * size_t(height_)), pixels(rows.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers_[texture]);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rows.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    for (int y = 0; y < height_; ++y)  // GL rows run bottom to top; images here run top to bottom
        std::copy_n(rows.begin() + std::ptrdiff_t(height_ - 1 - y) * width_, width_,
                    pixels.begin() + std::ptrdiff_t(y) * width_);
    return pixels;
}

std::vector<glm::vec4> DenoisePasses::prepared() const {
    return read(kColorA);
}

Image DenoisePasses::result() const {
    Image image(width_, height_);
    std::vector<glm::vec4> pixels = read(kResult);
    for (size_t i = 0; i < pixels.size(); ++i) image.pixels[i] = glm::vec3(pixels[i]);
    return image;
}

}  // namespace fp
