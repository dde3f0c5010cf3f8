#include "render/render_targets.h"

#include <algorithm>
#include <string>

#include "core/error.h"

namespace fp {

namespace {

// Makes the bound framebuffer's draw calls write every attachment, in order.
void drawAllAttachments() {
    std::array<GLenum, RenderTargets::kAttachments> buffers;
    for (int a = 0; a < RenderTargets::kAttachments; ++a)
        buffers[size_t(a)] = GLenum(GL_COLOR_ATTACHMENT0 + a);
    glDrawBuffers(RenderTargets::kAttachments, buffers.data());
}

}  // namespace

RenderTargets::RenderTargets(int width, int height) : width_(width), height_(height) {
    const GLint maxSize = glInteger(GL_MAX_TEXTURE_SIZE);
    if (width < 1 || height < 1 || width > maxSize || height > maxSize)
        throw Error("image size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is outside what this GPU supports (1 to " + std::to_string(maxSize) + " per side)");
    glGenFramebuffers(2, framebuffers_.data());
    for (int f = 0; f < 2; ++f) {
        glGenTextures(kAttachments, textures_[size_t(f)].data());
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_[size_t(f)]);
        for (int a = 0; a < kAttachments; ++a) {
            glBindTexture(GL_TEXTURE_2D, textures_[size_t(f)][size_t(a)]);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + a), GL_TEXTURE_2D,
                                   textures_[size_t(f)][size_t(a)], 0);
        }
        drawAllAttachments();
        GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            throw Error("float render targets are not supported here (framebuffer status 0x" +
                        std::to_string(status) + ")");
    }
    if (glGetError() == GL_OUT_OF_MEMORY)
        throw Error("out of GPU memory for " + std::to_string(width) + "x" + std::to_string(height) +
                    " render targets");
    clear();
}

RenderTargets::~RenderTargets() {
    for (auto& t : textures_) glDeleteTextures(kAttachments, t.data());
    glDeleteFramebuffers(2, framebuffers_.data());
}

void RenderTargets::clear() {
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (GLuint fb : framebuffers_) {
        glBindFramebuffer(GL_FRAMEBUFFER, fb);
        for (int a = 0; a < kAttachments; ++a) glClearBufferfv(GL_COLOR, a, zero);
    }
    current_ = 0;
}

void RenderTargets::beginPass(int firstUnit, const PixelRegion& region) {
    for (int a = 0; a < kAttachments; ++a) {
        glActiveTexture(GLenum(GL_TEXTURE0 + firstUnit + a));
        glBindTexture(GL_TEXTURE_2D, textures_[size_t(current_)][size_t(a)]);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_[size_t(current_ ^ 1)]);
    glViewport(0, 0, width_, height_);
    glEnable(GL_SCISSOR_TEST);
    glScissor(region.x, region.y, region.width, region.height);
}

void RenderTargets::endPass(const PixelRegion& region) {
    glDisable(GL_SCISSOR_TEST);
    if (region.x == 0 && region.y == 0 && region.width == width_ && region.height == height_) {
        current_ ^= 1;
        return;
    }
    // Only `region` of the written framebuffer is new: copy it into the current one, attachment by
    // attachment, so the current framebuffer stays complete.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers_[size_t(current_ ^ 1)]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffers_[size_t(current_)]);
    for (int a = 0; a < kAttachments; ++a) {
        std::array<GLenum, kAttachments> draw;
        draw.fill(GL_NONE);
        draw[size_t(a)] = GLenum(GL_COLOR_ATTACHMENT0 + a);
        glReadBuffer(draw[size_t(a)]);
        glDrawBuffers(kAttachments, draw.data());
        int x1 = region.x + region.width, y1 = region.y + region.height;
        glBlitFramebuffer(region.x, region.y, x1, y1, region.x, region.y, x1, y1, GL_COLOR_BUFFER_BIT,
                          GL_NEAREST);
    }
    drawAllAttachments();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RenderTargets::restore(const Image& mean, int samples) {
    clear();
    std::vector<glm::vec4> sums(size_t(width_) * size_t(height_));
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x)  // GL rows run bottom to top
            sums[size_t(height_ - 1 - y) * size_t(width_) + size_t(x)] =
                glm::vec4(mean.at(x, y) * float(samples), float(samples));
    glBindTexture(GL_TEXTURE_2D, textures_[size_t(current_)][0]);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGBA, GL_FLOAT, sums.data());
}

Accumulation RenderTargets::read() const {
    Accumulation acc;
    acc.width = width_;
    acc.height = height_;
    std::vector<glm::vec4>* outputs[kAttachments] = {&acc.sum, &acc.squares, &acc.counters, &acc.normalDepth,
                                                     &acc.albedo};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffers_[size_t(current_)]);
    std::vector<glm::vec4> rows(size_t(width_) * size_t(height_));
    for (int a = 0; a < kAttachments; ++a) {
        glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + a));
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rows.data());
        // GL rows run bottom to top; images here run top to bottom.
        std::vector<glm::vec4>& out = *outputs[a];
        out.resize(rows.size());
        for (int y = 0; y < height_; ++y)
            std::copy_n(&rows[size_t(height_ - 1 - y) * size_t(width_)], width_,
                        &out[size_t(y) * size_t(width_)]);
    }
    return acc;
}

}  // namespace fp
