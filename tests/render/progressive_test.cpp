// Progressive rendering as the viewer drives it: tiles, split views and restarts must give exactly
// the image a batch render gives, because a pixel's k-th sample is a pure function of (seed, pixel, k).
#include <gtest/gtest.h>

#include <cstring>

#include "render_test_util.h"
#include "scene/builtin_scene.h"

namespace fp::test {
namespace {

class Progressive : public CornellBoxSuite {
  protected:
    static RenderSettings settings() {
        RenderSettings s;
        s.width = 37;  // not a multiple of the tile size: partial tiles at the edges
        s.height = 23;
        s.maxDepth = 3;
        s.seed = 5;
        return s;
    }
    static Accumulation batch(const RenderSettings& s, int spp) {
        renderer_->configure(s, *scene_->camera);
        renderer_->render(spp);
        return renderer_->readback();
    }
};

bool sameSums(const Accumulation& a, const Accumulation& b) {
    return a.sum.size() == b.sum.size() &&
           std::memcmp(a.sum.data(), b.sum.data(), a.sum.size() * sizeof(glm::vec4)) == 0 &&
           std::memcmp(a.squares.data(), b.squares.data(), a.squares.size() * sizeof(glm::vec4)) == 0;
}

TEST_F(Progressive, TilesGiveTheBatchImageBitForBit) {
    Accumulation expected = batch(settings(), 3);
    renderer_->configure(settings(), *scene_->camera);
    int tiles = 0, completed = 0;
    while (completed < 3) {
        ++tiles;
        if (renderer_->renderTile(16)) ++completed;
    }
    EXPECT_EQ(tiles, 3 * 3 * 2) << "37x23 in 16x16 tiles is 3x2 tiles per sample";
    EXPECT_EQ(renderer_->samples(), 3);
    EXPECT_TRUE(sameSums(renderer_->readback(), expected));
}

TEST_F(Progressive, AnUnfinishedPassCountsOnlyCompletedSamples) {
    renderer_->configure(settings(), *scene_->camera);
    EXPECT_FALSE(renderer_->renderTile(16));
    EXPECT_EQ(renderer_->samples(), 0);
    Accumulation acc = renderer_->readback();
    // The first tile (bottom-left 16x16) has one sample, the rest none. Rows are top first here.
    EXPECT_EQ(acc.sum[size_t(22) * 37].w, 1.0f);
    EXPECT_EQ(acc.sum[size_t(22) * 37 + 16].w, 0.0f);
    EXPECT_EQ(acc.sum[0].w, 0.0f);
}

TEST_F(Progressive, ConfigureRestartsAccumulation) {
    batch(settings(), 2);
    renderer_->configure(settings(), *scene_->camera);
    EXPECT_EQ(renderer_->samples(), 0);
    for (const glm::vec4& s : renderer_->readback().sum) ASSERT_EQ(s, glm::vec4(0.0f));
}

TEST_F(Progressive, SplitViewHalvesEqualTheirOwnFullRenders) {
    RenderSettings left = settings(), right = settings();
    right.integrator = Integrator::Naive;
    right.maxDepth = 2;
    Accumulation a = batch(left, 2), b = batch(right, 2);
    RenderSettings split = settings();
    split.split = SplitView{Integrator::Naive, 2};
    for (bool tiled : {false, true}) {
        renderer_->configure(split, *scene_->camera);
        if (tiled)
            while (renderer_->samples() < 2) renderer_->renderTile(8);
        else
            renderer_->render(2);
        Accumulation s = renderer_->readback();
        int half = 37 / 2;
        for (int y = 0; y < 23; ++y)
            for (int x = 0; x < 37; ++x) {
                size_t i = size_t(y) * 37 + size_t(x);
                const Accumulation& expected = x < half ? a : b;
                ASSERT_EQ(s.sum[i], expected.sum[i]) << "pixel " << x << "," << y << (tiled ? " tiled" : "");
            }
    }
}

}  // namespace
}  // namespace fp::test
