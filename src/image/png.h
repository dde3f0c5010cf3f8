#pragma once
// 8-bit sRGB PNG for viewing: exposure, tone curve and sRGB encoding from tone_map.h, then stb.
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace fp {

// The display codes of `image`: 3 bytes (R, G, B) per pixel, top row first, each channel
// quantize8(displayEncode(pixel, display)). This is what the PNG stores and what the GL display pass
// must reproduce.
std::vector<std::uint8_t> toDisplay8(const Image& image, const DisplaySettings& display);

std::vector<std::uint8_t> encodePng(const Image& image, const DisplaySettings& display);
// Display codes as they are (3 bytes per pixel, top row first), for images not made by toDisplay8.
std::vector<std::uint8_t> encodeRgb8Png(int width, int height, const std::vector<std::uint8_t>& rgb);
void writePng(const std::string& path, const Image& image, const DisplaySettings& display);

}  // namespace fp
