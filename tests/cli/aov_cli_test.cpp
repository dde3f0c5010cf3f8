// render --aovs: the first-hit layers in the .exr output, checked against the built-in Cornell box
// (assets/cornell: its MTL colours, its walls' planes and its camera), and what they must not change.
#include <gtest/gtest.h>
#include <tinyexr.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cli/fragpath_runner.h"
#include "image/exr.h"
#include "render/partial_render.h"

namespace fp {
namespace {

constexpr int kSize = 64;  // square, so the aspect ratio is 1

// Pixels [x0, x1] x [y0, y1] (columns from the left, rows from the top) of a kSize x kSize render of
// the built-in Cornell box that see one wall only, jitter included (worked out from the geometry in
// assets/cornell/cornell.obj seen from cornell.json's camera; the boxes stand clear of them).
struct Block {
    const char* name;
    int x0, x1, y0, y1;
};
const Block kRedWall{"red (left) wall", 4, 9, 24, 40};
const Block kGreenWall{"green (right) wall", 54, 59, 24, 40};
const Block kBackWall{"back wall", 27, 37, 19, 23};
const Block kFloor{"floor", 24, 40, 60, 61};

class Aovs : public test::TempDirTest {
  protected:
    void render(const std::string& options, const std::string& out) {
        test::CliRun r =
            test::runFragpath("render --size " + std::to_string(kSize) + "x" + std::to_string(kSize) +
                              " --quiet " + options + " -o " + path(out));
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    // The layer called `name` of an EXR, or an empty image.
    Image layer(const std::string& file, const std::string& name) {
        std::vector<ExrLayer> layers;
        readExr(path(file), nullptr, &layers);
        for (const ExrLayer& l : layers)
            if (l.name == name) return l.image;
        ADD_FAILURE() << file << " has no layer " << name;
        return Image();
    }
    // AOVs of renders of the same samples, in whatever parts. Albedo and normal are means over all the
    // samples and combine exactly (up to float rounding); depth is a mean over the samples that hit
    // something, and parts combine it weighted by samples, so it is compared only where every sample
    // hit one flat surface (a unit normal).
    void expectSameAovs(const PartialRender& a, const PartialRender& whole) {
        const AovImage* normal = nullptr;
        for (const AovImage& w : whole.aovs)
            if (w.aov == Aov::Normal) normal = &w;
        ASSERT_NE(normal, nullptr);
        int compared = 0;
        for (const AovImage& m : a.aovs)
            for (const AovImage& w : whole.aovs) {
                if (m.aov != w.aov) continue;
                for (size_t i = 0; i < w.image.pixels.size(); ++i) {
                    if (m.aov == Aov::Depth && std::abs(glm::length(normal->image.pixels[i]) - 1.0f) > 1e-5f)
                        continue;
                    ++compared;
                    for (int c = 0; c < 3; ++c)
                        ASSERT_NEAR(m.image.pixels[i][c], w.image.pixels[i][c],
                                    1e-4f * (1.0f + std::abs(w.image.pixels[i][c])))
                            << aovName(m.aov) << " pixel " << i;
                }
            }
        EXPECT_GT(compared, int(a.aovs.size() * whole.mean.pixels.size() * 8 / 10));
    }
    template <typename Check>
    void forEachPixel(const Block& block, const Image& image, Check check) {
        ASSERT_EQ(image.width, kSize);
        for (int y = block.y0; y <= block.y1; ++y)
            for (int x = block.x0; x <= block.x1; ++x) check(x, y, image.at(x, y));
    }
};

std::vector<std::string> channelNames(const std::string& file) {
    EXRVersion version;
    EXRHeader header;
    InitEXRHeader(&header);
    const char* err = nullptr;
    std::vector<std::string> names;
    if (ParseEXRVersionFromFile(&version, file.c_str()) != TINYEXR_SUCCESS ||
        ParseEXRHeaderFromFile(&header, &version, file.c_str(), &err) != TINYEXR_SUCCESS) {
        ADD_FAILURE() << "cannot parse " << file << ": " << (err ? err : "");
        if (err) FreeEXRErrorMessage(err);
        return names;
    }
    for (int c = 0; c < header.num_channels; ++c) names.push_back(header.channels[c].name);
    FreeEXRHeader(&header);
    return names;
}

// The names users of Cycles, Nuke and OIDN look for (src/render/aovs.h), next to the beauty's R, G, B,
// in the sorted order OpenEXR requires; an AOV not asked for is not written.
TEST_F(Aovs, LayersHaveTheConventionalChannelNames) {
    render("--spp 1 --aovs albedo,normal,depth", "all.exr");
    EXPECT_EQ(channelNames(path("all.exr")),
              (std::vector<std::string>{"B", "G", "R", "albedo.B", "albedo.G", "albedo.R", "depth.Z",
                                        "normal.X", "normal.Y", "normal.Z"}));
    render("--spp 1 --aovs depth", "depth.exr");
    EXPECT_EQ(channelNames(path("depth.exr")), (std::vector<std::string>{"B", "G", "R", "depth.Z"}));
    render("--spp 1", "none.exr");
    EXPECT_EQ(channelNames(path("none.exr")), (std::vector<std::string>{"B", "G", "R"}));
}

// The albedo of a matte wall is its MTL Kd (assets/cornell/cornell.mtl), in every pixel of the block.
TEST_F(Aovs, AlbedoOfTheWallsIsTheirMtlColour) {
    render("--spp 4 --aovs albedo", "out.exr");
    const Image albedo = layer("out.exr", "albedo");
    for (auto [block, kd] : {std::pair{kRedWall, glm::vec3(0.63f, 0.065f, 0.05f)},
                             std::pair{kGreenWall, glm::vec3(0.14f, 0.45f, 0.091f)},
                             std::pair{kBackWall, glm::vec3(0.73f)}, std::pair{kFloor, glm::vec3(0.73f)}})
        forEachPixel(block, albedo, [&](int x, int y, const glm::vec3& v) {
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(v[c], kd[c], 1e-5f) << block.name << " at " << x << "," << y << " channel " << c;
        });
}

// World-space shading normals, on the side facing the camera (which looks along +z from z = -800):
// unit length inside a flat surface (a mean of equal unit vectors).
TEST_F(Aovs, NormalsAreUnitWorldSpaceAndFaceTheCamera) {
    render("--spp 4 --aovs normal", "out.exr");
    const Image normal = layer("out.exr", "normal");
    for (auto [block, expected] :
         {std::pair{kFloor, glm::vec3(0, 1, 0)}, std::pair{kBackWall, glm::vec3(0, 0, -1)},
          // The red wall (x = 549.6 .. 556) leans a little: its normal is within 0.5 degrees of -x.
          std::pair{kRedWall, glm::vec3(-1, 0, 0)}, std::pair{kGreenWall, glm::vec3(1, 0, 0)}})
        forEachPixel(block, normal, [&](int x, int y, const glm::vec3& n) {
            ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f) << block.name << " at " << x << "," << y;
            ASSERT_GT(glm::dot(n, expected), 0.9999f)
                << block.name << " at " << x << "," << y << ": " << n.x << " " << n.y << " " << n.z;
        });
    // Outside the box the camera ray hits nothing: no normal.
    EXPECT_EQ(normal.at(kSize / 2, kSize - 1), glm::vec3(0.0f));
}

// Depth is the distance along the camera ray to the back wall (the plane z = 559.2, the eye at
// z = -800 looking along +z): through normalised device coordinates (u, v) the ray's direction is
// (-u t, v t, 1) normalised, t = tan(fov / 2), so the distance is 1359.2 sqrt(1 + t^2 (u^2 + v^2)).
// Samples are jittered inside the pixel, so their mean lies between that distance's least and greatest
// value over the pixel's square (a range of 1 to 3.5 here; the distance along the view axis, 1359.2
// everywhere, would be 5 to 19 too short).
TEST_F(Aovs, DepthIsTheDistanceAlongTheCameraRay) {
    render("--spp 4 --aovs depth", "out.exr");
    const Image depth = layer("out.exr", "depth");
    const double t = std::tan(0.5 * 39.3 * M_PI / 180.0);
    // The least and greatest square of a coordinate over [a, b].
    auto squares = [](double a, double b) {
        double low = a <= 0.0 && b >= 0.0 ? 0.0 : std::min(a * a, b * b);
        return std::pair{low, std::max(a * a, b * b)};
    };
    forEachPixel(kBackWall, depth, [&](int x, int y, const glm::vec3& d) {
        const double h = 2.0 / kSize;  // a pixel in device coordinates
        const double u = 2.0 * x / kSize - 1.0, v = 2.0 * (kSize - 1 - y) / kSize - 1.0;  // pixel corner
        auto [u2min, u2max] = squares(u, u + h);
        auto [v2min, v2max] = squares(v, v + h);
        const double nearest = 1359.2 * std::sqrt(1.0 + t * t * (u2min + v2min)),
                     farthest = 1359.2 * std::sqrt(1.0 + t * t * (u2max + v2max));
        ASSERT_GE(d.x, nearest - 1e-3) << "at " << x << "," << y;
        ASSERT_LE(d.x, farthest + 1e-3) << "at " << x << "," << y;
        ASSERT_EQ(d.y, 0.0f);
    });
    EXPECT_EQ(depth.at(kSize / 2, kSize - 1).x, 0.0f) << "no hit, no depth";
}

// Accumulating the AOVs traces one more ray per sample but must not change a bit of the beauty (nor
// the fingerprint, so that renders with and without AOVs merge and resume).
TEST_F(Aovs, BeautyIsBitIdenticalWithAndWithout) {
    for (const char* integrator : {"nee", "bdpt"}) {
        const std::string options = std::string("--spp 3 --seed 7 --integrator ") + integrator;
        render(options, "plain.exr");
        render(options + " --aovs albedo,normal,depth", "aovs.exr");
        PartialRender plain = readPartial(path("plain.exr")), withAovs = readPartial(path("aovs.exr"));
        EXPECT_EQ(plain.mean.pixels, withAovs.mean.pixels) << integrator;
        EXPECT_EQ(plain.fingerprint, withAovs.fingerprint) << integrator;
        EXPECT_EQ(withAovs.aovs.size(), 3u);
    }
}

TEST_F(Aovs, NeedAnExrOutputAndKnownNames) {
    test::CliRun r = test::runFragpath("render --size 8x8 --spp 1 --aovs albedo -o " + path("out.png"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("--aovs needs an .exr output"), std::string::npos) << r.output;
    r = test::runFragpath("render --size 8x8 --spp 1 --aovs albedo,normals -o " + path("out.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("unknown AOV 'normals'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("choose from albedo, normal, depth"), std::string::npos) << r.output;
    r = test::runFragpath("render --size 8x8 --spp 1 --aovs albedo, -o " + path("out.exr"));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("--aovs: empty name"), std::string::npos) << r.output;
}

// A file with AOV layers resumes like any other, and the resumed AOVs are those of the whole render.
TEST_F(Aovs, ResumeKeepsAndExtendsTheLayers) {
    const std::string aovs = " --aovs albedo,normal,depth";
    render("--spp 6" + aovs, "whole.exr");
    render("--spp 2" + aovs, "part.exr");
    render("--spp 6 --resume " + path("part.exr") + aovs, "resumed.exr");
    PartialRender whole = readPartial(path("whole.exr")), resumed = readPartial(path("resumed.exr"));
    ASSERT_EQ(resumed.samples(), 6u);
    ASSERT_EQ(resumed.aovs.size(), 3u);
    expectSameAovs(resumed, whole);
    // Resuming without --aovs reads the layers and leaves them out of the output.
    render("--spp 4 --resume " + path("part.exr"), "plain.exr");
    EXPECT_TRUE(readPartial(path("plain.exr")).aovs.empty());
    EXPECT_EQ(channelNames(path("plain.exr")).size(), 3u);
}

// merge carries an AOV when every part has it (weighted by samples, as one render would average it) and
// drops it otherwise.
TEST_F(Aovs, MergeCarriesTheLayersEveryPartHas) {
    render("--spp 5 --aovs albedo,normal,depth", "whole.exr");
    render("--spp 2 --aovs albedo,normal,depth", "a.exr");
    render("--spp 3 --sample-offset 2 --aovs normal,depth", "b.exr");
    test::CliRun r =
        test::runFragpath("merge " + path("a.exr") + " " + path("b.exr") + " -o " + path("m.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(channelNames(path("m.exr")),
              (std::vector<std::string>{"B", "G", "R", "depth.Z", "normal.X", "normal.Y", "normal.Z"}));
    PartialRender merged = readPartial(path("m.exr")), whole = readPartial(path("whole.exr"));
    ASSERT_EQ(merged.aovs.size(), 2u);
    expectSameAovs(merged, whole);
}

}  // namespace
}  // namespace fp
