#pragma once
// A linear RGB float image, rows stored top to bottom, and its file formats.
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace fp {

struct Image {
    int width = 0, height = 0;
    std::vector<glm::vec3> pixels;  // row-major, row 0 at the top

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h), glm::vec3(0.0f)) {}
    glm::vec3& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
    const glm::vec3& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

enum class ToneMap { Clamp, Reinhard, Aces };
constexpr ToneMap kAllToneMaps[] = {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces};

struct DisplaySettings {
    float exposure = 0.0f;  // in stops: pixels are scaled by 2^exposure before tone mapping
    ToneMap toneMap = ToneMap::Clamp;
};

// Write by the extension of `path`: .pfm and .exr keep linear floats, .png is tone-mapped sRGB.
// Writes to a temporary name and renames, so a failure never leaves a truncated file.
// Throws fp::Error naming the path on an unknown extension or a file that cannot be written.
void writeImage(const std::string& path, const Image& image, const DisplaySettings& display = {});
// Read a linear .pfm, .exr or .hdr image; throws fp::Error on a missing or malformed file.
Image readImage(const std::string& path);
// readImage, and also 8-bit .png images, decoded from sRGB to linear [0, 1] (alpha ignored): for
// comparing images, where a PNG is what was shown. Throws fp::Error as readImage does.
Image readImageOrPng(const std::string& path);

}  // namespace fp
