// `fragpath study` end to end on a tiny Cornell box and a two-scene set: every artefact is written with
// the expected contents, and bad requests fail with a clear message before any rendering.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "fragpath_runner.h"
#include "image/image.h"

namespace fp::test {
namespace {

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Width and height from a PNG's IHDR chunk, or (0, 0) if the file is not a PNG.
std::pair<int, int> pngSize(const std::string& path) {
    std::string bytes = readText(path);
    if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 ||
        bytes.compare(12, 4, "IHDR") != 0)
        return {0, 0};
    auto be32 = [&](size_t at) {
        return int((uint8_t(bytes[at]) << 24) | (uint8_t(bytes[at + 1]) << 16) |
                   (uint8_t(bytes[at + 2]) << 8) | uint8_t(bytes[at + 3]));
    };
    return {be32(16), be32(20)};
}

std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream in(line);
    std::string cell;
    while (std::getline(in, cell, ',')) cells.push_back(cell);
    return cells;
}

class StudyTest : public TempDirTest {};

TEST_F(StudyTest, WritesEveryArtefact) {
    const std::string out = path("out");
    CliRun run = runFragpath(
        "study --scenes cornell --size 16x16 --max-spp 4 --reference-spp 64 --integrators nee,naive --quiet "
        "--out " +
        out);
    ASSERT_EQ(run.exitCode, 0) << run.output;

    // The CSV: the documented header, then scene x integrators x denoisers x spp levels (1, 2, 4) rows.
    std::ifstream csv(out + "/study.csv");
    std::string header;
    std::getline(csv, header);
    EXPECT_EQ(
        header,
        "scene,integrator,denoiser,spp,render_seconds,render_cpu_seconds,denoise_seconds,total_seconds,rmse,"
        "rel_mse,ssim,flip");
    std::map<std::pair<std::string, std::string>, std::set<int>> levels;
    std::map<int, double> neeRawRmse, neeRawFlip;
    std::set<std::string> denoisers;
    int rows = 0;
    for (std::string line; std::getline(csv, line); ++rows) {
        std::vector<std::string> cells = splitCsvLine(line);
        ASSERT_EQ(cells.size(), 12u) << line;
        EXPECT_EQ(cells[0], "cornell") << line;
        cells.erase(cells.begin());  // the rest as before the scene column
        for (size_t i = 3; i < 9; ++i) {
            double v = std::strtod(cells[i].c_str(), nullptr);
            EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << line;
        }
        // SSIM lies in [-1, 1]: a noisy 16x16 image can correlate negatively with the reference.
        double ssim = std::strtod(cells[9].c_str(), nullptr);
        EXPECT_TRUE(std::isfinite(ssim) && ssim >= -1.0 && ssim <= 1.0) << line;
        // Mean FLIP lies in [0, 1].
        double flip = std::strtod(cells[10].c_str(), nullptr);
        EXPECT_TRUE(std::isfinite(flip) && flip >= 0.0 && flip <= 1.0) << line;
        int spp = std::stoi(cells[2]);
        levels[{cells[0], cells[1]}].insert(spp);
        denoisers.insert(cells[1]);
        if (cells[0] == "nee" && cells[1] == "none") {
            neeRawRmse[spp] = std::strtod(cells[7].c_str(), nullptr);
            neeRawFlip[spp] = flip;
        }
    }
    EXPECT_TRUE(denoisers.count("none"));
    EXPECT_EQ(rows, int(2 * denoisers.size() * 3));
    for (const auto& [series, spp] : levels) EXPECT_EQ(spp, (std::set<int>{1, 2, 4})) << series.first;
    // Expected MSE at N spp is var/N plus the 64-spp reference's var/64, so RMSE(4)/RMSE(1) is about
    // sqrt((1/4 + 1/64) / (1 + 1/64)) = 0.51; 0.8 leaves room for the spread of a 16x16 image's MSE.
    ASSERT_EQ(neeRawRmse.size(), 3u);
    EXPECT_LT(neeRawRmse[4], 0.8 * neeRawRmse[1]);
    // Less noise, less visible difference.
    EXPECT_LT(neeRawFlip[4], neeRawFlip[1]);

    // Plots from gnuplot, the script that drew them, the strip and the reference.
    EXPECT_TRUE(std::filesystem::exists(out + "/plots.gp"));
    for (const char* plot :
         {"cornell_error_vs_spp.png", "cornell_error_vs_time.png", "cornell_ssim_vs_spp.png"}) {
        EXPECT_GT(pngSize(out + "/" + plot).first, 0) << plot;
        EXPECT_GT(std::filesystem::file_size(out + "/" + plot), 5000u) << plot;
    }
    // nee's raw series extrapolates to the threshold (MSE ~ 1/N), so the roofline charts it.
    EXPECT_TRUE(std::filesystem::exists(out + "/cornell_roofline.gp"));
    EXPECT_GT(pngSize(out + "/cornell_roofline_nee.png").first, 0);
    // Columns 1 and 4 spp and the reference, 16 pixels each with 2-pixel gaps; a row per series. Labels
    // at text scale 1 (image/image_grid.h), padding 2: a header of 9 + 2 * 2 = 13 rows, and a label
    // column as wide as the widest row label, "naive + bilateral", plus 2 * 2. Its width from
    // stb_easy_font's advances: n 6, a 6, i 3, v 7, e 6 (28), ' ' 6, + 7, ' ' 6 (19), b 6, i 3, l 3,
    // a 6, t 5, e 6, r 5, a 6, l 3 (43): 90.
    std::pair<int, int> strip = pngSize(out + "/strip_cornell.png");
    EXPECT_EQ(strip.first, 90 + 2 * 2 + 3 * 16 + 2 * 2);
    EXPECT_EQ(strip.second, 13 + int(levels.size()) * 16 + (int(levels.size()) - 1) * 2);
    EXPECT_EQ(readImage(out + "/reference_cornell.exr").width, 16);

    std::string report = readText(out + "/report.md");
    EXPECT_NE(report.find("Thresholds used: **relMSE <= 0.0004**, **SSIM >= 0.98**, **FLIP <= 0.05**"),
              std::string::npos);
    EXPECT_NE(report.find("## Scene: cornell"), std::string::npos);
    EXPECT_NE(report.find("67 pixels per degree"), std::string::npos);
    EXPECT_NE(report.find("| metric | threshold | without a denoiser |"), std::string::npos);
    EXPECT_NE(report.find("| FLIP | <= 0.05 |"), std::string::npos);
    // The reference's own noise, against the threshold.
    EXPECT_NE(report.find("% of the threshold"), std::string::npos);
    EXPECT_NE(report.find("Weber"), std::string::npos);
    EXPECT_NE(report.find("| operation | FLOPs | from |"), std::string::npos);
    EXPECT_NE(report.find("| ray-triangle test (Moller-Trumbore) | 52 |"), std::string::npos);
    EXPECT_NE(report.find("RTX 3080"), std::string::npos);
    EXPECT_NE(report.find("within 4 years"), std::string::npos);

    // The saved reference can be loaded back for another study of the same size.
    run = runFragpath(
        "study --scenes cornell --size 16x16 --max-spp 2 --integrators nee --no-plots --quiet "
        "--reference " +
        out + "/reference_cornell.exr --out " + path("again"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(readText(path("again/report.md")).find("loaded from"), std::string::npos);
}

// Two scenes of the set in one run: a row set, a strip, a reference and a report section each.
TEST_F(StudyTest, StudiesSeveralScenesInOneRun) {
    const std::string out = path("set");
    CliRun run = runFragpath(
        "study --scenes cornell,environment --size 16x16 --max-spp 2 --reference-spp 16 --integrators nee "
        "--denoisers none --no-plots --quiet --flip-threshold 0.1 --ssim-threshold 0.9 --practice-frames 3 "
        "--practice-reference-spp 16 --out " +
        out);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::ifstream csv(out + "/study.csv");
    std::map<std::string, int> rowsPerScene;
    std::string line;
    std::getline(csv, line);  // header
    while (std::getline(csv, line)) ++rowsPerScene[splitCsvLine(line)[0]];
    // nee x none x (1, 2 spp) per scene.
    EXPECT_EQ(rowsPerScene, (std::map<std::string, int>{{"cornell", 2}, {"environment", 2}}));
    for (const char* scene : {"cornell", "environment"}) {
        EXPECT_EQ(readImage(out + "/reference_" + scene + ".exr").width, 16) << scene;
        EXPECT_GT(pngSize(out + "/strip_" + scene + ".png").first, 0) << scene;
    }
    std::string report = readText(out + "/report.md");
    size_t cornell = report.find("## Scene: cornell"), environment = report.find("## Scene: environment");
    ASSERT_NE(cornell, std::string::npos);
    ASSERT_NE(environment, std::string::npos);
    EXPECT_LT(cornell, environment);
    EXPECT_NE(report.find("**SSIM >= 0.9**, **FLIP <= 0.1**"), std::string::npos);
    // 16-spp references at 16x16 carry far more noise than a quarter of the 4e-4 threshold (the 64-spp
    // 64x64 Cornell reference adds about 0.0036, nine times it): each is flagged.
    size_t flag = report.find("raise --reference-spp");
    ASSERT_NE(flag, std::string::npos);
    EXPECT_LT(flag, environment);
    EXPECT_NE(report.find("raise --reference-spp", environment), std::string::npos);
    // The GPU table once, before the scenes; a roofline in each scene's section (its bytes and counts
    // are the scene's).
    size_t gpus = report.find("### GPUs");
    ASSERT_NE(gpus, std::string::npos);
    EXPECT_LT(gpus, cornell);
    EXPECT_EQ(report.find("### GPUs", gpus + 1), std::string::npos);
    size_t cornellRoofline = report.find("### Roofline", cornell);
    ASSERT_NE(cornellRoofline, std::string::npos);
    EXPECT_LT(cornellRoofline, environment);
    EXPECT_NE(report.find("### Roofline", environment), std::string::npos);
    // The practice runs once, on the first scene, judged by the study's --flip-threshold; its section and
    // the seed's claim follow the scenes and name it.
    size_t practice = report.find("## Practice:");
    ASSERT_NE(practice, std::string::npos);
    EXPECT_GT(practice, environment);
    EXPECT_EQ(report.find("## Practice:", practice + 1), std::string::npos);
    EXPECT_NE(report.find("on `cornell` (the first scene studied)", practice), std::string::npos);
    EXPECT_NE(report.find("- FLIP threshold: 0.1, the study's", practice), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(out + "/practice/moving/pipeline_1spp/frames.csv"));
    size_t claim = report.find("## The seed's claim, in both senses");
    ASSERT_NE(claim, std::string::npos);
    EXPECT_GT(claim, practice);
    EXPECT_NE(report.find("`cornell`, the first scene studied", claim), std::string::npos);
}

TEST_F(StudyTest, RejectsBadRequestsBeforeRendering) {
    auto expectError = [](const std::string& args, const std::string& message, const std::string& env = "") {
        CliRun run = env.empty() ? runFragpath(args) : runFragpath(args, env);
        EXPECT_EQ(run.exitCode, 1) << args << "\n" << run.output;
        EXPECT_NE(run.output.find(message), std::string::npos) << args << "\n" << run.output;
    };
    const std::string out = " --out " + path("out");
    expectError("study --integrators nee,warp" + out, "unknown integrator 'warp'");
    expectError("study --denoisers none,magic" + out, "unknown denoiser 'magic' (choose none");
    expectError("study --integrators nee,nee" + out, "'nee' is listed twice");
    expectError("study --scenes cornell --size 8x8" + out, "at least 11x11");
    expectError("study --scenes cornell,teapot" + out, "unknown scene 'teapot'");
    expectError("study --scenes cornell,environment --reference x.exr" + out, "--reference is one scene's");
    expectError("study --scenes cornell,environment --eye 0,1,2" + out, "--eye moves one scene's camera");
    expectError("study " + std::string(FP_SOURCE_DIR) + "/assets/cornell/cornell.json --scenes cornell" + out,
                "cannot be combined with a SCENE file");
    expectError("study --flip-threshold 1.5" + out, "--flip-threshold must be between 0 and 1");
    expectError("study --ssim-threshold 0" + out, "--ssim-threshold must be between 0 and 1");

    Image small(20, 20);
    writeImage(path("small.exr"), small);
    expectError("study --scenes cornell --size 16x16 --reference " + path("small.exr") + out,
                "is 20x20 but the study renders 16x16 (--size)");
    expectError("study --scenes cornell --reference " + path("missing.exr") + out, "missing.exr");

    std::ofstream(path("file")) << "not a directory";
    expectError("study --out " + path("file") + "/sub",
                "output directory " + path("file") + "/sub cannot be created");
    expectError("study" + out, "gnuplot, which is not on PATH", "LP_NUM_THREADS=2 PATH=/nonexistent");
}

}  // namespace
}  // namespace fp::test
