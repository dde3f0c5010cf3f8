#include "image/png.h"

#include <stb_image_write.h>

#include "core/error.h"
#include "image/file_io.h"
#include "image/image_check.h"
#include "image/tone_map.h"

namespace fp {

namespace {

void appendToVector(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<std::uint8_t> toDisplay8(const Image& image, const DisplaySettings& display) {
    std::vector<std::uint8_t> codes;
    codes.reserve(image.pixels.size() * 3);
    for (const glm::vec3& pixel : image.pixels) {
        const glm::vec3 encoded = displayEncode(pixel, display);
        codes.push_back(quantize8(encoded.r));
        codes.push_back(quantize8(encoded.g));
        codes.push_back(quantize8(encoded.b));
    }
    return codes;
}

std::vector<std::uint8_t> encodePng(const Image& image, const DisplaySettings& display) {
    checkImageShape(image, "cannot encode PNG");
    // stb_image_write sizes its buffers with int; stay well below that.
    if (image.pixels.size() * 3 > (size_t(1) << 30)) {
        throw Error("cannot encode PNG: a " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " image is too large");
    }
    return encodeRgb8Png(image.width, image.height, toDisplay8(image, display));
}

std::vector<std::uint8_t> encodeRgb8Png(int width, int height, const std::vector<std::uint8_t>& rgb) {
    if (width <= 0 || height <= 0 || rgb.size() != size_t(width) * size_t(height) * 3)
        throw Error("cannot encode PNG: no image to encode");
    std::vector<std::uint8_t> png;
    if (!stbi_write_png_to_func(appendToVector, &png, width, height, 3, rgb.data(), width * 3))
        throw Error("cannot encode PNG: stb_image_write failed");
    return png;
}

void writePng(const std::string& path, const Image& image, const DisplaySettings& display) {
    checkImageShape(image, "cannot write '" + path + "'");
    std::vector<std::uint8_t> bytes;
    try {
        bytes = encodePng(image, display);
    } catch (const Error& e) {
        throw Error("cannot write '" + path + "': " + e.what());
    }
    writeFileAtomically(path, bytes);
}

}  // namespace fp
