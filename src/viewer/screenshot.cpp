#include "viewer/screenshot.h"

#include <stb_image_write.h>

#include "core/error.h"
#include "image/file_io.h"
#include "image/tone_map.h"
#include "viewer/heat_map.h"

namespace fp {

namespace {

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

void writeRgb8Png(const std::string& path, glm::ivec2 size, const std::vector<std::uint8_t>& rgb) {
    if (size.x <= 0 || size.y <= 0 || rgb.size() != size_t(size.x) * size_t(size.y) * 3)
        throw Error("cannot write '" + path + "': no image to write");
    std::vector<std::uint8_t> png;
    if (!stbi_write_png_to_func(appendBytes, &png, size.x, size.y, 3, rgb.data(), size.x * 3))
        throw Error("cannot write '" + path + "': PNG encoding failed");
    writeFileAtomically(path, png);
}

void writeViewImage(const std::string& path, const Image& mean, const DisplayOptions& options) {
    if (lowerCaseExtension(path) != ".png" || !(options.heatMax > 0.0f)) {
        writeImage(path, mean, options.tone);
        return;
    }
    // A count view: the same colours the display pass shows (the count is in the red channel).
    std::vector<std::uint8_t> rgb;
    rgb.reserve(mean.pixels.size() * 3);
    for (const glm::vec3& p : mean.pixels) {
        glm::vec3 c = heatMapColor(p.r / options.heatMax);
        for (int i = 0; i < 3; ++i) rgb.push_back(quantize8(c[i]));
    }
    writeRgb8Png(path, {mean.width, mean.height}, rgb);
}

std::string screenshotBaseName(int samples) {
    return "fragpath_" + std::to_string(samples) + "spp";
}

}  // namespace fp
