#include "render/view_image.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/text.h"
#include "image/file_io.h"
#include "image/png.h"
#include "image/tone_map.h"
#include "render/heat_map.h"

namespace fp {

void writeRgb8Png(const std::string& path, glm::ivec2 size, const std::vector<std::uint8_t>& rgb) {
    try {
        writeFileAtomically(path, encodeRgb8Png(size.x, size.y, rgb));
    } catch (const Error& e) {
        throw Error("cannot write '" + path + "': " + e.what());
    }
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

void writeRenderedView(const std::string& path, const Image& mean, View view, const DisplaySettings& tone) {
    if (lowerCaseExtension(path) != ".png" ||
        (view != View::Depth && view != View::Cost && !isCountView(view))) {
        writeImage(path, mean, tone);
        return;
    }
    glm::vec3 least(INFINITY), largest(0.0f);
    for (const glm::vec3& p : mean.pixels)
        for (int c = 0; c < 3; ++c)
            if (std::isfinite(p[c]) && p[c] > 0.0f) {
                least[c] = std::min(least[c], p[c]);
                largest[c] = std::max(largest[c], p[c]);
            }
    if (isCountView(view)) {
        writeViewImage(path, mean, {tone, std::max(largest.r, 1.0f), false});
        return;
    }
    // Depth from the nearest hit (black) to the farthest (white), misses black; cost's three counts
    // each from 0 to their largest.
    Image scaled = mean;
    for (glm::vec3& p : scaled.pixels)
        for (int c = 0; c < 3; ++c) {
            float low = view == View::Depth ? least[c] : 0.0f, span = largest[c] - low;
            p[c] = std::isfinite(p[c]) && p[c] > 0.0f && span > 0.0f
                       ? std::clamp((p[c] - low) / span, 0.0f, 1.0f)
                       : 0.0f;
        }
    writeImage(path, scaled, {0.0f, ToneMap::Clamp});
}

}  // namespace fp
