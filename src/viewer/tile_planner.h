#pragma once
// How much rendering fits in one frame. A 512x512 pass takes ~0.3 s on a software renderer, so a frame
// renders square tiles (Renderer::renderTile) until its time budget is used, and the viewer still
// handles input 20+ times a second. The tile size follows the measured cost per pixel so that a tile
// takes a fraction of the budget; on a fast GPU a tile covers the whole image and a frame takes
// several samples. No OpenGL here: the caller times the tiles (after glFinish) and reports them.
#include <glm/glm.hpp>

namespace fp {

class TilePlanner {
  public:
    struct Options {
        double budgetSeconds = 0.033;          // rendering time per frame
        double tileFraction = 1.0 / 3.0;       // a tile should take this share of the budget
        double initialSecondsPerPixel = 2e-6;  // a guess (llvmpipe, Cornell box) until measured
        int minTile = 16;
    };

    TilePlanner() : TilePlanner(Options{}) {}
    explicit TilePlanner(const Options& options);

    // The side of the tiles for the next pass over an image of `size`: the whole image (its larger side)
    // when a full pass fits in one tile's share of the budget. Keep it for the whole pass, since the
    // renderer numbers tiles by their size.
    int tileSize(glm::ivec2 size) const;
    // Pixels in one tile of a pass with tiles of `tile`, on average (edge tiles are smaller).
    static double pixelsPerTile(glm::ivec2 size, int tile);

    // Reports a finished tile of `pixels` that took `seconds` (including the wait for the GPU).
    void record(double pixels, double seconds);
    // Reports that the tiles recorded since the last call completed a pass over the whole image.
    void passDone();
    // Starts over without a pass in progress (accumulation restarted).
    void passAbandoned() { passPixels_ = passSeconds_ = 0.0; }
    // Whether another tile of `pixels` fits when `elapsed` of this frame's budget is used.
    bool fits(double elapsed, double pixels) const;

    // The recent tiles' cost. Costs differ across an image (a tile of sky is nearly free), so this
    // follows the region being rendered; it sizes the tiles.
    double secondsPerPixel() const { return secondsPerPixel_; }
    double budgetSeconds() const { return options_.budgetSeconds; }
    // The viewer shrinks the budget when drawing the window itself takes long (large windows).
    void setBudgetSeconds(double seconds) { options_.budgetSeconds = seconds; }
    // Seconds a full pass over `size` is expected to take, from the average cost of whole passes.
    double passSeconds(glm::ivec2 size) const {
        return passSecondsPerPixel_ * double(size.x) * double(size.y);
    }

  private:
    Options options_;
    double secondsPerPixel_;
    double passSecondsPerPixel_;
    double passPixels_ = 0.0, passSeconds_ = 0.0;  // of the pass in progress
};

}  // namespace fp
