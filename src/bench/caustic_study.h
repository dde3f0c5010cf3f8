#pragma once
// `fragpath bench --study caustic`: bdpt against nee (camera paths alone, and with its light pass for
// caustics) at equal process CPU time on causticScene
// (scene/procedural.h), the figures of BENCHMARKS.md ("BDPT vs NEE on a caustic scene").
#include <cstdint>

#include "image/image.h"
#include "image/image_stats.h"
#include "render/accumulation.h"
#include "settings/render_settings.h"

namespace fp::bench {

struct CausticStudyOptions {
    double budgetSeconds = 40.0;  // process CPU seconds per integrator and scene
    int referenceSpp = 16384;     // bdpt samples per pixel of the reference
};

// Prints the table; returns the exit code.
int runCausticStudy(const CausticStudyOptions& options);

// The study's parts that need no GL context.
// The settings of each of its renders: 24x24 (the size kCausticUnderSphere is given for), depth 5,
// 16 samples per pass; nee with `caustics` (camera paths alone, or its light pass).
RenderSettings causticStudySettings(Integrator integrator, uint32_t seed, Caustics caustics = Caustics::Auto);
// The pixels of `rect` (inside `image`) as an image of their own.
Image cropImage(const Image& image, const PixelRect& rect);
// The per-pixel variance of the mean in the luminance channel G, summed over `rect`.
double regionVariance(const Accumulation& acc, const PixelRect& rect);

}  // namespace fp::bench
