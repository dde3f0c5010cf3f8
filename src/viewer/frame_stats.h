#pragma once
// The figures the panel shows and `--frames` prints: frame time, samples/s and paths/s. Rates are taken
// over the last second or so, so they follow changes (resolution, integrator) without flickering.
#include <cstddef>
#include <deque>
#include <vector>

namespace fp {

class FrameStats {
  public:
    explicit FrameStats(double windowSeconds = 1.0) : window_(windowSeconds) {}

    // One frame that ended at `now` and took `frameSeconds` (start to start of the next), during which
    // `paths` pixel samples were traced into an accumulation of `imagePixels` pixels.
    void addFrame(double now, double frameSeconds, double paths, double imagePixels);

    double frameSeconds() const;    // mean over the recent window
    double pathsPerSecond() const;  // recent window
    // Full-image samples per second at the current accumulation size.
    double samplesPerSecond() const { return imagePixels_ > 0.0 ? pathsPerSecond() / imagePixels_ : 0.0; }

    // Over every frame so far, for the summary printed at exit.
    size_t frames() const { return all_.size(); }
    double medianFrameSeconds() const;
    // Paths per second of frame time over every frame but the first, which also pays for compiling
    // the shaders (on llvmpipe, for the JIT at the first draw).
    double steadyPathsPerSecond() const { return steadySeconds_ > 0.0 ? steadyPaths_ / steadySeconds_ : 0.0; }

  private:
    struct Frame {
        double end, seconds, paths;
    };
    double window_;
    double imagePixels_ = 0.0;
    std::deque<Frame> recent_;
    std::vector<double> all_;
    double steadyPaths_ = 0.0, steadySeconds_ = 0.0;
};

}  // namespace fp
