#include "study/denoisers.h"

#include <memory>

#include "core/error.h"
#include "core/text.h"
#include "denoise/denoise_passes.h"
#include "denoise/denoiser.h"
#include "study/name_list.h"

namespace fp::study {

std::vector<StudyDenoiser> availableDenoisers() {
    // One set of compiled denoising passes shared by every study denoiser (fp::denoise() would compile
    // them for each call); created on first use, when a GL context is current.
    auto passes = std::make_shared<std::unique_ptr<DenoisePasses>>();
    std::vector<StudyDenoiser> list;
    for (Denoiser d : {Denoiser::None, Denoiser::Bilateral, Denoiser::Atrous}) {
        list.push_back({denoiserName(d), [d, passes](Renderer& renderer) {
                            if (d == Denoiser::None) return renderer.readback().mean();
                            // From the renderer's shaders, so that --shader-dir reaches them too.
                            if (!*passes) *passes = std::make_unique<DenoisePasses>(renderer.shaders());
                            (*passes)->run(renderer, d);
                            return (*passes)->result();
                        }});
    }
    return list;
}

std::vector<StudyDenoiser> selectDenoisers(const std::string& names) {
    std::vector<StudyDenoiser> all = availableDenoisers(), chosen;
    std::vector<std::string> known;
    for (const StudyDenoiser& d : all) known.push_back(d.name);
    for (const std::string& name : splitNameList(names, "--denoisers")) {
        size_t i = indexOfName(known, name, "denoiser");
        chosen.push_back(all[i]);
    }
    return chosen;
}

}  // namespace fp::study
