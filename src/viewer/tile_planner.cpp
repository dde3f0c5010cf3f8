#include "viewer/tile_planner.h"

#include <algorithm>
#include <cmath>

namespace fp {

TilePlanner::TilePlanner(const Options& options)
    : options_(options),
      secondsPerPixel_(options.initialSecondsPerPixel),
      passSecondsPerPixel_(options.initialSecondsPerPixel) {}

int TilePlanner::tileSize(glm::ivec2 size) const {
    int whole = std::max({size.x, size.y, 1});
    double pixels = options_.budgetSeconds * options_.tileFraction / secondsPerPixel_;
    if (pixels >= double(size.x) * double(size.y)) return whole;
    // Multiples of 16 keep tile edges on llvmpipe's own 16-pixel raster blocks.
    int side = int(std::sqrt(pixels)) / 16 * 16;
    return std::clamp(side, options_.minTile, whole);
}

double TilePlanner::pixelsPerTile(glm::ivec2 size, int tile) {
    tile = std::max(tile, 1);
    double tiles = double((size.x + tile - 1) / tile) * double((size.y + tile - 1) / tile);
    return double(size.x) * double(size.y) / std::max(tiles, 1.0);
}

void TilePlanner::record(double pixels, double seconds) {
    if (!(pixels > 0.0) || !(seconds >= 0.0)) return;
    double measured = std::max(seconds / pixels, 1e-12);
    // Smoothed, and one slow tile (a shader compiled on first use, another process taking the CPU) can
    // at most double the estimate, so it does not shrink the tiles to nothing for many frames.
    secondsPerPixel_ = std::min(2.0 * secondsPerPixel_, 0.5 * (secondsPerPixel_ + measured));
    passPixels_ += pixels;
    passSeconds_ += seconds;
}

void TilePlanner::passDone() {
    if (passPixels_ > 0.0) {
        double measured = std::max(passSeconds_ / passPixels_, 1e-12);
        passSecondsPerPixel_ = std::min(2.0 * passSecondsPerPixel_, 0.5 * (passSecondsPerPixel_ + measured));
    }
    passAbandoned();
}

bool TilePlanner::fits(double elapsed, double pixels) const {
    return elapsed + secondsPerPixel_ * pixels <= options_.budgetSeconds;
}

}  // namespace fp
