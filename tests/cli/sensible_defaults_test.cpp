// Sensible defaults, as a user meets them (issue 18, item 6; issue 34, item 2): a scene without light of
// its own gets the studio environment and a note, in every front end (the native reference, which has
// constant skies only, the uniform white sky of radiance 1), `--environment 1` the uniform sky and
// `--environment none` keeps it black; a missing texture gets a warning and the magenta and black
// checker, and `--strict` makes every such warning an error (the default light is not one);
// `--environment FILE` and scene files take .exr maps as well as .hdr.
//
// The checks use an open quad of Lambertian reflectance k under the uniform sky at max depth 1: each
// point of it sees the whole sky over its hemisphere, so its radiance is exactly k (the white furnace's
// answer for one bounce), and with BSDF sampling (cosine-weighted, every direction escaping to radiance
// 1) every sample is k: no noise at all.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "cli/fragpath_runner.h"
#include "image/exr.h"
#include "image/hdr.h"
#include "image/image.h"
#include "image/image_stats.h"

namespace fp {
namespace {

namespace fs = std::filesystem;
using test::CliRun;
using test::runFragpath;

const std::string kNative = fs::path(FP_BINARY).parent_path().string() + "/fragpath_native";
const glm::vec3 kAlbedo(0.25f, 0.5f, 0.75f);
const char* kNoLight =
    "no light of its own: lit by the studio environment (--environment none keeps it dark)";
const char* kNativeNoLight =
    "no light of its own: lit by a uniform white sky of radiance 1 (--environment none keeps it dark)";

// The unit quad in z = 0, facing -z (toward the camera below), texture coordinates = (x, y).
const char* kQuadObj =
    "mtllib quad.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "usemtl quad\n"
    "f 1/1 4/4 3/3 2/2\n";

// The camera looks at the quad's centre along +z from 2 units away; the quad fills the middle of the
// image (pixels 5 to 27 of 32) with sky around it.
const std::string kCamera = " --eye 0.5,0.5,-2 --target 0.5,0.5,0 --up 0,1,0 --fov 40";
constexpr int kSize = 32;

class SensibleDefaults : public test::TempDirTest {
  protected:
    void SetUp() override {
        TempDirTest::SetUp();
        write("quad.mtl", "newmtl quad\nKd 0.25 0.5 0.75\n");
        quad_ = write("quad.obj", kQuadObj);
    }
    // `fragpath render ARGS` of 32x32 pixels to a PFM, which must succeed; the image.
    Image render(const std::string& args, CliRun* run = nullptr) {
        std::string out = path("out.pfm");
        fs::remove(out);
        CliRun r = runFragpath("render " + args + " --size 32x32 --quiet -o " + out);
        EXPECT_EQ(r.exitCode, 0) << r.output;
        if (run) *run = r;
        return r.exitCode == 0 ? readImage(out) : Image();
    }
    std::string quad_;
};

// The mean and the standard error of the mean of a 4x4 block of pixels.
struct BlockEstimate {
    glm::dvec3 mean{0.0}, standardError{0.0};
};
BlockEstimate block(const Image& image, int x0, int y0) {
    BlockEstimate e;
    glm::dvec3 sumSquares(0.0);
    for (int y = y0; y < y0 + 4; ++y)
        for (int x = x0; x < x0 + 4; ++x) {
            glm::dvec3 p(image.at(x, y));
            e.mean += p / 16.0;
            sumSquares += p * p / 16.0;
        }
    glm::dvec3 variance = glm::max(sumSquares - e.mean * e.mean, glm::dvec3(0.0)) * (16.0 / 15.0);
    e.standardError = glm::sqrt(variance / 16.0);
    return e;
}

// Every 4x4 block inside the quad (pixels 8 to 23) shows k: exactly with `exact`, else within five
// standard errors, which must be small enough (2 % of k) for the check to mean something.
void expectAlbedoBlocks(const Image& image, bool exact) {
    ASSERT_EQ(image.width, kSize);
    for (int by = 8; by < 24; by += 4)
        for (int bx = 8; bx < 24; bx += 4) {
            BlockEstimate e = block(image, bx, by);
            for (int c = 0; c < 3; ++c) {
                double k = kAlbedo[c];
                if (exact) {
                    EXPECT_NEAR(e.mean[c], k, 1e-5 * k) << "block " << bx << "," << by << " channel " << c;
                    EXPECT_LT(e.standardError[c], 1e-5 * k) << "BSDF sampling leaves no noise here";
                } else {
                    EXPECT_NEAR(e.mean[c], k, 5.0 * e.standardError[c] + 1e-6)
                        << "block " << bx << "," << by << " channel " << c;
                    EXPECT_LT(e.standardError[c], 0.02 * k);
                }
            }
        }
}

// The sky seen directly at the image's corners: radiance 1 exactly.
void expectSkyCorners(const Image& image) {
    for (auto [x, y] : {std::pair{0, 0}, {kSize - 1, 0}, {0, kSize - 1}, {kSize - 1, kSize - 1}})
        EXPECT_EQ(image.at(x, y), glm::vec3(1.0f)) << "pixel " << x << "," << y;
}

TEST_F(SensibleDefaults, TheUniformSkyIsAConstantEnvironmentOfOne) {
    CliRun run;
    Image bsdf = render(quad_ + kCamera + " --environment 1 --integrator bsdf --max-depth 1 --spp 4", &run);
    EXPECT_EQ(run.output.find("no light"), std::string::npos) << run.output;
    expectAlbedoBlocks(bsdf, true);
    expectSkyCorners(bsdf);
    // The default integrator, nee, samples the sky too: the same answer within its noise.
    Image nee = render(quad_ + kCamera + " --environment 1,1,1 --max-depth 1 --spp 64");
    expectAlbedoBlocks(nee, false);
    expectSkyCorners(nee);
    // A colour scales it channel by channel: the sky seen directly is the colour, the quad k times it.
    Image tinted = render(quad_ + kCamera + " --environment 0.5,1,2 --integrator bsdf --max-depth 1 --spp 4");
    EXPECT_EQ(tinted.at(0, 0), glm::vec3(0.5f, 1.0f, 2.0f));
    EXPECT_NEAR(tinted.at(16, 16).x, 0.5f * kAlbedo.x, 1e-5f);
    EXPECT_NEAR(tinted.at(16, 16).z, 2.0f * kAlbedo.z, 1e-5f);
}

TEST_F(SensibleDefaults, ASceneWithoutLightGetsTheStudioEnvironmentAndANote) {
    CliRun run;
    const std::string args = quad_ + kCamera + " --max-depth 2 --spp 4";
    Image studio = render(args, &run);
    EXPECT_NE(run.output.find("note: " + quad_ + ": " + kNoLight), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
    EXPECT_EQ(studio.pixels, render(args + " --environment studio").pixels) << "the studio environment";
    EXPECT_NE(studio.pixels, render(args + " --environment 1").pixels);
    for (const glm::vec3& p : studio.pixels) ASSERT_GT(p.y, 0.0f) << "the quad lit, the backdrop not black";
}

TEST_F(SensibleDefaults, EnvironmentNoneKeepsItBlack) {
    CliRun run;
    Image image = render(quad_ + kCamera + " --environment none --max-depth 3 --spp 2", &run);
    EXPECT_EQ(run.output.find("no light"), std::string::npos) << run.output;
    ASSERT_EQ(image.width, kSize);
    for (const glm::vec3& p : image.pixels) ASSERT_EQ(p, glm::vec3(0.0f));
    // `default` is the default.
    const std::string args = quad_ + kCamera + " --integrator bsdf --max-depth 1 --spp 1";
    EXPECT_EQ(render(args + " --environment default").pixels, render(args).pixels);
}

TEST_F(SensibleDefaults, ALitSceneIsLeftAlone) {
    // The built-in Cornell box has its lamp: no sky, no warning, the same image with --environment none.
    CliRun run;
    Image cornell = render("--spp 2", &run);
    EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
    EXPECT_EQ(cornell.pixels, render("--spp 2 --environment none").pixels);
    // And a scene file's own environment stays, unless --environment none removes it.
    std::string scene =
        write("scene.json", R"({"mesh": "quad.obj", "environment": {"color": [0.5, 0.5, 0.5]}})");
    Image own = render(scene + kCamera + " --integrator bsdf --max-depth 1 --spp 1", &run);
    EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
    EXPECT_EQ(own.at(0, 0), glm::vec3(0.5f));
    EXPECT_EQ(render(scene + kCamera + " --environment none --spp 1").at(0, 0), glm::vec3(0.0f));
}

CliRun run(const std::string& command) {
    return test::runCommand(command);
}

TEST_F(SensibleDefaults, TheNativeReferenceGetsTheSameSky) {
    std::string out = path("native.pfm");
    CliRun r = run(kNative + " " + quad_ + kCamera + " --size 32x32 --max-depth 1 --spp 64 -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(kNativeNoLight), std::string::npos) << r.output;
    Image native = readImage(out);
    expectAlbedoBlocks(native, false);
    expectSkyCorners(native);
    // It has constant skies only: a map is a clear error, not a different image.
    Image sky(4, 2);
    for (glm::vec3& p : sky.pixels) p = glm::vec3(1.0f);
    writeExr(path("sky.exr"), sky);
    r = run(kNative + " " + quad_ + " --environment " + path("sky.exr") + " -o " + out);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("an environment map (the native reference has a constant colour only)"),
              std::string::npos)
        << r.output;
    r = run(kNative + " " + quad_ + " --environment none --size 8x8 -o " + out);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    for (const glm::vec3& p : readImage(out).pixels) ASSERT_EQ(p, glm::vec3(0.0f));
}

TEST_F(SensibleDefaults, EveryFrontEndThatLoadsAScene) {
    // study: its reference is rendered with the studio environment (not black), after the note.
    CliRun r = runFragpath("study " + quad_ + kCamera +
                           " --size 16x16 --max-spp 1 --reference-spp 2 --integrators bsdf --denoisers none "
                           "--count-spp 1 --no-plots --quiet --max-depth 1 --out " +
                           path("study"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(kNoLight), std::string::npos) << r.output;
    Image reference = readImage(path("study/reference_quad.exr"));  // named after quad.obj
    EXPECT_GT(reference.at(0, 0).y, 0.0f);                          // the backdrop
    // The quad, lit (nee, 2 spp): it faces -z, away from the studio's key and fill, and sees its sky and
    // floor, about a third of its albedo (0.17 of 0.5 measured); unlit, it would be 0.
    EXPECT_GT(meanColor(reference, PixelRect{6, 6, 4, 4}).y, 0.15 * kAlbedo.y);
    // bench: the note, with --strict too (the default light is not a repair).
    r = runFragpath("bench " + quad_ + " --size 8x8 --spp 1 --runs 1");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(kNoLight), std::string::npos) << r.output;
    r = runFragpath("bench " + quad_ + " --size 8x8 --spp 1 --runs 1 --strict");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(kNoLight), std::string::npos) << r.output;
    r = runFragpath("bench --suite --environment none");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("--environment goes with a scene file, not --suite"), std::string::npos);
    // view: the note, and the studio light; with --environment 1 the same furnace as render's.
    std::string shot = path("view.pfm");
    const std::string view = "LP_NUM_THREADS=2 xvfb-run -a -s \"-screen 0 1280x1024x24\" " +
                             std::string(FP_BINARY) + " view " + quad_ + kCamera +
                             " --size 32x32 --integrator bsdf --max-depth 1 --spp 1 --frames 1 --no-ui " +
                             "--screenshot " + shot;
    r = run(view);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(kNoLight), std::string::npos) << r.output;
    EXPECT_GT(readImage(shot).at(0, 0).y, 0.0f);
    r = run(view + " --environment 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    Image furnace = readImage(shot);
    expectAlbedoBlocks(furnace, true);
    expectSkyCorners(furnace);
    // Each lists the options in its --help.
    for (const char* command : {"render", "view", "study", "bench"}) {
        r = runFragpath(std::string(command) + " --help");
        EXPECT_NE(r.output.find("--environment ENV"), std::string::npos) << command;
        EXPECT_NE(r.output.find("--strict"), std::string::npos) << command;
    }
    r = run(kNative + " --help");
    EXPECT_NE(r.output.find("--environment ENV"), std::string::npos) << r.output;
}

// A texture file that is missing shows as the magenta and black checker (under the uniform sky, where a
// Lambertian quad shows exactly its albedo).
TEST_F(SensibleDefaults, AMissingTextureWarnsAndShowsTheChecker) {
    write("quad.mtl", "newmtl quad\nKd 0.2 0.9 0.2\nmap_Kd textures/missing.png\n");
    const int size = 64;
    std::string out = path("checker.pfm");
    CliRun r = runFragpath("render " + quad_ + kCamera + " --size 64x64 --integrator bsdf --max-depth 1 " +
                           "--environment 1 --spp 4 --quiet -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("warning: " + path("quad.mtl") +
                            ":3: material 'quad': map_Kd texture 'textures/missing.png' not found"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("showing a magenta and black checker instead"), std::string::npos) << r.output;
    Image image = readImage(out);
    // Where each pixel centre lands on the quad: the camera at z = -2 looks along +z, so the image's
    // right is world -x; the texture's row 0 (v = 1) is at the top. 8x8 squares, the top-left magenta.
    const double halfHeight = std::tan(glm::radians(20.0));
    int magenta = 0, black = 0;
    for (int py = 0; py < size; ++py)
        for (int px = 0; px < size; ++px) {
            double u = 0.5 - 2.0 * (2.0 * (px + 0.5) / size - 1.0) * halfHeight;
            double v = 0.5 + 2.0 * (1.0 - 2.0 * (py + 0.5) / size) * halfHeight;
            if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) continue;
            double su = u * 8.0, sv = (1.0 - v) * 8.0;
            // Pixels whose footprint (about 0.023 of the quad) or the bilinear filter (1/64) reach a
            // square's edge mix both colours.
            auto nearEdge = [](double s) { return std::abs(s - std::round(s)) < 0.3; };
            if (nearEdge(su) || nearEdge(sv)) continue;
            bool isMagenta = (int(su) + int(sv)) % 2 == 0;
            glm::vec3 expected = isMagenta ? glm::vec3(1.0f, 0.0f, 1.0f) : glm::vec3(0.0f);
            glm::vec3 p = image.at(px, py);
            ASSERT_NEAR(p.x, expected.x, 1e-5) << "pixel " << px << "," << py;
            ASSERT_NEAR(p.y, expected.y, 1e-5) << "pixel " << px << "," << py;
            ASSERT_NEAR(p.z, expected.z, 1e-5) << "pixel " << px << "," << py;
            (isMagenta ? magenta : black)++;
        }
    EXPECT_GT(magenta, 100);  // 128 of each
    EXPECT_GT(black, 100);
}

TEST_F(SensibleDefaults, StrictMakesWarningsErrors) {
    write("quad.mtl", "newmtl quad\nmap_Kd missing.png\n");
    std::string out = path("out.png");
    CliRun r = runFragpath("render " + quad_ + " --size 8x8 --spp 1 --strict -o " + out);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("fragpath: error: " + path("quad.mtl") +
                            ":2: material 'quad': map_Kd texture 'missing.png' not found"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("(an error with --strict)"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    // A scene without light is not repaired input: the studio light is the default, --strict or not.
    std::string lightless = write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    r = runFragpath("render " + lightless + " --size 8x8 --spp 1 --strict -o " + out);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("note: " + lightless + ": " + kNoLight), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(out));
    // --strict with nothing to warn about changes nothing.
    r = runFragpath("render " + lightless + " --environment none --size 8x8 --spp 1 --strict --quiet -o " +
                    out);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    r = runFragpath("render --size 8x8 --spp 1 --strict --quiet -o " + out);
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

// Writes `sky` as a Radiance .hdr (8-bit mantissas) and, from the floats that file decodes to, as an
// .exr: the same map bit for bit in both formats.
void writeSameSky(const Image& sky, const std::string& hdr, const std::string& exr) {
    std::vector<float> rgb;
    for (const glm::vec3& p : sky.pixels) rgb.insert(rgb.end(), {p.x, p.y, p.z});
    ASSERT_TRUE(stbi_write_hdr(hdr.c_str(), sky.width, sky.height, 3, rgb.data()));
    Image decoded = readHdr(hdr);
    writeExr(exr, decoded);
    ASSERT_EQ(readExrRadiance(exr).pixels, decoded.pixels);
}

TEST_F(SensibleDefaults, AnExrSkyRendersAsTheSameSkyInHdr) {
    // A bluish sky, darker below the horizon, with a small bright sun: importance sampling matters.
    Image sky(32, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x)
            sky.at(x, y) = glm::vec3(0.3f, 0.4f, 0.7f) * (y < 8 ? 1.0f : 0.2f) * (1.0f + 0.01f * float(x));
    for (int y = 3; y < 5; ++y)
        for (int x = 20; x < 22; ++x) sky.at(x, y) = glm::vec3(300.0f, 250.0f, 180.0f);
    writeSameSky(sky, path("sky.hdr"), path("sky.exr"));
    const std::string settings = kCamera + " --max-depth 2 --spp 8";
    std::string hdrScene = write("hdr.json", R"({"mesh": "quad.obj", "environment": {"map": "sky.hdr",
        "intensity": 1.5, "rotation": 30}})");
    std::string exrScene = write("exr.json", R"({"mesh": "quad.obj", "environment": {"map": "sky.exr",
        "intensity": 1.5, "rotation": 30}})");
    Image fromHdr = render(hdrScene + settings);
    Image fromExr = render(exrScene + settings);
    ASSERT_EQ(fromHdr.width, kSize);
    EXPECT_EQ(fromExr.pixels, fromHdr.pixels);
    EXPECT_NE(fromHdr.at(0, 0), glm::vec3(0.0f));
    // The flag's map: intensity 1, no rotation, in place of the scene's environment.
    std::string plain = write("plain.json", R"({"mesh": "quad.obj", "environment": {"map": "sky.exr"}})");
    Image byFlag = render(hdrScene + settings + " --environment " + path("sky.exr"));
    EXPECT_EQ(byFlag.pixels, render(plain + settings).pixels);
    EXPECT_EQ(byFlag.pixels, render(quad_ + settings + " --environment " + path("sky.hdr")).pixels);
    EXPECT_NE(byFlag.pixels, fromHdr.pixels);
}

TEST_F(SensibleDefaults, BadEnvironmentsAreClearErrors) {
    auto expectError = [&](const std::string& args, const std::string& fragment) {
        CliRun r = runFragpath("render " + quad_ + " --size 8x8 --spp 1 " + args + " -o " + path("bad.png"));
        EXPECT_EQ(r.exitCode, 1) << r.output;
        EXPECT_NE(r.output.find("fragpath: error: " + fragment), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(path("bad.png")));
    };
    expectError(
        "--environment sky.png",
        "option --environment: expected none, default, studio, a colour (X or R,G,B) or an .hdr or .exr "
        "file, got 'sky.png'");
    expectError("--environment -0.5",
                "option --environment: a colour's radiance is 0 or more in each channel");
    expectError("--environment 1,1", "option --environment: expected X,Y,Z, got '1,1'");
    expectError("--environment " + path("missing.exr"),
                "option --environment: " + path("missing.exr") + ": no such file");
    write("text.exr", "not an EXR\n");
    expectError("--environment " + path("text.exr"),
                "cannot read EXR '" + path("text.exr") + "': not an OpenEXR file");
    // A file without colour channels, named in a scene file.
    Image grey(2, 2);
    writeExr(path("rgb.exr"), grey);
    std::string bytes;
    {
        // Rename the channels R, G, B to X, Y, Z in place: same length, same layout (no compression
        // of the header), so the file stays valid.
        std::ifstream in(path("rgb.exr"), std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
        size_t header = bytes.find("channels");
        ASSERT_NE(header, std::string::npos);
        for (auto [from, to] : {std::pair{"B\0", "X\0"}, {"G\0", "Y\0"}, {"R\0", "Z\0"}}) {
            size_t at = bytes.find(std::string(from, 2), header);
            ASSERT_NE(at, std::string::npos);
            bytes.replace(at, 2, std::string(to, 2));
        }
    }
    write("xyz.exr", bytes);
    std::string scene = write("scene.json", R"({"mesh": "quad.obj", "environment": {"map": "xyz.exr"}})");
    CliRun r = runFragpath("render " + scene + " --size 8x8 --spp 1 -o " + path("bad.png"));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("a radiance image needs R, G and B channels (or a single Y), found X, Y, Z"),
              std::string::npos)
        << r.output;
}

}  // namespace
}  // namespace fp
