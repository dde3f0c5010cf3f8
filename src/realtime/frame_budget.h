#pragma once
// Real-time mode's samples per frame: as many as fit the frame budget (1000 / target FPS ms), adapted
// from the last frame's measured trace time. No OpenGL here: it is unit-tested.
namespace fp {

struct FrameBudget {
    // The budget is 1000 / fps ms; the pipeline, panel and display take `overheadMs` of it.
    // Hysteresis: lower as soon as the trace overruns its share by more than `overrun` (10 %), raise only
    // when one more sample would still leave `headroom` (20 %) of the share free; otherwise keep spp.
    static constexpr double overrun = 1.1, headroom = 0.8;
    static constexpr int maxSpp = 64;
};

// The samples per pixel for the next frame, after a frame of `spp` samples whose trace took `traceMs`.
// At least 1, at most FrameBudget::maxSpp. A jump goes straight to the number that fits (the trace time
// is close to linear in spp), aiming at 90 % of the trace's share so that the next frame does not overrun.
int adaptSamplesPerFrame(int spp, double traceMs, double fps, double overheadMs);

}  // namespace fp
