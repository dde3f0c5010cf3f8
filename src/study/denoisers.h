#pragma once
// The one seam between the study and the denoisers: the list of denoisers a study can compare, each a
// name and a function from the renderer's current accumulation to an image.
#include <functional>
#include <string>
#include <vector>

#include "image/image.h"
#include "render/renderer.h"

namespace fp::study {

struct StudyDenoiser {
    std::string name;  // as in the CSV and the --denoisers flag
    std::function<Image(Renderer&)> apply;
};

// Every denoiser this build has, "none" (the raw mean) first.
std::vector<StudyDenoiser> availableDenoisers();
// The denoisers named in a comma-separated list, in its order; throws fp::Error naming the unknown one
// and the choices.
std::vector<StudyDenoiser> selectDenoisers(const std::string& names);

}  // namespace fp::study
