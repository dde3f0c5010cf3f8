#pragma once
// The denoisers: GLSL passes (glsl/denoise/) over a Renderer's accumulation, which they never change.
// `bilateral` is a joint bilateral filter of the mean colour; `atrous` the edge-avoiding a-trous
// wavelet filter (Dammertz et al. 2010) steered by per-pixel variance as in SVGF (Schied et al. 2017),
// on the colour divided by the first-hit albedo. Both are guided by the first-hit normal and depth,
// which the trace pass accumulates when RenderSettings::guides is set.
#include <string>

#include "image/image.h"
#include "render/renderer.h"

namespace fp {

enum class Denoiser { None, Bilateral, Atrous };

constexpr Denoiser kAllDenoisers[] = {Denoiser::None, Denoiser::Bilateral, Denoiser::Atrous};
Denoiser parseDenoiser(const std::string& name);  // throws fp::Error listing the choices
const char* denoiserName(Denoiser denoiser);

// The renderer's current accumulation, denoised by `which` (rows top first, like Accumulation::mean()).
// None gives the raw mean. Needs a render with RenderSettings::guides set (else throws fp::Error).
// Compiles the passes each call, from the renderer's shaders (built in, or its shader directory); to
// denoise often, keep a DenoisePasses (denoise/denoise_passes.h).
Image denoise(Renderer& renderer, Denoiser which);

}  // namespace fp
