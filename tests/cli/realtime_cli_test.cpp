// `fragpath realtime` as a user runs it: the frames and frames.csv it writes, and its refusals.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/fragpath_runner.h"
#include "core/text.h"
#include "image/image.h"

namespace fp::test {
namespace {

class RealtimeCli : public TempDirTest {};

std::vector<std::vector<std::string>> readCsv(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::stringstream s(line);
        std::string field;
        while (std::getline(s, field, ',')) fields.push_back(field);
        if (!line.empty() && line.back() == ',') fields.push_back("");
        rows.push_back(fields);
    }
    return rows;
}

TEST_F(RealtimeCli, WritesEveryFrameAndARowOfFiguresPerFrame) {
    CliRun run =
        runFragpath("realtime --size 32x32 --frames 3 --spp 2 --reference-spp 8 --out " + path("out"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (int f = 0; f < 3; ++f)
        EXPECT_TRUE(std::filesystem::exists(path("out/frame_000" + std::to_string(f) + ".png"))) << f;
    EXPECT_TRUE(std::filesystem::exists(path("out/strip.png")));
    auto rows = readCsv(path("out/frames.csv"));
    ASSERT_EQ(rows.size(), 4u);
    const std::vector<std::string> header = {
        "frame", "ms",      "spp",  "trace_ms", "temporal_ms", "filter_ms", "mean_history_frames",
        "rmse",  "rel_mse", "ssim", "flip",     "flicker"};
    EXPECT_EQ(rows[0], header);
    for (size_t r = 1; r < rows.size(); ++r) {
        ASSERT_EQ(rows[r].size(), header.size()) << r;
        EXPECT_EQ(rows[r][0], std::to_string(r - 1));
        EXPECT_EQ(rows[r][2], "2");  // --spp fixes the samples per frame
        // The history grows by one frame a frame (the orbit barely moves in 3 frames at 10 degrees/s).
        EXPECT_NEAR(std::stod(rows[r][6]), double(r), 0.2) << r;
        double flip = std::stod(rows[r][10]);
        EXPECT_GT(flip, 0.0);
        EXPECT_LT(flip, 1.0);
        EXPECT_EQ(rows[r][11].empty(), r == 1) << "flicker needs a previous frame";
    }
}

// Runs over the same path share references through --reference-cache: a reference found there is the
// one used (here one replaced on purpose by a uniform 1000, which no render of the box comes near), and
// a cache made for other settings or another path is refused, not silently used.
TEST_F(RealtimeCli, ReusesItsCachedReferencesAndRefusesAnotherRunsCache) {
    const std::string options =
        "realtime --size 32x32 --frames 2 --spp 1 --reference-spp 8 --reference-cache " + path("refs");
    CliRun first = runFragpath(options + " --out " + path("a"));
    ASSERT_EQ(first.exitCode, 0) << first.output;
    Image uniform(32, 32);
    for (glm::vec3& p : uniform.pixels) p = glm::vec3(1000.0f);
    writeImage(path("refs/reference_0001.exr"), uniform);
    CliRun second = runFragpath(options + " --out " + path("b"));
    ASSERT_EQ(second.exitCode, 0) << second.output;
    auto a = readCsv(path("a/frames.csv")), b = readCsv(path("b/frames.csv"));
    ASSERT_EQ(a.size(), 3u);
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(b[1][7], a[1][7]) << "frame 0: the same frame against the same cached reference";
    EXPECT_LT(std::stod(a[2][7]), 10.0);
    EXPECT_GT(std::stod(b[2][7]), 900.0) << "frame 1 was judged against the cached uniform 1000";

    CliRun otherPath = runFragpath(options + " --orbit-speed 40 --out " + path("c"));
    EXPECT_EQ(otherPath.exitCode, 1);
    EXPECT_NE(otherPath.output.find("another camera"), std::string::npos) << otherPath.output;
    CliRun otherSettings = runFragpath(options + " --max-depth 2 --out " + path("d"));
    EXPECT_EQ(otherSettings.exitCode, 1);
    EXPECT_NE(otherSettings.output.find("other settings"), std::string::npos) << otherSettings.output;
    EXPECT_EQ(
        runFragpath("realtime --frames 1 --reference-cache " + path("r") + " --out " + path("e")).exitCode, 2)
        << "a cache without --reference-spp";
}

// The strip's labels (image/image_grid.h) are white whatever the exposure and tone curve: at -3 stops
// under Reinhard a radiance of 1 would show as 0.11 (a dark grey). One frame, no reference: one tile
// and one row label, "frames" (advances f 6, r 5, a 6, m 7, e 6, s 5: 35) + 2 * 2 padding, so the strip
// is 39 + 32 = 71 wide and 13 (9 text rows + 2 * 2) + 32 = 45 high.
TEST_F(RealtimeCli, StripLabelsAreWhiteUnderAnyDisplay) {
    CliRun run = runFragpath(
        "realtime --size 32x32 --frames 1 --spp 1 --exposure -3 --tonemap reinhard --out " + path("out"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    Image strip = readImageOrPng(path("out/strip.png"));
    ASSERT_EQ(strip.width, 71);
    ASSERT_EQ(strip.height, 45);
    int white = 0;
    for (int y = 0; y < 13; ++y)  // the header, over the tile: "frame 0"
        for (int x = 39; x < 71; ++x) white += strip.at(x, y) == glm::vec3(1.0f);
    int labelWhite = 0;
    for (int y = 13; y < 45; ++y)
        for (int x = 0; x < 39; ++x) labelWhite += strip.at(x, y) == glm::vec3(1.0f);
    EXPECT_GT(white, 20);
    EXPECT_GT(labelWhite, 20);
}

TEST_F(RealtimeCli, RefusesWhatItCannotRender) {
    EXPECT_EQ(runFragpath("realtime --frames 1").exitCode, 2);  // no --out
    CliRun bad = runFragpath("realtime --temporal maybe --out " + path("o"));
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("expected on or off"), std::string::npos) << bad.output;
    CliRun missing = runFragpath("realtime --camera-path " + path("none.json") + " --out " + path("o"));
    EXPECT_NE(missing.exitCode, 0);
    EXPECT_NE(missing.output.find("none.json"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace fp::test
