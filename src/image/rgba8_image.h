#pragma once
// 8-bit colour images (PNG, JPEG, BMP, TGA, ... through stb_image) as material textures need them:
// the file's code values kept exactly, expanded to RGBA. Colour maps store sRGB-encoded values, so
// they stay encoded here and are decoded (exact sRGB curve) where they are used.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace fp {

struct Rgba8Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> texels;  // 4 bytes (R, G, B, A) per pixel, row-major, row 0 at the top
    int fileChannels = 4;  // what the file held: 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA (A = 255 without)
};

// Throws fp::Error starting with `name` when the bytes are not an 8-bit (or 16-bit, reduced to 8)
// image stb_image can decode; Radiance HDR files are refused too (a reflectance map is not radiance).
Rgba8Image decodeRgba8(const std::string& bytes, const std::string& name);

// What stands in for a colour texture that cannot be loaded: the magenta and black checker users
// recognise as "texture missing". 64x64 texels, 8x8 squares of 8x8 texels each (so bilinear filtering
// blends colours only along the squares' edges), magenta (255, 0, 255) in the top-left corner.
Rgba8Image missingTextureChecker();
constexpr int kCheckerTexels = 64, kCheckerSquares = 8;

// The mean of the pixels' linear RGB (each channel decoded from sRGB, then averaged; alpha ignored).
glm::vec3 meanLinearColor(const Rgba8Image& image);

// The mean of the pixels' codes / 255, all four channels (for maps of linear values).
glm::vec4 meanCodes(const Rgba8Image& image);

}  // namespace fp
