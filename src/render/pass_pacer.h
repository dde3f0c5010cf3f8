#pragma once
// How many samples each pixel takes in the next pass of a render.
//
// A pass costs more than its samples: the accumulation targets are read and written once per pass, and
// on llvmpipe a group of 8 pixels shades in the lanes of one vector and waits for its longest path, which
// path regeneration (glsl/passes/trace.frag.glsl) hides only within a pass. At 256x256, depth 64, 256
// spp, one sample per pass cost the Cornell box 1.27x the CPU time of 16 per pass (issue 35). A long pass,
// though, answers an interrupt or a time budget late, and can outlast a GPU's watchdog. So, unless the
// user fixes the count, each pass takes as many samples as fit kTargetPassSeconds at the last pass's
// rate, at most RenderSettings::kMaxSamplesPerPass. The image does not depend on the count: sample
// k of pixel p is the same whichever pass draws it.
namespace fp {

class PassPacer {
  public:
    // Seconds a pass should take: long beside a pass's fixed cost, short beside a GPU watchdog (2 s on
    // Windows) and a user waiting for an interrupt or a time budget to take effect.
    static constexpr double kTargetPassSeconds = 1.0;

    // fixedCount 0 chooses the count from the passes' times; 1 to maxCount draws that many every pass.
    PassPacer(int fixedCount, int maxCount, double targetSeconds = kTargetPassSeconds);

    // The next pass's sample count, at most `remaining`.
    int next(int remaining) const;
    // A pass of `samples` samples per pixel took `seconds`.
    void record(int samples, double seconds);

  private:
    int fixed_, max_;
    double target_;
    int count_ = 1;  // the first pass takes one sample: nothing is known yet of the scene's cost
};

}  // namespace fp
