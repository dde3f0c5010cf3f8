#pragma once
// The image a view shows, written to a file: what the display pass draws (the tone mapping of
// writeImage, or for count views the heat map), for the viewer's screenshots and `render -o x.png`.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "render/display.h"
#include "settings/render_settings.h"

namespace fp {

// By the extension of `path`: .png is the view as shown (the tone mapping of writeImage, or for count
// views the heat map with options.heatMax); .exr and .pfm keep the linear mean. Throws fp::Error.
void writeViewImage(const std::string& path, const Image& mean, const DisplayOptions& options);

// An RGB8 image (top row first) as PNG, e.g. GlfwWindow::readBackBuffer(). Throws fp::Error.
void writeRgb8Png(const std::string& path, glm::ivec2 size, const std::vector<std::uint8_t>& rgb);

// A PNG of `view` that shows its values, for `render` (which has no viewer to pick a scale): count
// views as the heat map up to the image's largest count; depth from the nearest hit (black) to the
// farthest (white); cost's three counts each divided by its largest; radiance, normal and albedo as
// writeImage. .exr and .pfm keep the raw values (depth in scene units, counts).
void writeRenderedView(const std::string& path, const Image& mean, View view, const DisplaySettings& tone);

}  // namespace fp
