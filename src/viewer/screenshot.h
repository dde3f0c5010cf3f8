#pragma once
// Images the viewer writes: what the 3D view shows (display transform or heat map, without the panel),
// the linear accumulation, and a capture of the whole window.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "render/display.h"

namespace fp {

// By the extension of `path`: .png is the view as shown (the tone mapping of writeImage, or for count
// views the heat map with options.heatMax); .exr and .pfm keep the linear mean. Throws fp::Error.
void writeViewImage(const std::string& path, const Image& mean, const DisplayOptions& options);

// An RGB8 image (top row first) as PNG, e.g. GlfwWindow::readBackBuffer(). Throws fp::Error.
void writeRgb8Png(const std::string& path, glm::ivec2 size, const std::vector<std::uint8_t>& rgb);

// The screenshot key's names: fragpath_<samples>spp.png and .exr, in the current directory.
std::string screenshotBaseName(int samples);

}  // namespace fp
