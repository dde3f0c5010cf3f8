// The AOVs of render --aovs (render/aovs.h) without a GPU: names, means from an accumulation, and how
// parts of a render (merge, resume) combine them.
#include "render/aovs.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "image/test_files.h"
#include "render/partial_render.h"

namespace fp {
namespace {

using test::errorMessage;

TEST(Aovs, ParseKeepsTheOrderGiven) {
    EXPECT_EQ(parseAovs("depth,albedo"), (std::vector<Aov>{Aov::Depth, Aov::Albedo}));
    EXPECT_EQ(parseAovs("normal"), (std::vector<Aov>{Aov::Normal}));
    std::string message = errorMessage([] { parseAovs("albedo,Normal"); });
    EXPECT_NE(message.find("unknown AOV 'Normal'"), std::string::npos) << message;
    EXPECT_NE(message.find("albedo, normal, depth"), std::string::npos) << message;
    for (const char* bad : {"", "albedo,,depth", "albedo,", "normal,normal"})
        EXPECT_NE(errorMessage([&] { parseAovs(bad); }).find("--aovs"), std::string::npos) << bad;
}

TEST(Aovs, OptionNeedsAnExrOutput) {
    EXPECT_TRUE(parseAovOption(std::nullopt, "out.png").empty());
    EXPECT_EQ(parseAovOption("albedo", "dir/OUT.EXR"), (std::vector<Aov>{Aov::Albedo}));
    for (const char* output : {"out.png", "out.pfm", "out"}) {
        std::string message = errorMessage([&] { parseAovOption("albedo", output); });
        EXPECT_NE(message.find("--aovs needs an .exr output"), std::string::npos) << message;
        EXPECT_NE(message.find(output), std::string::npos) << message;
    }
}

TEST(Aovs, ChannelNames) {
    EXPECT_EQ(toExrLayer({Aov::Albedo, Image(1, 1)}).channels, (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(toExrLayer({Aov::Normal, Image(1, 1)}).channels, (std::vector<std::string>{"X", "Y", "Z"}));
    EXPECT_EQ(toExrLayer({Aov::Depth, Image(1, 1)}).channels, (std::vector<std::string>{"Z"}));
    EXPECT_EQ(toExrLayer({Aov::Depth, Image(1, 1)}).name, "depth");
}

// Albedo and normal are means over all guide samples (a miss adds 0: an edge pixel's normal is
// shorter); depth is the mean over the samples that hit something.
TEST(Aovs, MeansFromTheAccumulation) {
    Accumulation acc;
    acc.width = 2;
    acc.height = 1;
    // Pixel 0: 4 guide samples, 3 of which hit: normals (0, 1, 0) three times, distances 2 + 3 + 4.
    // Pixel 1: nothing hit.
    acc.counters = {{100.0f, 0.0f, 3.0f, 0.0f}, {4.0f, 0.0f, 0.0f, 0.0f}};
    acc.normalDepth = {{0.0f, 3.0f, 0.0f, 9.0f}, {0.0f, 0.0f, 0.0f, 0.0f}};
    acc.albedo = {{2.0f, 1.0f, 0.4f, 4.0f}, {0.0f, 0.0f, 0.0f, 4.0f}};
    std::vector<AovImage> aovs = aovImages(acc, {Aov::Depth, Aov::Albedo, Aov::Normal});
    ASSERT_EQ(aovs.size(), 3u);
    EXPECT_EQ(aovs[0].aov, Aov::Depth);
    EXPECT_EQ(aovs[0].image.pixels[0], glm::vec3(3.0f, 0.0f, 0.0f));
    EXPECT_EQ(aovs[1].image.pixels[0], glm::vec3(0.5f, 0.25f, 0.1f));
    EXPECT_EQ(aovs[2].image.pixels[0], glm::vec3(0.0f, 0.75f, 0.0f));
    for (const AovImage& a : aovs) EXPECT_EQ(a.image.pixels[1], glm::vec3(0.0f)) << aovName(a.aov);
}

// Parts combine weighted by their samples; depth only over the parts that hit something there.
TEST(Aovs, PartsCombineWeightedBySamples) {
    auto image = [](glm::vec3 a, glm::vec3 b) {
        Image i(2, 1);
        i.pixels = {a, b};
        return i;
    };
    std::vector<AovImage> a = {{Aov::Albedo, image(glm::vec3(0.2f), glm::vec3(1.0f))},
                               {Aov::Depth, image(glm::vec3(2.0f, 0, 0), glm::vec3(0.0f))}};
    std::vector<AovImage> b = {{Aov::Albedo, image(glm::vec3(0.6f), glm::vec3(0.0f))},
                               {Aov::Depth, image(glm::vec3(6.0f, 0, 0), glm::vec3(5.0f, 0, 0))}};
    std::vector<AovPart> parts = {{&a, {1.0}}, {&b, {3.0}}};
    std::optional<AovImage> albedo = combineAov(Aov::Albedo, parts), depth = combineAov(Aov::Depth, parts);
    ASSERT_TRUE(albedo && depth);
    EXPECT_NEAR(albedo->image.pixels[0].x, 0.5f, 1e-6f);
    EXPECT_NEAR(albedo->image.pixels[1].x, 0.25f, 1e-6f);
    EXPECT_NEAR(depth->image.pixels[0].x, 5.0f, 1e-6f);
    EXPECT_EQ(depth->image.pixels[1].x, 5.0f) << "part a hit nothing there";
    EXPECT_FALSE(combineAov(Aov::Normal, parts)) << "no part has it";
    // Per-pixel samples (a render's guide samples) and a part without samples.
    std::vector<AovPart> perPixel = {{&a, {1.0, 0.0}}, {&b, {0.0, 2.0}}};
    EXPECT_EQ(combineAov(Aov::Albedo, perPixel)->image.pixels,
              (std::vector<glm::vec3>{glm::vec3(0.2f), glm::vec3(0.0f)}));
    EXPECT_FALSE(combineAov(Aov::Albedo, {{&a, {0.0}}})) << "no samples";
}

// merge keeps the AOVs every part has, combined like the beauty; one that some part lacks is dropped.
TEST(Aovs, MergeCarriesOnlyTheAovsOfEveryPart) {
    auto part = [](uint64_t first, uint64_t count, float value, std::vector<Aov> aovs) {
        PartialRender p;
        p.mean = Image(1, 1);
        p.mean.pixels[0] = glm::vec3(value);
        p.ranges = {{first, count}};
        p.fingerprint = "f";
        for (Aov aov : aovs) {
            Image image(1, 1);
            image.pixels[0] = glm::vec3(value, value, aov == Aov::Depth ? 0.0f : value);
            p.aovs.push_back({aov, image});
        }
        return p;
    };
    PartialRender merged = mergePartials({part(0, 1, 1.0f, {Aov::Normal, Aov::Depth, Aov::Albedo}),
                                          part(1, 3, 5.0f, {Aov::Albedo, Aov::Normal})},
                                         {"a", "b"});
    EXPECT_EQ(merged.mean.pixels[0], glm::vec3(4.0f));
    ASSERT_EQ(merged.aovs.size(), 2u);
    EXPECT_EQ(merged.aovs[0].aov, Aov::Normal);
    EXPECT_EQ(merged.aovs[1].aov, Aov::Albedo);
    for (const AovImage& a : merged.aovs) EXPECT_EQ(a.image.pixels[0], glm::vec3(4.0f)) << aovName(a.aov);
}

}  // namespace
}  // namespace fp
