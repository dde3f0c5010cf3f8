#include "study/denoisers.h"

#include "core/error.h"
#include "study/name_list.h"

namespace fp::study {

std::vector<StudyDenoiser> availableDenoisers() {
    // TODO(merge): when src/denoise/denoiser.h lands (enum class Denoiser { None, Bilateral, Atrous },
    // denoiserName, Image denoise(Renderer&, Denoiser)), replace this body by
    //     std::vector<StudyDenoiser> list;
    //     for (Denoiser d : {Denoiser::None, Denoiser::Bilateral, Denoiser::Atrous})
    //         list.push_back({denoiserName(d), [d](Renderer& r) { return denoise(r, d); }});
    //     return list;
    // and add fp_denoise to the DEPS of the study stage in CMakeLists.txt.
    return {{"none", [](Renderer& renderer) { return renderer.readback().mean(); }}};
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
