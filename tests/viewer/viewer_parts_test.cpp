// The viewer's small parts that need no window: tile planning, frame statistics, shader watching.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "viewer/frame_stats.h"
#include "render/heat_map.h"
#include "viewer/shader_watcher.h"
#include "viewer/tile_planner.h"

namespace fp {
namespace {

TEST(TilePlanner, SmallTilesWhenSlowWholeImageWhenFast) {
    TilePlanner::Options options;
    options.budgetSeconds = 0.03;
    options.initialSecondsPerPixel = 1e-6;  // a software renderer: 1 us per path
    TilePlanner planner(options);
    glm::ivec2 size(512, 512);
    int tile = planner.tileSize(size);
    // A tile takes about a third of the budget: 10 ms, 10000 pixels.
    EXPECT_GE(tile, 64);
    EXPECT_LE(tile, 112);
    EXPECT_EQ(tile % 16, 0);

    // A fast GPU: a whole pass fits in a tile's share, so a tile is the whole image.
    for (int i = 0; i < 40; ++i) planner.record(262144.0, 0.001);
    EXPECT_EQ(planner.tileSize(size), 512);
    EXPECT_EQ(planner.tileSize({640, 200}), 640);
    EXPECT_TRUE(planner.fits(0.01, 262144.0)) << "several passes per frame";
}

TEST(TilePlanner, OneSlowTileDoesNotCollapseTheTiles) {
    TilePlanner::Options options;
    options.initialSecondsPerPixel = 1e-6;
    TilePlanner planner(options);
    planner.record(10000.0, 0.5);  // a shader compiled on first use
    EXPECT_LE(planner.secondsPerPixel(), 2e-6);
}

TEST(TilePlanner, PassCostIsTheAverageOverWholePasses) {
    TilePlanner::Options options;
    options.initialSecondsPerPixel = 1e-6;
    TilePlanner planner(options);
    // Half the image is sky (nearly free), half is geometry (2 us per pixel): 1 us on average.
    for (int pass = 0; pass < 10; ++pass) {
        planner.record(1000.0, 0.0);
        planner.record(1000.0, 2e-3);
        planner.passDone();
    }
    EXPECT_NEAR(planner.passSeconds({100, 20}), 2000.0 * 1.0e-6, 1e-7);
    // An abandoned pass (a restart) does not count.
    planner.record(1000.0, 1.0);
    planner.passAbandoned();
    planner.record(1000.0, 1e-3);
    planner.passDone();
    EXPECT_NEAR(planner.passSeconds({100, 20}), 2000.0 * 1.0e-6, 1e-7);
}

TEST(TilePlanner, BudgetAndAverageTile) {
    TilePlanner::Options options;
    options.budgetSeconds = 0.03;
    options.initialSecondsPerPixel = 1e-6;
    TilePlanner planner(options);
    EXPECT_TRUE(planner.fits(0.0, 10000.0));
    EXPECT_FALSE(planner.fits(0.025, 10000.0));
    EXPECT_DOUBLE_EQ(TilePlanner::pixelsPerTile({100, 50}, 64), 2500.0);  // 2 x 1 tiles
    EXPECT_DOUBLE_EQ(TilePlanner::pixelsPerTile({100, 50}, 1000), 5000.0);
}

TEST(FrameStats, RatesOverTheRecentWindowAndMedianOverAll) {
    FrameStats stats(1.0);
    for (int i = 0; i < 10; ++i) stats.addFrame(0.1 * (i + 1), 0.1, 1000.0, 500.0);
    EXPECT_NEAR(stats.frameSeconds(), 0.1, 1e-12);
    EXPECT_NEAR(stats.pathsPerSecond(), 10000.0, 1e-6);
    EXPECT_NEAR(stats.samplesPerSecond(), 20.0, 1e-9);
    stats.addFrame(5.0, 0.5, 0.0, 500.0);  // an idle stretch: the old frames leave the window
    EXPECT_NEAR(stats.pathsPerSecond(), 0.0, 1e-12);
    EXPECT_EQ(stats.frames(), 11u);
    EXPECT_NEAR(stats.medianFrameSeconds(), 0.1, 1e-12);
    // The first frame (shader compilation) is left out of the steady rate.
    EXPECT_NEAR(stats.steadyPathsPerSecond(), 9000.0 / 1.4, 1e-6);
}

TEST(HeatMap, EndsAndStops) {
    EXPECT_EQ(heatMapColor(0.0f), glm::vec3(0.0f));
    EXPECT_EQ(heatMapColor(1.0f), glm::vec3(1.0f));
    EXPECT_EQ(heatMapColor(2.0f), glm::vec3(1.0f));
    EXPECT_EQ(heatMapColor(-1.0f), glm::vec3(0.0f));
    EXPECT_EQ(heatMapColor(0.8f), kHeatMapStops[4]);
    glm::vec3 mid = heatMapColor(0.1f);
    EXPECT_NEAR(mid.b, 0.5f, 1e-6f);
}

class ShaderWatcherTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() / ("fragpath_watch_" + std::to_string(getpid()));
        std::filesystem::create_directories(dir / "common");
        write("a.glsl", "void a() {}");
        write("common/b.glsl", "void b() {}");
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    void write(const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }
    // Moves the modification time, as an editor's save does, without waiting for the clock.
    void touch(const std::string& name, int seconds) {
        auto t = std::filesystem::last_write_time(dir / name);
        std::filesystem::last_write_time(dir / name, t + std::chrono::seconds(seconds));
    }
    std::filesystem::path dir;
};

TEST_F(ShaderWatcherTest, SeesEditsAdditionsAndRemovalsOfGlslFilesOnly) {
    ShaderWatcher watcher(dir.string(), 0.5);
    double t = 0.0;
    EXPECT_FALSE(watcher.poll(t += 1.0));

    touch("common/b.glsl", 5);
    EXPECT_TRUE(watcher.poll(t += 1.0)) << "an edit in a subdirectory";
    EXPECT_FALSE(watcher.poll(t += 1.0)) << "reported once";

    write("a.glsl", "void a() { int longer; }");  // same second, new size
    EXPECT_TRUE(watcher.poll(t += 1.0));

    write("notes.txt", "not a shader");
    EXPECT_FALSE(watcher.poll(t += 1.0));

    write("c.glsl", "");
    EXPECT_TRUE(watcher.poll(t += 1.0)) << "a new file";
    std::filesystem::remove(dir / "c.glsl");
    EXPECT_TRUE(watcher.poll(t += 1.0)) << "a removed file";
}

TEST_F(ShaderWatcherTest, PollsTheDiskAtMostOncePerInterval) {
    ShaderWatcher watcher(dir.string(), 0.5);
    EXPECT_FALSE(watcher.poll(10.0));
    touch("a.glsl", 5);
    EXPECT_FALSE(watcher.poll(10.2)) << "too soon after the last look";
    EXPECT_TRUE(watcher.poll(10.6));
}

TEST_F(ShaderWatcherTest, AMissingDirectoryIsNoChange) {
    ShaderWatcher watcher((dir / "missing").string());
    EXPECT_FALSE(watcher.poll(1.0));
}

}  // namespace
}  // namespace fp
