#include "image/rgba8_image.h"

#include <stb_image.h>

#include "core/error.h"
#include "image/tone_map.h"

namespace fp {

Rgba8Image decodeRgba8(const std::string& bytes, const std::string& name) {
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    if (bytes.empty()) throw Error(name + ": empty file, not an image");
    if (bytes.size() > size_t(1) << 31) throw Error(name + ": file too large to decode as an image");
    const int size = int(bytes.size());
    if (stbi_is_hdr_from_memory(data, size))
        throw Error(name +
                    ": a Radiance HDR image; a colour texture must be an 8-bit image (PNG, JPEG, ...)");
    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(data, size, &width, &height, &channels, 4);
    if (!pixels)
        throw Error(name + ": not an image stb_image can read (" + stbi_failure_reason() +
                    "; PNG, JPEG, BMP, TGA, GIF, PSD, PIC and PNM are)");
    Rgba8Image image;
    image.width = width;
    image.height = height;
    image.fileChannels = channels;
    // Copied in one pass (resize and memcpy wrote every byte twice: 16 MB of zeros for a 2048x2048 map).
    image.texels.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
    stbi_image_free(pixels);
    return image;
}

Rgba8Image missingTextureChecker() {
    Rgba8Image image;
    image.width = image.height = kCheckerTexels;
    image.texels.resize(size_t(kCheckerTexels) * kCheckerTexels * 4);
    constexpr int square = kCheckerTexels / kCheckerSquares;
    for (int y = 0; y < kCheckerTexels; ++y)
        for (int x = 0; x < kCheckerTexels; ++x) {
            const bool magenta = (x / square + y / square) % 2 == 0;
            std::uint8_t* texel = &image.texels[(size_t(y) * kCheckerTexels + size_t(x)) * 4];
            texel[0] = texel[2] = magenta ? 255 : 0;
            texel[1] = 0;
            texel[3] = 255;
        }
    return image;
}

glm::vec3 meanLinearColor(const Rgba8Image& image) {
    float decoded[256];
    for (int code = 0; code < 256; ++code) decoded[code] = srgbDecode(float(code) / 255.0f);
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i + 3 < image.texels.size(); i += 4)
        sum +=
            glm::dvec3(decoded[image.texels[i]], decoded[image.texels[i + 1]], decoded[image.texels[i + 2]]);
    size_t count = image.texels.size() / 4;
    return count == 0 ? glm::vec3(0.0f) : glm::vec3(sum / double(count));
}

glm::vec4 meanCodes(const Rgba8Image& image) {
    glm::dvec4 sum(0.0);
    for (size_t i = 0; i + 3 < image.texels.size(); i += 4)
        sum += glm::dvec4(image.texels[i], image.texels[i + 1], image.texels[i + 2], image.texels[i + 3]);
    size_t count = image.texels.size() / 4;
    return count == 0 ? glm::vec4(0.0f) : glm::vec4(sum / (255.0 * double(count)));
}

}  // namespace fp
