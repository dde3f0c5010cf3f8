#pragma once
// Everything the user can change in the viewer besides the camera: what to render (these restart
// accumulation) and how to show it (these never do). The panel edits it; command-line flags set it.
#include "denoise/denoiser.h"
#include "image/image.h"
#include "realtime/frame_budget.h"
#include "settings/render_settings.h"

namespace fp {

struct ViewerControls {
    // What to render. width and height are unused: the accumulation follows the window.
    RenderSettings render;
    bool split = false;
    SplitView splitView;           // the right half, when split
    float resolutionScale = 1.0f;  // accumulation size / window size when the camera is still

    // How to show it.
    DisplaySettings tone;
    bool autoHeatMax = true;  // count views: the heat map's top from the image itself
    float heatMax = 0.0f;     // count views: the count shown white; 0 until known
    int targetSpp = 0;        // stop rendering at this many samples per pixel; 0: never
    bool showPanel = true;
    // Denoising of the radiance view: choosing a denoiser restarts accumulation (the trace pass then
    // also accumulates the guides); showing the raw or the denoised image never does.
    Denoiser denoiser = Denoiser::None;
    bool showDenoised = true;

    // Real-time mode (src/realtime/temporal_pipeline.h): each frame traces a few samples per pixel at the
    // current camera, reprojects the previous frames' history and filters it. Off: progressive mode.
    bool realtime = false;
    int targetFps = kDefaultFps;    // samples per frame adapt to the budget 1000 / targetFps ms
    bool dynamicResolution = true;  // where 1 spp overruns the budget, fewer pixels (realtime/frame_budget.h)
    bool temporalReuse = true;      // reproject and blend the history
    bool realtimeFilter = true;     // the a-trous filter of the history
    int realtimeView = 0;           // RealtimeView: image, history length, deviation, disocclusion

    RenderSettings requested() const {
        RenderSettings s = render;
        s.split = split ? std::optional<SplitView>(splitView) : std::nullopt;
        s.guides = denoiser != Denoiser::None;
        return s;
    }
    // Adopts the render-related fields of `s` (after a failed change, to show what is really rendered).
    void adopt(const RenderSettings& s) {
        render = s;
        render.split.reset();
        split = s.split.has_value();
        if (s.split) splitView = *s.split;
    }
};

}  // namespace fp
