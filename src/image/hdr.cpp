#include "image/hdr.h"

#include <stb_image.h>

#include <cmath>

#include "core/error.h"
#include "core/file.h"

namespace fp {

Image decodeHdr(const std::vector<std::uint8_t>& bytes, const std::string& name) {
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int size = int(bytes.size());
    // stb_image would also "load" a PNG or JPEG as floats; an environment must be real radiance.
    if (bytes.empty() || !stbi_is_hdr_from_memory(data, size))
        throw Error(name + ": not a Radiance HDR image (expected a file starting with #?RADIANCE or #?RGBE)");
    int width = 0, height = 0, channels = 0;
    float* pixels = stbi_loadf_from_memory(data, size, &width, &height, &channels, 3);
    if (!pixels) throw Error(name + ": cannot decode HDR image: " + stbi_failure_reason());
    Image image(width, height);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        glm::vec3 p(pixels[3 * i], pixels[3 * i + 1], pixels[3 * i + 2]);
        // RGBE cannot hold NaN or negative values, but a corrupt file must not smuggle them in.
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(p[c]) || p[c] < 0.0f) p[c] = 0.0f;
        image.pixels[i] = p;
    }
    stbi_image_free(pixels);
    return image;
}

Image readHdr(const std::string& path) {
    const std::string bytes = readFileBytes(path);
    return decodeHdr(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), path);
}

}  // namespace fp
