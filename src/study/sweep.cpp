#include "study/sweep.h"

#include <algorithm>
#include <cstdio>

#include "core/clock.h"
#include "core/statistics.h"
#include "image/error_metrics.h"
#include "image/flip.h"
#include "image/image_stats.h"

namespace fp::study {

std::vector<int> sppLevels(int maxSpp) {
    std::vector<int> levels;
    for (int n = 1; n < maxSpp; n *= 2) levels.push_back(n);
    levels.push_back(maxSpp);
    return levels;
}

SweepResult runSweep(Renderer& renderer, const Image& reference, const SweepOptions& options) {
    // HDR-FLIP's exposures depend on the reference only: once for every row.
    const FlipExposures exposures = hdrFlipExposures(reference);
    const std::vector<int> levels = sppLevels(options.maxSpp);
    SweepResult result;
    for (Integrator integrator : options.integrators) {
        RenderSettings settings = options.render;
        settings.integrator = integrator;
        // The denoisers need the first-hit guides; they cost the raw render about a tenth (BENCHMARKS.md,
        // "Denoisers: cost on llvmpipe").
        for (const StudyDenoiser& denoiser : options.denoisers)
            if (denoiser.name != "none") settings.guides = true;
        const std::string name = integratorName(integrator);
        // Per level: wall and CPU seconds of every run.
        std::vector<std::vector<double>> wall(levels.size()), cpu(levels.size());
        std::vector<StudyRow> rows;
        // An untimed pass first: the first draw of a new program includes llvmpipe's JIT (0.3-0.7 s,
        // /work/shared/gl-notes.md), which no frame of an interactive renderer pays.
        renderer.configure(settings, options.camera);
        renderer.render(1);
        for (int run = 0; run < std::max(options.runs, 1); ++run) {
            renderer.configure(settings, options.camera);
            double wallSoFar = 0.0, cpuSoFar = 0.0;
            int done = 0;
            for (size_t level = 0; level < levels.size(); ++level) {
                auto start = SteadyClock::now();
                double cpuStart = processCpuSeconds();
                renderer.render(levels[level] - done);  // waits for the GPU (glFinish) before returning
                wallSoFar += secondsSince(start);
                cpuSoFar += processCpuSeconds() - cpuStart;
                done = levels[level];
                wall[level].push_back(wallSoFar);
                cpu[level].push_back(cpuSoFar);
                if (run > 0) continue;  // later runs only time; the images are the same bit for bit
                for (const StudyDenoiser& denoiser : options.denoisers) {
                    auto denoiseStart = SteadyClock::now();
                    Image image = denoiser.apply(renderer);
                    StudyRow row;
                    row.integrator = name;
                    row.denoiser = denoiser.name;
                    row.spp = levels[level];
                    // "none" only reads the accumulation back, which a real-time renderer never does.
                    row.denoiseSeconds = denoiser.name == "none" ? 0.0 : secondsSince(denoiseStart);
                    row.rmse = rmse(image, reference);
                    row.relMse = relativeMse(image, reference);
                    row.ssim = ssim(image, reference);
                    row.flip = hdrFlip(image, reference, kDefaultPixelsPerDegree, exposures).mean;
                    rows.push_back(row);
                    const std::vector<int>& keep = options.keepImagesAt;
                    if (std::find(keep.begin(), keep.end(), levels[level]) != keep.end())
                        result.images[{name, denoiser.name, levels[level]}] = std::move(image);
                }
                if (options.progress) {
                    char line[160];
                    std::snprintf(line, sizeof line, "%s %d spp: %.3f s, relMSE %.4g", name.c_str(),
                                  levels[level], wallSoFar,
                                  rows[rows.size() - options.denoisers.size()].relMse);
                    options.progress(line);
                }
            }
        }
        for (StudyRow& row : rows) {
            size_t level = size_t(std::find(levels.begin(), levels.end(), row.spp) - levels.begin());
            row.renderSeconds = median(wall[level]);
            row.renderCpuSeconds = median(cpu[level]);
            result.rows.push_back(row);
        }
    }
    return result;
}

}  // namespace fp::study
