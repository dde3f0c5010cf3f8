// `fragpath render --denoise NAME --denoised-out FILE`: -o keeps the raw samples, the denoised image
// goes to its own file, and every half-given or conflicting combination is refused before rendering.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/fragpath_runner.h"
#include "image/image.h"
#include "image/image_stats.h"
#include "render/partial_render.h"

namespace fp {
namespace {

namespace fs = std::filesystem;

class DenoiseCli : public test::TempDirTest {
  protected:
    test::CliRun run(const std::string& args) {
        return test::runFragpath("render --size 16x16 --spp 4 " + args);
    }
    void expectError(const std::string& args, const std::string& fragment) {
        test::CliRun r = run(args);
        EXPECT_EQ(r.exitCode, 1) << r.output;
        EXPECT_NE(r.output.find(fragment), std::string::npos)
            << "expected '" << fragment << "' in: " << r.output;
        EXPECT_TRUE(fs::is_empty(dir_)) << "nothing may be written: " << args;
    }
};

TEST_F(DenoiseCli, WritesTheRawSamplesToOutputAndTheDenoisedImageToItsOwnFile) {
    std::string raw = path("raw.exr"), plain = path("plain.exr");
    for (const char* name : {"bilateral", "atrous"}) {
        std::string denoised = path(std::string(name) + ".exr");
        test::CliRun r = run(std::string("--denoise ") + name + " -o " + raw + " --denoised-out " + denoised);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        Image image = readImage(denoised);
        EXPECT_EQ(image.width, 16);
        EXPECT_TRUE(allFinite(image));
        EXPECT_NE(image.pixels, readImage(raw).pixels) << name << " changed nothing";
    }
    // -o is the same render as without a denoiser (bit for bit) and still a resumable partial render.
    ASSERT_EQ(run("-o " + plain).exitCode, 0);
    EXPECT_EQ(readImage(raw).pixels, readImage(plain).pixels);
    EXPECT_EQ(readPartial(raw).samples(), 4u);
    // none: the denoised file is the raw mean.
    ASSERT_EQ(run("--denoise none -o " + raw + " --denoised-out " + path("none.pfm")).exitCode, 0);
    EXPECT_EQ(readImage(path("none.pfm")).pixels, readImage(raw).pixels);
}

TEST_F(DenoiseCli, RefusesUnknownNamesAndHalfGivenOrConflictingOutputs) {
    expectError("--denoise nlmeans -o " + path("a.png") + " --denoised-out " + path("b.png"),
                "unknown denoiser 'nlmeans' (choose none, bilateral or atrous)");
    expectError("--denoise atrous -o " + path("a.png"), "--denoise atrous needs --denoised-out FILE");
    expectError("-o " + path("a.png") + " --denoised-out " + path("b.png"), "--denoised-out needs --denoise");
    expectError("--denoise atrous -o " + path("a.png") + " --denoised-out " + path("a.png"),
                "name the same file");
    expectError("--denoise atrous -o " + path("a.png") + " --denoised-out " + path("b.jpg"),
                "unknown image format");
}

TEST_F(DenoiseCli, HelpNamesTheFlags) {
    test::CliRun r = test::runFragpath("render --help");
    EXPECT_NE(r.output.find("--denoise NAME"), std::string::npos);
    EXPECT_NE(r.output.find("--denoised-out FILE"), std::string::npos);
}

}  // namespace
}  // namespace fp
