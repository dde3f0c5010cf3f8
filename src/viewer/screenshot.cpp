#include "viewer/screenshot.h"

namespace fp {

std::string screenshotBaseName(int samples) {
    return "fragpath_" + std::to_string(samples) + "spp";
}

}  // namespace fp
