#pragma once
// Real-time mode's samples per frame and resolution: as many samples as fit the frame budget (1000 /
// target FPS ms), adapted from the last frame's measured trace time, and where even one sample per pixel
// does not fit, fewer pixels. No OpenGL here: it is unit-tested.
namespace fp {

// The frame rate real time aims at unless told otherwise: the viewer's real-time mode, `fragpath
// realtime` and the study's practice runs.
constexpr int kDefaultFps = 30;

struct FrameBudget {
    // The budget is 1000 / fps ms; the pipeline, panel and display take `overheadMs` of it.
    // Hysteresis: lower as soon as the trace overruns its share by more than `overrun` (10 %), raise only
    // when one more sample would still leave `headroom` (20 %) of the share free; otherwise keep spp.
    static constexpr double overrun = 1.1, headroom = 0.8;
    static constexpr int maxSpp = 64;
    // Resolution scales (image side / window side) run down a ladder of steps that halve the pixel count:
    // 1, 1/sqrt(2), 1/2, ... down to minScale.
    static constexpr float minScale = 0.125f;
};

// The samples per pixel for the next frame, after a frame of `spp` samples whose trace took `traceMs`.
// At least 1, at most FrameBudget::maxSpp. A jump goes straight to the number that fits (the trace time
// is close to linear in spp), aiming at 90 % of the trace's share so that the next frame does not overrun.
int adaptSamplesPerFrame(int spp, double traceMs, double fps, double overheadMs);

// The resolution scale for the next frame, after a frame of one sample per pixel at `scale` that took
// `frameMs` in all (trace, pipeline, display). Real-time rendering keeps one sample per pixel and gives
// up pixels first, as practice does (dynamic resolution), since the temporal filter recovers detail
// but cannot make up a frame rate. A frame time is taken as proportional to the pixel count (the trace
// and every filter pass are per pixel): an overrun by more than FrameBudget::overrun drops as many
// ladder steps as bring the frame under 90 % of the budget; a frame that would still leave
// FrameBudget::headroom of the budget free at twice the pixels climbs one step. Every change of size
// drops the history, so the band between the two is wide. Scales off the ladder are snapped to it.
float adaptResolutionScale(float scale, double frameMs, double fps);

}  // namespace fp
