#pragma once
// `fragpath realtime`: a camera path rendered frame by frame with the viewer's real-time pipeline
// (realtime/temporal_pipeline.h), each frame's samples fitted to a frame budget, and what it costs and
// how far it is from a converged image written to frames.csv, one row per frame.
#include <functional>
#include <optional>
#include <string>

#include "realtime/camera_path.h"
#include "realtime/frame_budget.h"
#include "realtime/temporal_pipeline.h"
#include "render/renderer.h"
#include "settings/render_settings.h"

namespace fp {

struct RealtimeRun {
    explicit RealtimeRun(CameraPath p) : path(std::move(p)) {}
    CameraPath path;
    int frames = 60;
    double fps = kDefaultFps;     // frame i shows path time i / fps; 1000 / fps ms is the budget
    std::optional<int> fixedSpp;  // samples per frame; unset: fitted to the budget
    TemporalSettings temporal;
    std::optional<int> referenceSpp;  // compare every frame with a render of this many samples
    // Where the references are kept between runs (realtime/reference_cache.h), with what names the scene
    // in its key (the scene file and environment as given).
    std::optional<std::string> referenceCache;
    std::string sceneKey;
    RenderSettings settings;  // size, integrator, depth, seed, sampler; spp and offset are set here
    DisplaySettings display;
    std::string outDir;
};

struct FrameRow {
    int frame = 0, spp = 0;
    double traceMs = 0.0, temporalMs = 0.0, filterMs = 0.0;
    double meanHistoryFrames = 0.0;  // history per pixel, in frames of this frame's spp
    std::optional<double> rmse, relMse, ssim, flip;
    std::optional<double> flicker;  // from the second frame on
    double ms() const { return traceMs + temporalMs + filterMs; }
};

// Temporal instability (flicker): the mean over pixels of |e_t - e_{t-1}|, where e is the display luma
// (image/error_metrics.h displayLuma) of a frame minus that of its reference, so that what the camera's
// motion changes in both is not counted; without references e is the frame's luma alone.
double flicker(const std::vector<float>& luma, const std::vector<float>& previousLuma,
               const std::vector<float>* reference, const std::vector<float>* previousReference);

// Renders the run into `run.outDir` (frame_NNNN.png, frames.csv, and strip.png: five frames spread over
// the run side by side, above their references with --reference-spp); `onFrame` sees each row.
// `stop` may return true to end early: what was rendered stays written.
std::vector<FrameRow> renderRealtime(Renderer& renderer, const RealtimeRun& run,
                                     const std::function<void(const FrameRow&)>& onFrame = nullptr,
                                     const std::function<bool()>& stop = nullptr);

}  // namespace fp
