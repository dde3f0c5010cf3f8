#include "denoise/denoiser.h"

#include "core/error.h"
#include "core/text.h"
#include "denoise/denoise_passes.h"

namespace fp {

Denoiser parseDenoiser(const std::string& name) {
    return parseName(name, kAllDenoisers, denoiserName, "denoiser");
}

const char* denoiserName(Denoiser denoiser) {
    static constexpr const char* kNames[] = {"none", "bilateral", "atrous"};  // in enum order
    return nameOf(denoiser, kNames);
}

Image denoise(Renderer& renderer, Denoiser which) {
    if (which == Denoiser::None) return renderer.readback().mean();
    DenoisePasses passes(renderer.shaders());
    passes.run(renderer, which);
    return passes.result();
}

}  // namespace fp
