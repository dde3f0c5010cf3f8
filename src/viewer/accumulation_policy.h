#pragma once
// When the viewer must throw its accumulated samples away, and at what size it accumulates.
//
// Samples may only be averaged while they estimate the same image: the same camera, render settings
// and accumulation size. Each frame the viewer describes what it wants; the policy answers whether the
// renderer must be reconfigured (which restarts accumulation at 0 samples). Display-only choices
// (exposure, tone map, heat-map range, the target sample count) are deliberately not part of the
// request, so changing them never costs samples.
//
// While the camera moves (or the window is being resized) the policy asks for a reduced resolution so
// that a software renderer keeps up; once nothing has changed for `settleSeconds` it asks for full
// resolution again, which is one more restart. No OpenGL here: it is unit-tested.
#include <cstdint>

#include <glm/glm.hpp>

#include "settings/render_settings.h"

namespace fp {

// Whether two settings describe the same accumulation (every field the renderer reads).
bool sameAccumulation(const RenderSettings& a, const RenderSettings& b);

class AccumulationPolicy {
  public:
    struct Options {
        double settleSeconds = 0.2;     // still for this long after the last change: back to full resolution
        float minScale = 1.0f / 16.0f;  // resolution scales are clamped to [minScale, 1]
    };

    // What the viewer wants this frame.
    struct Request {
        uint64_t cameraVersion = 0;    // CameraController::version()
        RenderSettings settings;       // width and height are ignored: they follow the window
        glm::ivec2 windowSize{0};      // framebuffer pixels
        float resolutionScale = 1.0f;  // accumulation size / window size when still
        // Accumulation size / window size while moving, when smaller than resolutionScale: small enough
        // that a whole pass fits in a frame, so that a moving image is never half rendered.
        float movingScale = 0.25f;
        bool reduceWhileMoving = true;  // false when a full-resolution pass is cheap, or nothing moves
        double now = 0.0;               // seconds, any monotonic origin
    };

    struct Decision {
        bool restart = false;     // configure the renderer with `settings` (accumulation restarts)
        bool render = false;      // false: nothing to draw into (a minimised window)
        bool reduced = false;     // `settings` is at the moving resolution
        RenderSettings settings;  // the accumulation to render into, its size included
    };

    AccumulationPolicy() : AccumulationPolicy(Options{}) {}
    explicit AccumulationPolicy(const Options& options) : options_(options) {}

    Decision update(const Request& request);

    // The configure() for the last restart failed (a shader error): the renderer still holds the
    // previous accumulation, so the next update compares against `settings` instead.
    void restartFailed(const RenderSettings& settings);
    // True from a camera or window change until settleSeconds after the last one.
    bool moving(double now) const;
    // Restarts so far, the first configure included.
    uint64_t restarts() const { return restarts_; }

  private:
    static glm::ivec2 scaled(glm::ivec2 window, float scale);

    Options options_;
    // What the last update saw, to detect motion.
    bool seenAny_ = false;
    uint64_t seenCamera_ = 0;
    glm::ivec2 seenWindow_{0};
    double lastChange_ = -1e300;
    // What the renderer accumulates now.
    bool configuredAny_ = false;
    uint64_t configuredCamera_ = 0;
    RenderSettings configured_;
    uint64_t restarts_ = 0;
};

}  // namespace fp
