#pragma once
// Small PNG textures written by the tests themselves (through stb_image_write, as the renderer's PNG
// writer does), so that every texture test states its texels.
#include <stb_image_write.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fp::test {

// A PNG of `width` x `height` RGBA texels (4 bytes each, top row first), as file bytes.
inline std::string pngBytes(int width, int height, const std::vector<uint8_t>& rgba) {
    std::string out;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
    };
    if (!stbi_write_png_to_func(append, &out, width, height, 4, rgba.data(), width * 4)) return "";
    return out;
}

// A PNG of `channels` (1 grey, 2 grey + alpha, 3 RGB, 4 RGBA) bytes per texel, as file bytes.
inline std::string pngBytes(int width, int height, int channels, const std::vector<uint8_t>& texels) {
    std::string out;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
    };
    if (!stbi_write_png_to_func(append, &out, width, height, channels, texels.data(), width * channels))
        return "";
    return out;
}

// A checker of two colours: texel (x, y) is `a` where x + y is even, else `b` (alpha 255).
using Rgb8 = std::array<uint8_t, 3>;

inline std::vector<uint8_t> checkerTexels(int width, int height, Rgb8 a, Rgb8 b) {
    // Written texel by texel: GCC 12 warns (-Wstringop-overflow, falsely) about inserting a list here.
    std::vector<uint8_t> rgba(size_t(width) * size_t(height) * 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Rgb8& c = (x + y) % 2 == 0 ? a : b;
            uint8_t* texel = &rgba[(size_t(y) * size_t(width) + size_t(x)) * 4];
            texel[0] = c[0];
            texel[1] = c[1];
            texel[2] = c[2];
            texel[3] = 255;
        }
    return rgba;
}

}  // namespace fp::test
