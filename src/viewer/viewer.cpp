#include "viewer/viewer.h"

// clang-format off
#include "gl/glfw_window.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
// clang-format on

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/clock.h"
#include "core/error.h"
#include "denoise/denoise_passes.h"
#include "realtime/frame_budget.h"
#include "realtime/temporal_pipeline.h"
#include "render/display.h"
#include "render/renderer.h"
#include "scene/punctual_light.h"
#include "viewer/accumulation_policy.h"
#include "viewer/camera_controller.h"
#include "viewer/camera_input.h"
#include "viewer/focus_picker.h"
#include "viewer/frame_stats.h"
#include "viewer/imgui_layer.h"
#include "viewer/panel.h"
#include "viewer/screenshot.h"
#include "viewer/shader_watcher.h"
#include "viewer/tile_planner.h"

namespace fp {

namespace {

// The longest a restart may keep the previous picture on screen, so the panel never freezes for long.
constexpr double kMaxHoldSeconds = 1.0;
// Frames should take about this long (25 per second); rendering gets what drawing the window leaves,
// within these bounds.
constexpr double kTargetFrameSeconds = 0.040;
constexpr double kMinBudgetSeconds = 0.010, kMaxBudgetSeconds = 0.033;

double now() {
    static const auto start = SteadyClock::now();
    return secondsSince(start);
}

class Session {
  public:
    Session(const Scene& scene, const ViewerOptions& options);
    void run();

  private:
    void handleKeys();
    void handleCamera(double dt);
    void setFlying(bool flying);
    void focusAt(glm::dvec2 cursor, glm::ivec2 windowSize);
    void applyActions(const PanelActions& actions);
    PanelInfo panelInfo() const;
    void reloadShadersIfChanged(double t);
    void restart(const RenderSettings& settings, bool reduced);
    float movingScale(glm::ivec2 framebuffer) const;
    void renderWithinBudget(bool stopAtPassEnd);
    void fitHeatMapIfDue();
    DisplayOptions displayOptions() const;
    bool showsDenoised() const;
    GLuint shownTexture(bool current = false);
    Image shownImage();
    void present(glm::ivec2 framebuffer);
    void screenshotKey();
    void reportError(const std::string& message);
    bool targetReached() const {
        return controls_.targetSpp > 0 && renderer_.samples() >= controls_.targetSpp;
    }
    // No pass in progress, and at least one done: every pixel has the same number of samples.
    bool wholePasses() const { return renderer_.samples() >= 1 && tile_ == 0; }
    // When --frames run out mid-pass, the automation goes on until the pass is complete, so that what
    // it saves at exit holds whole passes (issue 17: a screenshot with a black band, "0 spp").
    bool automationDone(int frames) const {
        if (controls_.realtime)
            return options_.frames > 0 && frames >= options_.frames && realtimeFrames_ > 0;
        return options_.frames > 0 && frames >= options_.frames &&
               (controls_.targetSpp == 0 || renderer_.samples() >= controls_.targetSpp) && wholePasses();
    }
    void printTiming() const;
    // Real-time mode: one frame's samples at the current camera through the temporal pipeline.
    TemporalSettings temporalSettings() const;
    bool realtimeFrame(glm::ivec2 framebuffer);
    bool progressiveFrame(glm::ivec2 framebuffer, bool automatedSamples, double start, int frames);
    void leaveRealtime();
    bool showsRealtime() const { return controls_.realtime && pipeline_ && realtimeFrames_ > 0; }

    const ViewerOptions& options_;
    GlfwWindow window_;  // first: everything below needs its GL context
    std::string description_;
    Renderer renderer_;
    Display display_;
    DenoisePasses denoiser_;
    std::unique_ptr<ImGuiLayer> ui_;
    Panel panel_;
    std::optional<ShaderWatcher> watcher_;
    ViewerControls controls_;
    CameraController camera_;
    CameraInput input_;
    FocusPicker picker_;
    AccumulationPolicy policy_;
    TilePlanner planner_;
    FrameStats stats_;

    RenderSettings lastGood_;  // the settings of the last configure() that succeeded
    bool configured_ = false;
    bool reduced_ = false;
    int tile_ = 0;  // tile size of the pass in progress; 0 before a pass starts
    double restartTime_ = 0.0;
    bool completeShown_ = false;  // the window shows an image with at least one whole pass
    double framePaths_ = 0.0;
    double frameRenderSeconds_ = 0.0;
    double overheadSeconds_ = 0.005;  // per frame, everything but rendering (events, panel, display, swap)
    int denoisedSamples_ = -1;        // the sample count the denoiser's result is of; -1: none is current
    double denoiseSeconds_ = 0.0, denoisedAt_ = 0.0;
    double frameDenoiseSeconds_ = 0.0;  // not part of the per-frame overhead: it happens now and then
    bool heatFitDue_ = true, heatFitRequested_ = false;
    std::string shaderError_, message_;
    std::vector<std::string> lights_;  // the scene's punctual lights, for the panel

    // Real-time mode. The pipeline is made when the mode is first entered (progressive mode never
    // touches it); its history is kept across camera motion and reset when anything else changes.
    std::unique_ptr<TemporalPipeline> pipeline_;
    RenderSettings realtimeSettings_;  // the last frame's, sampleOffset and samplesPerPass aside
    bool realtimeWasOn_ = false;
    int realtimeSpp_ = 1;
    uint32_t sampleOffset_ = 0;  // the next frame's first sample index: every frame gets new samples
    int realtimeFrames_ = 0;     // frames since the last reset
    double traceMs_ = 0.0;
    int traceSpp_ = 0;  // the samples per pixel of the last frame, which traceMs_ is the time of
    double realtimeOverheadMs_ = 5.0;  // per frame, everything but tracing (pipeline, panel, display, swap)
    // The first frames after a reset compile shaders and warm caches: their time says nothing of the
    // budget, and dropping the resolution on them would also drop the history.
    static constexpr int kWarmUpFrames = 2;
    float realtimeScale_ = 1.0f;  // dynamic resolution: a share of the resolution scale (frame_budget.h)
};

Session::Session(const Scene& scene, const ViewerOptions& options)
    : options_(options),
      window_(options.windowSize.x, options.windowSize.y, "fragpath - " + scene.source),
      description_(window_.description()),
      renderer_(scene, ShaderLibrary(options.shaderDir), layout::bvhOptions(options.bvhThreads)),
      display_(ShaderLibrary(options.shaderDir)),
      denoiser_(ShaderLibrary(options.shaderDir)),
      controls_(options.controls),
      camera_(options.camera),
      picker_(scene, options.bvhThreads) {
    if (options.ui) ui_ = std::make_unique<ImGuiLayer>(window_.handle());
    if (!options.shaderDir.empty()) watcher_.emplace(options.shaderDir);
    for (const PunctualLight& light : scene.punctualLights) lights_.push_back(describePunctualLight(light));
}

void Session::reportError(const std::string& message) {
    if (message == shaderError_) return;  // once, not every frame it persists
    shaderError_ = message;
    std::fprintf(stderr, "fragpath: error: %s\n", message.c_str());
}

void Session::setFlying(bool flying) {
    input_.setFlying(flying);
    window_.setCursorCaptured(flying);
    if (ui_) ui_->setMouseEnabled(!flying);
}

void Session::handleKeys() {
    bool uiHasKeyboard = ui_ && ui_->wantsKeyboard();
    for (int key : window_.takeKeyPresses()) {
        if (uiHasKeyboard) continue;
        switch (key) {
            case GLFW_KEY_F:
                setFlying(!input_.flying());
                break;
            case GLFW_KEY_ESCAPE:
                if (input_.flying()) setFlying(false);
                break;
            case GLFW_KEY_R:
                camera_.reset();
                break;
            case GLFW_KEY_P:
                screenshotKey();
                break;
            case GLFW_KEY_H:
                controls_.showPanel = !controls_.showPanel;
                break;
            case GLFW_KEY_N:
                controls_.showDenoised = !controls_.showDenoised;
                break;
            default:
                break;
        }
    }
}

void Session::handleCamera(double dt) {
    GLFWwindow* w = window_.handle();
    auto key = [w](int k) { return glfwGetKey(w, k) == GLFW_PRESS; };
    auto button = [w](int b) { return glfwGetMouseButton(w, b) == GLFW_PRESS; };
    InputFrame in;
    glfwGetCursorPos(w, &in.cursor.x, &in.cursor.y);
    in.left = button(GLFW_MOUSE_BUTTON_LEFT);
    in.middle = button(GLFW_MOUSE_BUTTON_MIDDLE);
    in.right = button(GLFW_MOUSE_BUTTON_RIGHT);
    in.shift = key(GLFW_KEY_LEFT_SHIFT) || key(GLFW_KEY_RIGHT_SHIFT);
    in.ctrl = key(GLFW_KEY_LEFT_CONTROL) || key(GLFW_KEY_RIGHT_CONTROL);
    in.forward = key(GLFW_KEY_W);
    in.back = key(GLFW_KEY_S);
    in.strafeLeft = key(GLFW_KEY_A);
    in.strafeRight = key(GLFW_KEY_D);
    in.down = key(GLFW_KEY_Q);
    in.up = key(GLFW_KEY_E);
    in.scroll = window_.takeScroll();
    in.uiWantsMouse = ui_ && ui_->wantsMouse();
    in.uiWantsKeyboard = ui_ && ui_->wantsKeyboard();
    in.dt = std::min(dt, 0.1);  // a stalled frame (a shader compile) must not fling the camera
    in.windowSize = window_.windowSize();
    input_.update(in, camera_);
    if (input_.focusClick()) focusAt(*input_.focusClick(), in.windowSize);
}

// Click to focus: the plane of focus through the surface under the cursor (the accumulation has the
// window's aspect ratio, whatever its resolution).
void Session::focusAt(glm::dvec2 cursor, glm::ivec2 windowSize) {
    const RenderSettings& s = renderer_.settings();
    std::optional<float> depth = picker_.focusDistanceAt(camera_.camera(), float(s.width) / float(s.height),
                                                         cursorToNdc(cursor, windowSize));
    char text[160];
    if (!depth) {
        std::snprintf(text, sizeof text, "focus: nothing under the cursor");
    } else {
        camera_.setFocusDistance(*depth);
        std::snprintf(text, sizeof text, "focus distance %.4g%s", double(*depth),
                      camera_.camera().aperture > 0.0f ? "" : " (aperture 0: everything is sharp)");
    }
    message_ = text;
    std::printf("%s\n", text);
    std::fflush(stdout);
}

void Session::applyActions(const PanelActions& actions) {
    if (actions.resetCamera) camera_.reset();
    if (actions.toggleFly) setFlying(!input_.flying());
    if (actions.fov) camera_.setFov(*actions.fov);
    if (actions.aperture) camera_.setAperture(*actions.aperture);
    if (actions.focusDistance) camera_.setFocusDistance(*actions.focusDistance);
    if (actions.focusOnTarget) camera_.setFocusDistance(std::nullopt);
    if (actions.fitHeatMap) heatFitRequested_ = true;
    if (actions.screenshot) screenshotKey();
}

PanelInfo Session::panelInfo() const {
    PanelInfo info;
    info.samples = renderer_.samples();
    info.accumulation = {renderer_.settings().width, renderer_.settings().height};
    info.reduced = reduced_;
    info.samplesPerSecond = stats_.samplesPerSecond();
    info.pathsPerSecond = stats_.pathsPerSecond();
    info.frameMs = 1000.0 * stats_.frameSeconds();
    info.denoiseMs = showsDenoised() ? 1000.0 * denoiseSeconds_ : 0.0;
    info.renderer = description_;
    info.shaderSource = options_.shaderDir.empty()
                            ? "built into the binary (--shader-dir DIR to edit them)"
                            : options_.shaderDir + " (hot reload: checked twice a second)";
    info.shaderError = shaderError_;
    info.message = message_;
    info.flying = input_.flying();
    info.camera = camera_.camera();
    info.lights = lights_;
    if (controls_.realtime) {
        info.realtimeSpp = traceSpp_;
        info.realtimeScale = realtimeScale_;
        info.traceMs = traceMs_;
        if (pipeline_) {
            info.temporalMs = 1000.0 * pipeline_->timings().temporalSeconds;
            info.filterMs = 1000.0 * pipeline_->timings().filterSeconds;
        }
        info.historyMaxFrames = temporalSettings().maxHistorySamples / float(realtimeSpp_);
    }
    return info;
}

void Session::reloadShadersIfChanged(double t) {
    if (!watcher_ || !watcher_->poll(t)) return;
    try {
        renderer_.reloadShaders();  // restarts accumulation, or throws and keeps the running programs
        tile_ = 0;
        planner_.passAbandoned();
        restartTime_ = now();
        heatFitDue_ = true;
        display_.reloadShaders();
        denoiser_.reloadShaders();
        if (pipeline_) {
            pipeline_->reloadShaders();
            pipeline_->reset();
            realtimeFrames_ = 0;
        }
        denoisedSamples_ = -1;
        shaderError_.clear();
        std::fprintf(stderr, "fragpath: reloaded shaders from %s\n", options_.shaderDir.c_str());
    } catch (const Error& e) {
        reportError(e.what());
    }
}

void Session::restart(const RenderSettings& settings, bool reduced) {
    try {
        renderer_.configure(settings, camera_.camera());
        lastGood_ = settings;
        configured_ = true;
    } catch (const Error& e) {
        if (!configured_) throw;  // at start there is nothing to fall back to
        // The renderer keeps the programs it had: go back to the settings they were compiled for, in the
        // panel too, so that it shows what is rendered.
        reportError(e.what());
        controls_.adopt(lastGood_);
        try {
            renderer_.configure(lastGood_, camera_.camera());
        } catch (const Error&) {
            // Nothing recompiled successfully; the previous programs keep drawing.
        }
        policy_.restartFailed(lastGood_);
    }
    tile_ = 0;
    planner_.passAbandoned();
    restartTime_ = now();
    denoisedSamples_ = -1;
    // While moving, keep the heat map's range from the last full-resolution image: a range fitted to
    // every reduced frame would flicker.
    if (!reduced || controls_.heatMax <= 0.0f) heatFitDue_ = true;
}

float Session::movingScale(glm::ivec2 framebuffer) const {
    // A quarter of the window, or less (by halves) until a whole pass fits in a frame's budget: then
    // every frame of a camera motion shows a complete image.
    float scale = 0.25f;
    while (scale > 1.0f / 16.0f &&
           planner_.passSeconds(framebuffer) * scale * scale > planner_.budgetSeconds())
        scale *= 0.5f;
    return scale;
}

// With stopAtPassEnd the frame does not start another pass after completing one.
void Session::renderWithinBudget(bool stopAtPassEnd) {
    glm::ivec2 size(renderer_.settings().width, renderer_.settings().height);
    double start = now();
    planner_.setBudgetSeconds(
        std::clamp(kTargetFrameSeconds - overheadSeconds_, kMinBudgetSeconds, kMaxBudgetSeconds));
    for (;;) {
        if (tile_ == 0) tile_ = planner_.tileSize(size);  // fixed for a whole pass
        double pixels = TilePlanner::pixelsPerTile(size, tile_);
        double tileStart = now();
        bool passDone = renderer_.renderTile(tile_);
        window_.finish();  // time the work, not the queueing of it
        planner_.record(pixels, now() - tileStart);
        framePaths_ += pixels;
        if (passDone) {
            tile_ = 0;
            planner_.passDone();
            if (stopAtPassEnd) break;
        }
        if (targetReached()) break;
        int next = tile_ ? tile_ : planner_.tileSize(size);
        if (!planner_.fits(now() - start, TilePlanner::pixelsPerTile(size, next))) break;
    }
    frameRenderSeconds_ = now() - start;
}

void Session::fitHeatMapIfDue() {
    bool countView = isCountView(renderer_.settings().view);
    bool due = heatFitRequested_ || (controls_.autoHeatMax && heatFitDue_);
    if (!countView || !due || renderer_.samples() < 1) return;
    // One read-back per fit: the largest mean count in the image becomes the top of the scale.
    Image mean = renderer_.readback().mean();
    float largest = 0.0f;
    for (const glm::vec3& p : mean.pixels)
        if (std::isfinite(p.r)) largest = std::max(largest, p.r);
    controls_.heatMax = std::max(1.0f, std::ceil(largest));
    heatFitDue_ = heatFitRequested_ = false;
}

DisplayOptions Session::displayOptions() const {
    DisplayOptions d;
    d.tone = controls_.tone;
    const RenderSettings& s = renderer_.settings();
    if (isCountView(s.view)) {
        // Until the first fit, a range that every count stays within (bounces) or a rough guess.
        float fallback = s.view == View::Bounces ? float(std::max(s.maxDepth, 1)) : 16.0f;
        d.heatMax = controls_.heatMax > 0.0f ? controls_.heatMax : fallback;
    }
    d.splitLine = s.split.has_value();
    if (controls_.realtime) {
        d.splitLine = false;
        // Debug views as heat maps: history length in frames up to what a moving camera keeps,
        // the filter's standard deviation up to 1, disocclusion 0 or 1.
        switch (RealtimeView(controls_.realtimeView)) {
            case RealtimeView::HistoryLength:
                d.heatMax = std::max(1.0f, temporalSettings().maxHistorySamples / float(realtimeSpp_));
                break;
            case RealtimeView::Deviation:
            case RealtimeView::Disocclusion:
                d.heatMax = 1.0f;
                break;
            default:
                break;
        }
    }
    return d;
}

// The denoised image replaces the raw one when a denoiser is chosen and shown, the accumulation has
// the guides (the restart that adds them may still be pending) and a whole sample, and the view is
// radiance (denoising a count view would show nothing true).
bool Session::showsDenoised() const {
    const RenderSettings& s = renderer_.settings();
    return controls_.denoiser != Denoiser::None && controls_.showDenoised && s.guides &&
           s.view == View::Radiance && renderer_.samples() >= 1;
}

// Denoises again when the sample count changed, but spends at most about a quarter of the time on it: on a
// software renderer the a-trous passes cost about one sample (BENCHMARKS.md, "Denoisers: cost on llvmpipe"),
// on a GPU next to nothing, so there it follows every sample. `current` forces an up-to-date result
// (screenshots).
GLuint Session::shownTexture(bool current) {
    if (!showsDenoised()) return renderer_.textures().sum;
    bool stale = denoisedSamples_ != renderer_.samples();
    bool due = denoisedSamples_ < 0 || current || now() - denoisedAt_ >= 3.0 * denoiseSeconds_;
    if (stale && due) {
        double start = now();
        try {
            denoiser_.run(renderer_, controls_.denoiser);
        } catch (const Error& e) {
            reportError(e.what());
            controls_.denoiser = Denoiser::None;
            return renderer_.textures().sum;
        }
        window_.finish();
        denoisedAt_ = now();
        denoiseSeconds_ = denoisedAt_ - start;
        frameDenoiseSeconds_ += denoiseSeconds_;
        denoisedSamples_ = renderer_.samples();
    }
    return denoiser_.resultTexture();
}

Image Session::shownImage() {
    if (showsRealtime()) return pipeline_->result();
    if (!showsDenoised()) return renderer_.readback().mean();
    shownTexture(true);
    return denoiser_.result();
}

void Session::present(glm::ivec2 framebuffer) {
    // Before binding the window: denoising binds its own framebuffers.
    GLuint texture = showsRealtime() ? pipeline_->resultTexture() : shownTexture();
    window_.bindWindowFramebuffer();
    if (framebuffer.x > 0 && framebuffer.y > 0)
        display_.draw(
            texture == renderer_.textures().sum ? renderer_.textures() : AccumulationTextures{texture},
            framebuffer.x, framebuffer.y, displayOptions());
    if (ui_) ui_->render();
}

void Session::screenshotKey() {
    std::string base = screenshotBaseName(renderer_.samples());
    if (showsRealtime())
        base += "_realtime";
    else if (showsDenoised())
        base += std::string("_") + denoiserName(controls_.denoiser);
    try {
        Image mean = shownImage();
        writeViewImage(base + ".png", mean, displayOptions());
        writeImage(base + ".exr", mean);
        message_ = "wrote " + base + ".png, .exr";
        std::printf("wrote %s.png and %s.exr\n", base.c_str(), base.c_str());
        std::fflush(stdout);
    } catch (const Error& e) {
        message_ = "screenshot failed";
        std::fprintf(stderr, "fragpath: error: %s\n", e.what());
    }
}

void Session::printTiming() const {
    const RenderSettings& s = renderer_.settings();
    double pixels = double(s.width) * double(s.height);
    double paths = stats_.steadyPathsPerSecond();
    std::printf(
        "view: %zu frames, image %dx%d, %d spp; median frame time %.1f ms; %.3g samples/s, "
        "%.3g paths/s (after the first frame)\n",
        stats_.frames(), s.width, s.height, renderer_.samples(), 1000.0 * stats_.medianFrameSeconds(),
        pixels > 0 ? paths / pixels : 0.0, paths);
    if (controls_.realtime && pipeline_)
        std::printf(
            "real-time: %d spp in the last frame (next %d) at %dx%d: trace %.1f ms, temporal %.1f ms, "
            "filter %.1f ms\n",
            traceSpp_, realtimeSpp_, realtimeSettings_.width, realtimeSettings_.height, traceMs_,
            1000.0 * pipeline_->timings().temporalSeconds, 1000.0 * pipeline_->timings().filterSeconds);
}

TemporalSettings Session::temporalSettings() const {
    TemporalSettings t;
    t.reuse = controls_.temporalReuse;
    t.filter = controls_.realtimeFilter ? Denoiser::Atrous : Denoiser::None;
    return t;
}

// Leaving real-time mode: the renderer holds one frame's samples, so progressive mode starts afresh.
void Session::leaveRealtime() {
    policy_ = AccumulationPolicy();  // forgets what it configured: the next update restarts
    tile_ = 0;
    planner_.passAbandoned();
    denoisedSamples_ = -1;
    heatFitDue_ = true;
    realtimeWasOn_ = false;
}

// One real-time frame over the whole image (at the resolution scale). False when there is nothing to draw
// into or it failed. The history survives camera motion (reprojection is the point); anything else the
// renderer is configured with (scene settings, integrator, size) resets it, as does a shader reload.
bool Session::realtimeFrame(glm::ivec2 framebuffer) {
    if (framebuffer.x <= 0 || framebuffer.y <= 0) return false;
    if (!realtimeWasOn_) {  // entering: drop the progressive pass in progress
        tile_ = 0;
        planner_.passAbandoned();
        realtimeFrames_ = 0;
        realtimeWasOn_ = true;
    }
    RenderSettings s = controls_.requested();
    s.split.reset();  // the pipeline reprojects one image
    s.guides = true;
    glm::ivec2 size =
        glm::max(glm::ivec2(1),
                 glm::ivec2(glm::round(glm::vec2(framebuffer) * controls_.resolutionScale * realtimeScale_)));
    s.width = size.x;
    s.height = size.y;
    s.samplesPerPass = 1;
    s.sampleOffset = 0;
    if (realtimeFrames_ == 0 || !sameAccumulation(s, realtimeSettings_)) {
        if (pipeline_) pipeline_->reset();  // a new one (made below) starts without history
        realtimeFrames_ = 0;
        sampleOffset_ = 0;
    }
    RenderSettings frame = s;
    frame.samplesPerPass = std::min(realtimeSpp_, RenderSettings::kMaxSamplesPerPass);
    frame.sampleOffset = sampleOffset_;
    const Camera camera = camera_.camera();
    try {
        if (!pipeline_) pipeline_ = std::make_unique<TemporalPipeline>(ShaderLibrary(options_.shaderDir));
        double start = now();
        renderer_.configure(frame, camera);
        renderer_.render(realtimeSpp_);
        window_.finish();
        traceMs_ = 1000.0 * (now() - start);
        traceSpp_ = realtimeSpp_;
        pipeline_->run(renderer_, camera, temporalSettings(), RealtimeView(controls_.realtimeView));
    } catch (const Error& e) {
        if (!configured_ && realtimeFrames_ == 0 && realtimeSettings_.width == 0)
            throw;  // nothing to fall back to
        reportError(e.what());
        if (realtimeSettings_.width > 0) {
            controls_.adopt(realtimeSettings_);  // the settings that last worked, as progressive mode does
            controls_.render.samplesPerPass = lastGood_.samplesPerPass;  // progressive mode's own
            controls_.render.sampleOffset = lastGood_.sampleOffset;
            realtimeFrames_ = 0;
        } else {
            controls_.realtime = false;
            leaveRealtime();
        }
        return false;
    }
    configured_ = true;
    // What progressive mode falls back to if its next restart fails: these settings, its own passes.
    lastGood_ = s;
    lastGood_.guides = controls_.denoiser != Denoiser::None;
    lastGood_.samplesPerPass = controls_.render.samplesPerPass;
    lastGood_.sampleOffset = controls_.render.sampleOffset;
    realtimeSettings_ = s;
    sampleOffset_ += uint32_t(realtimeSpp_);
    ++realtimeFrames_;
    framePaths_ = double(realtimeSpp_) * double(size.x) * double(size.y);
    frameRenderSeconds_ = traceMs_ / 1000.0;
    return true;
}

// One progressive frame: restart when the policy says so, then render within the frame's budget.
bool Session::progressiveFrame(glm::ivec2 framebuffer, bool automatedSamples, double start, int frames) {
    AccumulationPolicy::Request request;
    request.cameraVersion = camera_.version();
    request.settings = controls_.requested();
    request.windowSize = framebuffer;
    request.resolutionScale = controls_.resolutionScale;
    glm::ivec2 full = glm::max(glm::ivec2(1), glm::ivec2(glm::vec2(framebuffer) * controls_.resolutionScale));
    // Reduced resolution only helps where a full pass does not fit in a frame (software rendering).
    request.reduceWhileMoving = !automatedSamples && planner_.passSeconds(full) > planner_.budgetSeconds();
    request.movingScale = movingScale(framebuffer);
    request.now = start;
    AccumulationPolicy::Decision decision = policy_.update(request);
    if (decision.restart) restart(decision.settings, decision.reduced);
    reduced_ = decision.reduced;

    bool rendering = decision.render && !targetReached();
    // From the automation's last frame on, a frame ends at a pass's end rather than start another.
    bool lastFrames = options_.frames > 0 && frames + 1 >= options_.frames;
    if (rendering) renderWithinBudget(lastFrames);
    return rendering;
}

void Session::run() {
    // With --spp in automation nothing moves, and the result must equal `fragpath render`'s.
    bool automatedSamples = options_.frames > 0 && controls_.targetSpp > 0;
    double last = now();
    int frames = 0;
    bool idle = false;
    while (!window_.shouldClose()) {
        if (idle)
            window_.waitEvents(0.25);  // wakes for input; the timeout keeps hot reload polling
        else
            window_.pollEvents();
        double start = now();
        double dt = start - last;
        last = start;

        if (ui_) ui_->beginFrame();
        handleKeys();
        handleCamera(dt);
        reloadShadersIfChanged(start);

        glm::ivec2 framebuffer = window_.framebufferSize();
        framePaths_ = 0.0;
        frameRenderSeconds_ = 0.0;
        frameDenoiseSeconds_ = 0.0;
        bool rendering = false;
        if (controls_.realtime) {
            rendering = realtimeFrame(framebuffer);
        } else {
            if (realtimeWasOn_) leaveRealtime();
            rendering = progressiveFrame(framebuffer, automatedSamples, start, frames);
        }
        fitHeatMapIfDue();
        // After rendering, so that it shows this frame's figures; its changes apply from the next frame.
        if (ui_ && controls_.showPanel) applyActions(panel_.draw(controls_, panelInfo()));
        ++frames;
        bool done = automationDone(frames);
        // A new accumulation is black where its first pass has not reached yet. Rather than wipe the
        // picture and fill it in tile by tile (most of a second at full resolution on a software
        // renderer), keep the last complete picture on screen (no swap) until the first pass is done.
        // Not while moving: motion must show at once (its reduced passes fit in a frame anyway).
        bool complete = renderer_.samples() >= 1;
        bool hold = !complete && completeShown_ && !policy_.moving(now()) &&
                    now() - restartTime_ < kMaxHoldSeconds && !done;
        if (hold) {
            if (ui_) ui_->skipFrame();
        } else {
            present(framebuffer);
            if (done && !options_.windowScreenshot.empty()) {
                glm::ivec2 size;
                std::vector<std::uint8_t> pixels = window_.readBackBuffer(size);
                writeRgb8Png(options_.windowScreenshot, size, pixels);
                std::printf("wrote %s (the window)\n", options_.windowScreenshot.c_str());
            }
            window_.swapBuffers();
            completeShown_ = complete;
        }
        double frameSeconds = now() - start;
        stats_.addFrame(now(), frameSeconds, framePaths_,
                        double(renderer_.settings().width) * double(renderer_.settings().height));
        if (rendering && controls_.realtime) {
            realtimeOverheadMs_ +=
                0.25 * (std::max(1000.0 * frameSeconds - traceMs_, 0.0) - realtimeOverheadMs_);
            // One sample per pixel first, then pixels (dynamic resolution), then more samples.
            if (!controls_.dynamicResolution)
                realtimeScale_ = 1.0f;
            else if (realtimeSpp_ == 1 && realtimeFrames_ > kWarmUpFrames)
                realtimeScale_ =
                    adaptResolutionScale(realtimeScale_, 1000.0 * frameSeconds, double(controls_.targetFps));
            if (realtimeScale_ >= 1.0f)
                realtimeSpp_ = adaptSamplesPerFrame(realtimeSpp_, traceMs_, double(controls_.targetFps),
                                                    realtimeOverheadMs_);
        } else if (rendering) {
            overheadSeconds_ +=
                0.25 *
                (std::max(frameSeconds - frameRenderSeconds_ - frameDenoiseSeconds_, 0.0) - overheadSeconds_);
        }
        if (done) break;
        // Real-time mode idles only when it cannot render (a minimised window): a still camera keeps
        // accumulating into the history.
        idle = options_.frames == 0 && !rendering &&
               (controls_.realtime || (!policy_.moving(now()) && !input_.flying()));
    }

    if (!options_.screenshot.empty()) {
        writeViewImage(options_.screenshot, shownImage(), displayOptions());
        std::printf("wrote %s (%d spp)\n", options_.screenshot.c_str(), renderer_.samples());
    }
    if (options_.printTiming) printTiming();
}

}  // namespace

void runViewer(const Scene& scene, const ViewerOptions& options) {
    Session session(scene, options);
    session.run();
}

}  // namespace fp
