#pragma once
// The names of the viewer's screenshots. What they hold is written by render/view_image.h (the view as
// shown, the linear accumulation, a capture of the whole window).
#include <string>

#include "render/view_image.h"

namespace fp {

// The screenshot key's names: fragpath_<samples>spp.png and .exr, in the current directory.
std::string screenshotBaseName(int samples);

}  // namespace fp
