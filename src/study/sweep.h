#pragma once
// The measurement grid of the study: for each integrator, samples per pixel 1, 2, 4, ... up to a
// limit, and at each level each denoiser; time and error against the reference.
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "image/image.h"
#include "render/renderer.h"
#include "study/denoisers.h"

namespace fp::study {

// One row of study.csv.
struct StudyRow {
    std::string scene;  // the scene set's name for it, or the scene file's stem (study/scene_set.h)
    std::string integrator, denoiser;
    int spp = 0;
    // Rendering the spp samples from scratch (median over the runs): wall seconds and process CPU
    // seconds (all of llvmpipe's threads). The denoiser's wall seconds come on top.
    double renderSeconds = 0.0, renderCpuSeconds = 0.0, denoiseSeconds = 0.0;
    double rmse = 0.0, relMse = 0.0, ssim = 0.0;
    double flip = 0.0;  // mean HDR-FLIP at the standard viewing condition (image/flip.h)
    double totalSeconds() const { return renderSeconds + denoiseSeconds; }
};

struct SweepOptions {
    RenderSettings render;  // size, depth, seed; the integrator is set per row
    Camera camera;
    std::vector<Integrator> integrators;
    std::vector<StudyDenoiser> denoisers;
    int maxSpp = 64;
    int runs = 1;                                      // timed repetitions; the median is kept
    std::vector<int> keepImagesAt;                     // spp levels whose images the strip needs
    std::function<void(const std::string&)> progress;  // a line per level, may be empty
};

struct SweepResult {
    std::vector<StudyRow> rows;  // integrator-major, then spp, then denoiser
    // (integrator, denoiser, spp) -> image, for the levels in keepImagesAt.
    std::map<std::tuple<std::string, std::string, int>, Image> images;
};

// 1, 2, 4, ... up to maxSpp (maxSpp itself last even if it is not a power of two).
std::vector<int> sppLevels(int maxSpp);

// Renders progressively: the image at 2N spp continues the one at N (sample k of a pixel depends only
// on the seed, the pixel and k), so each level costs only its new samples, and its time is the sum of
// the passes up to it, which is what rendering it from scratch costs (read-back and metrics excluded).
SweepResult runSweep(Renderer& renderer, const Image& reference, const SweepOptions& options);

}  // namespace fp::study
