#pragma once
// The image strip: the same crop of the image at several sample counts side by side, one row per
// integrator and denoiser, the reference last in every row; a grey gap separates the tiles, a header
// names the columns ("4 spp", "reference") and a label column the rows ("nee + atrous"; the integrator
// alone for the raw image), laid out by image/image_grid.h.
#include <string>
#include <vector>

#include "image/image.h"
#include "image/image_grid.h"
#include "image/image_stats.h"
#include "study/sweep.h"

namespace fp::study {

// The spp levels the strip shows, of those the sweep renders.
std::vector<int> stripLevels(int maxSpp);
// The centred square crop of at most 128 pixels a side.
PixelRect stripCrop(int width, int height);

struct StripLayout {
    std::vector<std::pair<std::string, std::string>> rows;  // (integrator, denoiser), top to bottom
    std::vector<int> columns;                               // spp, left to right; then the reference
};

// The labels of the strip's columns and rows.
GridLabels stripLabels(const StripLayout& layout);

// Linear radiance of the strip, to be written as PNG with the usual tone map. Throws fp::Error if an
// image the layout names is missing.
Image assembleStrip(const SweepResult& sweep, const Image& reference, const StripLayout& layout,
                    const PixelRect& crop);

}  // namespace fp::study
