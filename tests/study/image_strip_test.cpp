// The study's image strip (src/study/image_strip.h): its labels, the crop of each image in its place,
// and a missing image refused.
#include <gtest/gtest.h>

#include "core/error.h"
#include "image/tagged_image.h"
#include "image/text_label.h"
#include "study/image_strip.h"

namespace fp::study {
namespace {

StripLayout twoByTwo() {
    StripLayout layout;
    layout.rows = {{"nee", "none"}, {"nee", "atrous"}};
    layout.columns = {1, 4};
    return layout;
}

TEST(ImageStrip, LabelsNameTheSampleCountsAndTheSeries) {
    GridLabels labels = stripLabels(twoByTwo());
    EXPECT_EQ(labels.columns, (std::vector<std::string>{"1 spp", "4 spp", "reference"}));
    EXPECT_EQ(labels.rows, (std::vector<std::string>{"nee", "nee + atrous"}));
}

// A 12x12 crop at (4, 4) of 20x20 images: each tile holds its image's crop, the reference last in each
// row. Layout (image_grid.h, text scale 1 below 96 pixels, padding 2): a header of 9 + 2 * 2 = 13 rows;
// a label column as wide as "nee + atrous" + 2 * 2 (its width from textExtent, which text_label_test
// checks against the font's table); tiles 12 + 2 apart.
TEST(ImageStrip, EachTileHoldsItsCrop) {
    StripLayout layout = twoByTwo();
    SweepResult sweep;
    float tag = 1.0f;
    for (const auto& [integrator, denoiser] : layout.rows)
        for (int spp : layout.columns)
            sweep.images[{integrator, denoiser, spp}] = test::taggedImage(20, 20, tag++);
    Image reference = test::taggedImage(20, 20, 100.0f);
    const PixelRect crop{4, 4, 12, 12};
    Image strip = assembleStrip(sweep, reference, layout, crop);
    const int labelWidth = textExtent("nee + atrous", 1).width + 4, header = 13;
    ASSERT_EQ(strip.width, labelWidth + 3 * 12 + 2 * 2);
    ASSERT_EQ(strip.height, header + 2 * 12 + 2);
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c) {
            const auto& [integrator, denoiser] = layout.rows[size_t(r)];
            const Image& source =
                c < 2 ? sweep.images.at({integrator, denoiser, layout.columns[size_t(c)]}) : reference;
            for (int y = 0; y < 12; ++y)
                for (int x = 0; x < 12; ++x)
                    ASSERT_EQ(strip.at(labelWidth + c * 14 + x, header + r * 14 + y), source.at(4 + x, 4 + y))
                        << r << "," << c;
        }
    sweep.images.erase({"nee", "atrous", 4});
    EXPECT_THROW(assembleStrip(sweep, reference, layout, crop), Error);
}

}  // namespace
}  // namespace fp::study
