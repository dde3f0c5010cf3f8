#include "render/light_splat.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "pack/layout.h"

namespace fp {

namespace {

void checkComplete(const char* what) {
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error(std::string(what) + " are not supported here (framebuffer status 0x" +
                    std::to_string(status) + ")");
}

void setNearest(GLenum target) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

}  // namespace

ShaderDefines LightSplat::defines() {
    return {{"LIGHT_RECORDS", std::to_string(kLightVertices)}};
}

LightSplat::LightSplat(const ShaderLibrary& shaders, int width, int height) : width_(width), height_(height) {
    splat_ = std::make_unique<Program>(shaders, "passes/light_splat.vert.glsl",
                                       "passes/light_splat.frag.glsl", defines());
    // The records: one layer per record, each layer a colour attachment of the trace pass.
    glGenTextures(1, &recordTexture_);
    glBindTexture(GL_TEXTURE_2D_ARRAY, recordTexture_);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, width, height, kRecords, 0, GL_RGBA, GL_FLOAT, nullptr);
    setNearest(GL_TEXTURE_2D_ARRAY);
    glGenFramebuffers(1, &recordFramebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, recordFramebuffer_);
    GLenum buffers[kRecords];
    for (int k = 0; k < kRecords; ++k) {
        buffers[k] = GLenum(GL_COLOR_ATTACHMENT0 + k);
        glFramebufferTextureLayer(GL_FRAMEBUFFER, buffers[k], recordTexture_, 0, k);
    }
    glDrawBuffers(kRecords, buffers);
    checkComplete("light-tracing records");

    glGenTextures(2, image_);
    glGenFramebuffers(1, &imageFramebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, imageFramebuffer_);
    for (int a = 0; a < 2; ++a) {
        glBindTexture(GL_TEXTURE_2D, image_[a]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
        setNearest(GL_TEXTURE_2D);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + a), GL_TEXTURE_2D, image_[a], 0);
    }
    const GLenum both[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, both);
    checkComplete("light images");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (glGetError() == GL_OUT_OF_MEMORY)
        throw Error("out of GPU memory for " + std::to_string(width) + "x" + std::to_string(height) +
                    " light-tracing targets");
    glGenVertexArrays(1, &vertexArray_);
    clear();
}

LightSplat::~LightSplat() {
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteFramebuffers(1, &imageFramebuffer_);
    glDeleteTextures(2, image_);
    glDeleteFramebuffers(1, &recordFramebuffer_);
    glDeleteTextures(1, &recordTexture_);
}

void LightSplat::clear() {
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glBindFramebuffer(GL_FRAMEBUFFER, imageFramebuffer_);
    for (int a = 0; a < 2; ++a) glClearBufferfv(GL_COLOR, a, zero);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// As launchSlotsPerRow in glsl/passes/light_launch.glsl: 4 slots per launching block a row can meet.
static int slotsPerRow(const PixelRegion& launch, int stride) {
    if (stride == 1) return launch.width;
    int blocks = ((launch.x + launch.width - 1) >> 2) - (launch.x >> 2) + 1;
    return 4 * ((blocks + stride - 1) / stride);
}

// The pixels of `launch` that launch a light path for sample `sampleIndex` (light_launch.glsl).
static int64_t launchingPixels(const PixelRegion& launch, int stride, uint32_t sampleIndex) {
    if (stride == 1) return int64_t(launch.width) * launch.height;
    int phase = int(sampleIndex % uint32_t(stride));
    int64_t count = 0;
    for (int y = launch.y; y < launch.y + launch.height; ++y)
        for (int b = launch.x >> 2; 4 * b < launch.x + launch.width; ++b)
            if ((b + (y >> 2) + phase) % stride == 0)
                count += std::min(4 * b + 4, launch.x + launch.width) - std::max(4 * b, launch.x);
    return count;
}

void LightSplat::trace(Program& tracer, uint32_t sampleIndex, const PixelRegion& launch,
                       const PixelRegion& splatRegion, Launch how) {
    if (launch.empty() || splatRegion.empty()) return;
    // No larger than the region's diagonals of blocks, so that every phase launches some block; a region
    // too narrow for the slots launches every pixel.
    int diagonals = ((launch.x + launch.width - 1) >> 2) - (launch.x >> 2) +
                    ((launch.y + launch.height - 1) >> 2) - (launch.y >> 2) + 1;
    how.stride = std::min(how.stride, diagonals);
    if (slotsPerRow(launch, how.stride) > width_) how.stride = 1;
    int64_t launching = launchingPixels(launch, how.stride, sampleIndex);
    int perRow = slotsPerRow(launch, how.stride);
    // Every pixel's light path has the same distribution, so the launching ones, each counted
    // (pixels / launching) times, estimate the light image of every pixel launching one: exactly, in
    // expectation, whatever the pattern, the tiling or the sample count.
    float weight = float(double(launch.width) * launch.height / double(launching));
    auto setLaunch = [&](Program& p) {
        p.set("uLightSample", unsigned(sampleIndex));
        p.set("uLaunchStride", how.stride);
        p.set("uLaunchOrigin", glm::ivec2(launch.x, launch.y));
        p.set("uLaunchWidth", launch.width);
    };
    // One fragment per slot (light_launch.glsl), in the records' lower-left corner; the trace pass writes
    // every record of every slot, so the records need no clearing.
    tracer.use();
    setLaunch(tracer);
    tracer.set("uLaunchWeight", weight);
    glBindFramebuffer(GL_FRAMEBUFFER, recordFramebuffer_);
    glViewport(0, 0, width_, height_);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, perRow, launch.height);
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    const int unit = layout::kFirstFreeUnit;
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D_ARRAY, recordTexture_);
    splat_->use();
    splat_->set("uRecords", unit);
    setLaunch(*splat_);
    splat_->set("uFirstRecord", how.firstRecord);
    glBindFramebuffer(GL_FRAMEBUFFER, imageFramebuffer_);
    glScissor(splatRegion.x, splatRegion.y, splatRegion.width, splatRegion.height);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glDrawArrays(GL_POINTS, 0, perRow * launch.height * (kRecords - how.firstRecord));
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void LightSplat::read(std::vector<glm::vec4>& sum, std::vector<glm::vec4>& squares) const {
    std::vector<glm::vec4>* outputs[2] = {&sum, &squares};
    std::vector<glm::vec4> rows(size_t(width_) * size_t(height_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, imageFramebuffer_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int a = 0; a < 2; ++a) {
        glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + a));
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rows.data());
        std::vector<glm::vec4>& out = *outputs[a];
        out.resize(rows.size());
        for (int y = 0; y < height_; ++y)  // GL rows run bottom to top
            std::copy_n(&rows[size_t(height_ - 1 - y) * size_t(width_)], width_,
                        &out[size_t(y) * size_t(width_)]);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

}  // namespace fp
