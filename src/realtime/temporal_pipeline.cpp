#include "realtime/temporal_pipeline.h"

#include "core/clock.h"
#include "core/error.h"
#include "pack/layout.h"

namespace fp {

namespace {

// Units above the denoisers' (denoise_passes.cpp), so that no binding the others rely on is disturbed.
constexpr int kFirstUnit = layout::kFirstFreeUnit + 16;
constexpr int kSpareUnit = kFirstUnit + 11;
const char* const kPassFiles[] = {"realtime/temporal.frag.glsl", "realtime/output.frag.glsl"};

void setCamera(Program& program, const char* eye, const char* forward, const char* right, const char* up,
               const Camera& camera, float aspect) {
    CameraFrame f = cameraFrame(camera, aspect);
    program.set(eye, f.eye);
    program.set(forward, f.forward);
    program.set(right, f.right);
    program.set(up, f.up);
}

bool sameCamera(const Camera& a, const Camera& b) {
    return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fovY == b.fovY;
}

GLuint floatTexture(int width, int height) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return texture;
}

}  // namespace

TemporalPipeline::TemporalPipeline(ShaderLibrary shaders) : shaders_(shaders), denoise_(std::move(shaders)) {
    glGenVertexArrays(1, &vertexArray_);
}

TemporalPipeline::~TemporalPipeline() {
    resize(0, 0);
    glDeleteVertexArrays(1, &vertexArray_);
}

Program& TemporalPipeline::program(int which) {
    std::unique_ptr<Program>& p = programs_[size_t(which)];
    if (!p) p = std::make_unique<Program>(shaders_, "passes/fullscreen.vert.glsl", kPassFiles[which]);
    return *p;
}

void TemporalPipeline::reloadShaders() {
    std::array<std::unique_ptr<Program>, 2> programs;
    for (size_t p = 0; p < programs.size(); ++p)
        programs[p] = std::make_unique<Program>(shaders_, "passes/fullscreen.vert.glsl", kPassFiles[p]);
    denoise_.reloadShaders();
    programs_ = std::move(programs);
}

void TemporalPipeline::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    if (width_ > 0) {
        for (auto& set : textures_) glDeleteTextures(kTargetCount, set.data());
        glDeleteFramebuffers(2, framebuffers_.data());
        glDeleteTextures(1, &outputTexture_);
        glDeleteFramebuffers(1, &outputFramebuffer_);
    }
    width_ = width;
    height_ = height;
    frames_ = 0;
    if (width == 0) return;
    glActiveTexture(GLenum(GL_TEXTURE0 + kSpareUnit));
    glGenFramebuffers(2, framebuffers_.data());
    std::array<GLenum, kTargetCount> buffers{};
    for (int t = 0; t < kTargetCount; ++t) buffers[size_t(t)] = GLenum(GL_COLOR_ATTACHMENT0 + t);
    for (size_t set = 0; set < 2; ++set) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_[set]);
        for (int t = 0; t < kTargetCount; ++t) {
            textures_[set][size_t(t)] = floatTexture(width, height);
            glFramebufferTexture2D(GL_FRAMEBUFFER, buffers[size_t(t)], GL_TEXTURE_2D,
                                   textures_[set][size_t(t)], 0);
        }
        glDrawBuffers(kTargetCount, buffers.data());
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Error("the real-time pipeline's float render targets are not supported here");
    }
    outputTexture_ = floatTexture(width, height);
    glGenFramebuffers(1, &outputFramebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, outputFramebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, outputTexture_, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void TemporalPipeline::run(const Renderer& renderer, const Camera& camera, const TemporalSettings& settings,
                           RealtimeView view) {
    const RenderSettings& rs = renderer.settings();
    if (!rs.guides) throw Error("real-time rendering needs the first-hit guides: RenderSettings::guides");
    resize(rs.width, rs.height);
    auto start = SteadyClock::now();
    const int previous = current_, next = 1 - current_;
    const float aspect = float(rs.width) / float(rs.height);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(vertexArray_);

    Program& temporal = program(0);
    temporal.use();
    AccumulationTextures image = renderer.textures();
    bool splats = image.splatSum != 0 && image.lightPathsPerPixel > 0.0f;
    const std::pair<const char*, GLuint> inputs[] = {
        {"uSum", renderer.accumulationTexture(kSumAttachment)},
        {"uCounters", renderer.accumulationTexture(kCountersAttachment)},
        {"uNormalDepth", renderer.accumulationTexture(kNormalDepthAttachment)},
        {"uAlbedoSum", renderer.accumulationTexture(kAlbedoAttachment)},
        {"uSplatSum", splats ? image.splatSum : image.sum},
        {"uPrevRadiance", textures_[size_t(previous)][kRadiance]},
        {"uPrevAlbedo", textures_[size_t(previous)][kAlbedo]},
        {"uPrevMoments", textures_[size_t(previous)][kMoments]},
        {"uPrevGuide", textures_[size_t(previous)][kGuide]}};
    int unit = kFirstUnit;
    for (const auto& [name, texture] : inputs) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(GL_TEXTURE_2D, texture);
        temporal.set(name, unit++);
    }
    temporal.set("uLightPaths", splats ? image.lightPathsPerPixel : 0.0f);
    setCamera(temporal, "uEye", "uForward", "uRight", "uUp", camera, aspect);
    const Camera& before = frames_ > 0 ? previousCamera_ : camera;
    setCamera(temporal, "uPrevEye", "uPrevForward", "uPrevRight", "uPrevUp", before, aspect);
    temporal.set("uResolution", glm::vec2(float(rs.width), float(rs.height)));
    temporal.set("uUseHistory", settings.reuse && frames_ > 0 ? 1 : 0);
    temporal.set("uCameraMoved", sameCamera(before, camera) ? 0 : 1);
    temporal.set("uMaxHistory", settings.maxHistorySamples);
    temporal.set("uMinNormalCos", settings.minNormalCos);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffers_[size_t(next)]);
    glViewport(0, 0, rs.width, rs.height);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
    timings_.temporalSeconds = secondsSince(start);
    current_ = next;
    frames_ = settings.reuse ? frames_ + 1 : 1;
    previousCamera_ = camera;

    start = SteadyClock::now();
    const auto& targets = textures_[size_t(current_)];
    if (settings.filter != Denoiser::None)
        denoise_.filter(targets[kFilter], targets[kGuide], targets[kModulate], rs.width, rs.height,
                        settings.filter, targets[kRadiance], settings.settledSamples);
    glFinish();
    timings_.filterSeconds = secondsSince(start);

    Program& output = program(1);
    output.use();
    const std::pair<const char*, GLuint> outputs[] = {{"uRadiance", targets[kRadiance]},
                                                      {"uMoments", targets[kMoments]},
                                                      {"uFilter", targets[kFilter]},
                                                      {"uFiltered", denoise_.resultTexture()}};
    unit = kFirstUnit;
    for (const auto& [name, texture] : outputs) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glBindTexture(GL_TEXTURE_2D, texture);
        output.set(name, unit++);
    }
    output.set("uUseFiltered", settings.filter != Denoiser::None ? 1 : 0);
    output.set("uMaxHistory", settings.maxHistorySamples);
    output.set("uSamplesPerFrame", float(std::max(1, renderer.samples())));
    output.set("uView", int(view));
    glBindFramebuffer(GL_FRAMEBUFFER, outputFramebuffer_);
    glViewport(0, 0, rs.width, rs.height);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glActiveTexture(GLenum(GL_TEXTURE0 + kSpareUnit));
}

std::vector<glm::vec4> TemporalPipeline::read(GLuint framebuffer, int attachment) const {
    std::vector<glm::vec4> rows(size_t(width_) * size_t(height_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + attachment));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rows.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    // GL rows run bottom to top; images here run top to bottom.
    std::vector<glm::vec4> flipped(rows.size());
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x)
            flipped[size_t(y) * size_t(width_) + size_t(x)] =
                rows[size_t(height_ - 1 - y) * size_t(width_) + size_t(x)];
    return flipped;
}

Image TemporalPipeline::result() const {
    std::vector<glm::vec4> rows = read(outputFramebuffer_, 0);
    Image image(width_, height_);
    for (size_t i = 0; i < rows.size(); ++i) image.pixels[i] = glm::vec3(rows[i]);
    return image;
}

Image TemporalPipeline::historyMean() const {
    std::vector<glm::vec4> rows = read(framebuffers_[size_t(current_)], kRadiance);
    Image image(width_, height_);
    for (size_t i = 0; i < rows.size(); ++i) image.pixels[i] = glm::vec3(rows[i]);
    return image;
}

std::vector<float> TemporalPipeline::historySamples() const {
    std::vector<glm::vec4> rows = read(framebuffers_[size_t(current_)], kRadiance);
    std::vector<float> samples(rows.size());
    for (size_t i = 0; i < rows.size(); ++i) samples[i] = rows[i].a;
    return samples;
}

}  // namespace fp
