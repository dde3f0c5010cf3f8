#include "study/image_strip.h"

#include <algorithm>

#include "core/error.h"
#include "image/image_grid.h"

namespace fp::study {

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

GridLabels stripLabels(const StripLayout& layout) {
    GridLabels labels;
    for (int spp : layout.columns) labels.columns.push_back(std::to_string(spp) + " spp");
    labels.columns.push_back("reference");
    for (const auto& [integrator, denoiser] : layout.rows)
        labels.rows.push_back(denoiser == "none" ? integrator : integrator + " + " + denoiser);
    return labels;
}

Image assembleStrip(const SweepResult& sweep, const Image& reference, const StripLayout& layout,
                    const PixelRect& crop) {
    std::vector<std::vector<const Image*>> tiles;
    for (const auto& [integrator, denoiser] : layout.rows) {
        std::vector<const Image*>& row = tiles.emplace_back();
        for (int spp : layout.columns) {
            auto it = sweep.images.find({integrator, denoiser, spp});
            if (it == sweep.images.end())
                throw Error("internal: no " + integrator + "/" + denoiser + " image at " +
                            std::to_string(spp) + " spp for the strip");
            row.push_back(&it->second);
        }
        row.push_back(&reference);
    }
    return assembleGrid(tiles, crop, stripLabels(layout));
}

}  // namespace fp::study
