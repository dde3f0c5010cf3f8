#include "study/image_strip.h"

#include <algorithm>

#include "core/error.h"

namespace fp::study {

namespace {

constexpr int kGap = 2;
const glm::vec3 kGapColour(0.18f);  // mid grey after the sRGB encoding

void paste(Image& strip, const Image& source, const PixelRect& crop, int left, int top) {
    for (int y = 0; y < crop.height; ++y)
        for (int x = 0; x < crop.width; ++x) strip.at(left + x, top + y) = source.at(crop.x + x, crop.y + y);
}

}  // namespace

std::vector<int> stripLevels(int maxSpp) {
    std::vector<int> levels;
    for (int n : {1, 4, 16, 64})
        if (n <= maxSpp) levels.push_back(n);
    return levels;
}

PixelRect stripCrop(int width, int height) {
    int side = std::min({width, height, 128});
    return {(width - side) / 2, (height - side) / 2, side, side};
}

Image assembleStrip(const SweepResult& sweep, const Image& reference, const StripLayout& layout,
                    const PixelRect& crop) {
    const int columns = int(layout.columns.size()) + 1, rows = int(layout.rows.size());
    Image strip(columns * crop.width + (columns - 1) * kGap, rows * crop.height + (rows - 1) * kGap);
    std::fill(strip.pixels.begin(), strip.pixels.end(), kGapColour);
    for (int r = 0; r < rows; ++r) {
        const auto& [integrator, denoiser] = layout.rows[size_t(r)];
        const int top = r * (crop.height + kGap);
        for (int c = 0; c < columns; ++c) {
            const Image* image = &reference;
            if (c + 1 < columns) {
                auto it = sweep.images.find({integrator, denoiser, layout.columns[size_t(c)]});
                if (it == sweep.images.end())
                    throw Error("internal: no " + integrator + "/" + denoiser + " image at " +
                                std::to_string(layout.columns[size_t(c)]) + " spp for the strip");
                image = &it->second;
            }
            paste(strip, *image, crop, c * (crop.width + kGap), top);
        }
    }
    return strip;
}

}  // namespace fp::study
