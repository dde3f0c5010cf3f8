// Labelled grids of images (src/image/image_grid.h): the layout worked out by hand, every tile pixel
// where it belongs, labels where the layout puts them, and the refusals.
#include <gtest/gtest.h>

#include "core/error.h"
#include "image/image_grid.h"
#include "image/tagged_image.h"
#include "image/text_label.h"

namespace fp {
namespace {

bool uniform(const Image& image, const PixelRect& r, glm::vec3 colour) {
    for (int y = r.y; y < r.y + r.height; ++y)
        for (int x = r.x; x < r.x + r.width; ++x)
            if (image.at(x, y) != colour) return false;
    return true;
}

// 2 rows of 3 16x16 tiles. Text scale 1 (tiles under 96 pixels), padding 2. Header 9 + 2 * 2 = 13
// rows. Label column: the wider label "HH" is 6 + 6 = 12 columns ('H' advances 6), + 2 * 2 = 16.
// Width 16 + 3 * 16 + 2 * 2 = 68, height 13 + 2 * 16 + 2 = 47.
TEST(ImageGrid, LayoutWorkedOutByHand) {
    GridLabels labels{{"a", "b", "c"}, {"H", "HH"}};
    GridLayout l = gridLayout(2, 3, 16, 16, labels);
    EXPECT_EQ(l.scale, 1);
    EXPECT_EQ(l.headerHeight, 13);
    EXPECT_EQ(l.labelWidth, 16);
    EXPECT_EQ(l.width, 68);
    EXPECT_EQ(l.height, 47);
    EXPECT_EQ(l.tileLeft(2), 16 + 2 * 18);
    EXPECT_EQ(l.tileTop(1), 13 + 18);
    // 128-pixel tiles: scale 2, padding 4, header 18 + 8 = 26, label column 24 + 8 = 32.
    GridLayout big = gridLayout(2, 3, 128, 128, labels);
    EXPECT_EQ(big.scale, 2);
    EXPECT_EQ(big.headerHeight, 26);
    EXPECT_EQ(big.labelWidth, 32);
    EXPECT_EQ(big.width, 32 + 3 * 128 + 2 * 2);
    EXPECT_EQ(big.height, 26 + 2 * 128 + 2);
    // No labels: the tiles and gaps alone.
    GridLayout bare = gridLayout(2, 3, 16, 16, GridLabels{});
    EXPECT_EQ(bare.width, 3 * 16 + 2 * 2);
    EXPECT_EQ(bare.height, 2 * 16 + 2);
    EXPECT_EQ(bare.tileLeft(0), 0);
    EXPECT_EQ(bare.tileTop(0), 0);
}

TEST(ImageGrid, TilesHoldTheirCropsAndLabelsLightTheirPlaces) {
    const PixelRect crop{3, 2, 16, 16};
    std::vector<Image> images;
    for (int i = 0; i < 6; ++i) images.push_back(test::taggedImage(24, 20, float(i + 1)));
    std::vector<std::vector<const Image*>> tiles{{&images[0], &images[1], &images[2]},
                                                 {&images[3], &images[4], &images[5]}};
    GridLabels labels{{"a", "b", "c"}, {"H", "HH"}};
    labels.colour = glm::vec3(5.0f);
    Image grid = assembleGrid(tiles, crop, labels);
    GridLayout l = gridLayout(2, 3, 16, 16, labels);
    ASSERT_EQ(grid.width, l.width);
    ASSERT_EQ(grid.height, l.height);
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c)
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x)
                    ASSERT_EQ(grid.at(l.tileLeft(c) + x, l.tileTop(r) + y),
                              images[size_t(r * 3 + c)].at(crop.x + x, crop.y + y))
                        << r << "," << c << " at " << x << "," << y;
    // The gap between columns 0 and 1 is grey all the way down.
    EXPECT_TRUE(uniform(grid, PixelRect{l.tileLeft(1) - 2, 0, 2, l.height}, kGridGapColour));
    // Every header cell holds some text, and nothing but grey and text.
    for (int c = 0; c < 3; ++c) {
        PixelRect cell{l.tileLeft(c), 0, 16, l.headerHeight};
        EXPECT_FALSE(uniform(grid, cell, kGridGapColour)) << c;
        for (int y = 0; y < cell.height; ++y)
            for (int x = cell.x; x < cell.x + cell.width; ++x)
                ASSERT_TRUE(grid.at(x, y) == kGridGapColour || grid.at(x, y) == labels.colour)
                    << x << "," << y;
    }
    // Row 0's "H": its left bar in column `padding` = 2, from the row's top + (16 - 9) / 2 = 3 down 7
    // rows; the column after it is grey except at the crossbar (glyph row 3).
    for (int y = 0; y < 7; ++y) {
        EXPECT_EQ(grid.at(2, l.tileTop(0) + 3 + y), labels.colour) << y;
        EXPECT_EQ(grid.at(3, l.tileTop(0) + 3 + y), y == 3 ? labels.colour : kGridGapColour) << y;
    }
    // Without labels: the tiles at the top-left corner, no header, no label column.
    Image bare = assembleGrid(tiles, crop, GridLabels{});
    EXPECT_EQ(bare.width, 3 * 16 + 2 * 2);
    EXPECT_EQ(bare.at(0, 0), images[0].at(crop.x, crop.y));
}

// A column label wider than its tile is cut at the tile's edge: it never runs into the next header.
TEST(ImageGrid, AWideColumnLabelStaysOverItsTile) {
    Image tile = test::taggedImage(8, 8, 1.0f);
    GridLabels labels{{"HHHHHH", "a"}, {}};
    labels.colour = glm::vec3(5.0f);
    Image grid = assembleGrid({{&tile, &tile}}, PixelRect{0, 0, 8, 8}, labels);
    GridLayout l = gridLayout(1, 2, 8, 8, labels);
    EXPECT_TRUE(uniform(grid, PixelRect{8, 0, 2, l.headerHeight}, kGridGapColour));  // the gap above
    EXPECT_EQ(grid.at(0, l.padding), labels.colour);  // the first H starts at the tile's left edge
}

TEST(ImageGrid, RefusesMismatchedInput) {
    Image a = test::taggedImage(8, 8, 1.0f), small = test::taggedImage(4, 4, 2.0f);
    const PixelRect crop{0, 0, 8, 8};
    EXPECT_THROW(assembleGrid({}, crop, GridLabels{}), Error);
    EXPECT_THROW(assembleGrid({{&a, &a}, {&a}}, crop, GridLabels{}), Error);          // ragged rows
    EXPECT_THROW(assembleGrid({{&a, &small}}, crop, GridLabels{}), Error);            // crop outside
    EXPECT_THROW(assembleGrid({{&a, &a}}, crop, GridLabels{{"1"}, {}}), Error);       // 1 label, 2 columns
    EXPECT_THROW(assembleGrid({{&a, &a}}, crop, GridLabels{{}, {"x", "y"}}), Error);  // 2 labels, 1 row
    EXPECT_THROW(assembleGrid({{&a}}, crop, GridLabels{{"\t"}, {}}), Error);          // not printable
}

}  // namespace
}  // namespace fp
