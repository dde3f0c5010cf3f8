// Text labels (src/image/text_label.h): sizes from stb_easy_font's advance table, a glyph's pixels
// worked out from its shape, scaling, clipping and the refusals.
#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "core/error.h"
#include "image/text_label.h"

namespace fp {
namespace {

const glm::vec3 kInk(1.0f);

std::set<std::pair<int, int>> litPixels(const Image& image) {
    std::set<std::pair<int, int>> lit;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (image.at(x, y) == kInk) lit.insert({x, y});
    return lit;
}

// stb_easy_font's table (stb_easy_font_charinfo, advance & 15): '1' 6, ' ' 6, 's' 5, 'p' 6, 'H' 6;
// the glyphs are 9 rows high (7 above the baseline, 2 for descenders).
TEST(TextLabel, ExtentFollowsTheFontsAdvances) {
    EXPECT_EQ(textExtent("H", 1).width, 6);
    EXPECT_EQ(textExtent("H", 1).height, 9);
    EXPECT_EQ(textExtent("1 spp", 1).width, 6 + 6 + 5 + 6 + 6);
    EXPECT_EQ(textExtent("1 spp", 3).width, 3 * 29);
    EXPECT_EQ(textExtent("1 spp", 3).height, 27);
    EXPECT_EQ(textExtent("", 2).width, 0);
}

// 'H': two 7-pixel bars in columns 0 and 3 and a crossbar in row 3 between them.
TEST(TextLabel, AnHLightsItsBarsAndNothingElse) {
    Image image(8, 10);
    drawText(image, "H", 1, 1, 1, kInk);
    std::set<std::pair<int, int>> expected{{2, 4}, {3, 4}};
    for (int y = 1; y <= 7; ++y) {
        expected.insert({1, y});
        expected.insert({4, y});
    }
    EXPECT_EQ(litPixels(image), expected);

    // At scale 2 every font pixel is a 2x2 square: 16 pixels become 64, the crossbar at rows 6-7.
    Image big(12, 20);
    drawText(big, "H", 0, 0, 2, kInk);
    std::set<std::pair<int, int>> lit = litPixels(big);
    EXPECT_EQ(lit.size(), 64u);
    for (int x = 0; x < 8; ++x) EXPECT_TRUE(lit.count({x, 6}) && lit.count({x, 7})) << x;
    EXPECT_FALSE(lit.count({2, 5}));
}

// Pixels outside the image or the clip rectangle are left alone: the right bar only, rows 1-4 only.
TEST(TextLabel, ClipsToTheImageAndTheRectangle) {
    Image image(8, 10);
    drawText(image, "H", 1, 1, 1, kInk, PixelRect{3, 0, 5, 5});
    std::set<std::pair<int, int>> expected{{3, 4}};
    for (int y = 1; y <= 4; ++y) expected.insert({4, y});
    EXPECT_EQ(litPixels(image), expected);
    Image small(2, 2);
    drawText(small, "H", -3, -2, 1, kInk);  // only column 3 of the glyph lands, rows 2 and 3
    EXPECT_EQ(litPixels(small), (std::set<std::pair<int, int>>{{0, 0}, {0, 1}}));
}

TEST(TextLabel, RefusesWhatTheFontCannotDraw) {
    Image image(8, 8);
    for (const char* text : {"a\nb", "tab\t", "caf\xc3\xa9", "\x7f"}) {
        EXPECT_THROW(textExtent(text, 1), Error) << text;
        EXPECT_THROW(drawText(image, text, 0, 0, 1, kInk), Error) << text;
    }
    EXPECT_THROW(textExtent("ok", 0), Error);
    EXPECT_THROW(drawText(image, "ok", 0, 0, -1, kInk), Error);
}

}  // namespace
}  // namespace fp
