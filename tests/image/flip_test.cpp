// LDR-FLIP and HDR-FLIP (image/flip.h) against values worked out by hand from the papers' formulas, and
// against what the metric is for: colour differences, moved edges, viewing distance, exposures.
#include "image/flip.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/error.h"
#include "image/flip_pipelines.h"

namespace fp {
namespace {

Image flat(int w, int h, glm::vec3 colour) {
    Image image(w, h);
    for (glm::vec3& p : image.pixels) p = colour;
    return image;
}

Image noise(int w, int h, float scale, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, scale);
    Image image(w, h);
    for (glm::vec3& p : image.pixels) p = {u(rng), u(rng), u(rng)};
    return image;
}

TEST(Flip, DefaultViewingIsSeventyCentimetresFromA4kDisplay) {
    // 0.7 * (3840 / 0.7) * pi / 180 = 3840 pi / 180 = 67.0206...
    EXPECT_NEAR(kDefaultPixelsPerDegree, 67.0206, 1e-4);
    EXPECT_DOUBLE_EQ(pixelsPerDegree(0.7, 0.7, 3840), kDefaultPixelsPerDegree);
    EXPECT_DOUBLE_EQ(pixelsPerDegree(1.4, 0.7, 3840), 2.0 * kDefaultPixelsPerDegree);
}

TEST(Flip, IdenticalImagesGiveExactlyZero) {
    const Image image = noise(23, 17, 1.0f, 1);
    const FlipResult r = ldrFlip(image, image);
    EXPECT_EQ(r.mean, 0.0);
    for (const glm::vec3& p : r.errorMap.pixels) ASSERT_EQ(p, glm::vec3(0.0f));
}

TEST(Flip, BlackAgainstWhiteIsTheRemappedDistanceOfTheFormulas) {
    // By hand. Flat fields stay flat under the normalised CSF filters and give no features, so
    // deltaE_f = 0 and deltaE = deltaE_c. Black is L* = 0; white (the reference white itself) is
    // L* = 100, a* = b* = 0, unchanged by the Hunt adjustment: HyAB = 100 and 100^0.7 = 25.1189.
    // cmax: green (0, 1, 0) is XYZ (0.3576, 0.7152, 0.1192), CIELAB (87.737, -86.188, 83.186), Hunt
    // (87.737, -75.619, 72.985); blue (0, 0, 1) is XYZ (0.1805, 0.0722, 0.9505), CIELAB (32.303, 79.194,
    // -107.854), Hunt (32.303, 25.582, -34.840); HyAB = 55.434 + hypot(101.201, 107.825) = 203.312, and
    // cmax = 203.312^0.7 = 41.2776. 25.1189 >= pc cmax = 16.5110, so
    // deltaE = pt + (25.1189 - 16.5110) / (41.2776 - 16.5110) * (1 - pt) = 0.95 + 0.34756 * 0.05 = 0.967378.
    const Image black = flat(12, 9, glm::vec3(0.0f)), white = flat(12, 9, glm::vec3(1.0f));
    const FlipResult r = ldrFlip(black, white);
    EXPECT_NEAR(r.mean, 0.967378, 2e-5);
    for (const glm::vec3& p : r.errorMap.pixels) EXPECT_NEAR(p.r, 0.967378, 2e-5);
}

TEST(Flip, ColourErrorGrowsWithTheDifferenceAndIsSymmetric) {
    for (glm::vec3 base : {glm::vec3(0.5f), glm::vec3(0.2f, 0.4f, 0.6f), glm::vec3(0.05f, 0.3f, 0.02f)}) {
        double previous = 0.0;
        for (float d : {0.005f, 0.01f, 0.02f, 0.05f, 0.1f, 0.2f, 0.35f}) {
            const Image reference = flat(8, 8, base), test = flat(8, 8, base + glm::vec3(d, 0.0f, 0.0f));
            const double forward = ldrFlip(test, reference).mean, backward = ldrFlip(reference, test).mean;
            EXPECT_GT(forward, previous) << "base " << base.g << ", d " << d;
            EXPECT_DOUBLE_EQ(forward, backward) << "base " << base.g << ", d " << d;
            EXPECT_LE(forward, 1.0);
            previous = forward;
        }
    }
}

TEST(Flip, AnEdgeMovedByOnePixelShowsAtTheEdge) {
    // A vertical black-to-white edge at column 32, and the same edge at column 33: the images differ in
    // one column, and the error must be around it (the filters spread it over a few pixels), not over
    // the flat parts.
    auto edgeAt = [](int column) {
        Image image(64, 16);
        for (int y = 0; y < 16; ++y)
            for (int x = column; x < 64; ++x) image.at(x, y) = glm::vec3(1.0f);
        return image;
    };
    const FlipResult r = ldrFlip(edgeAt(33), edgeAt(32));
    std::vector<double> column(64, 0.0);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 64; ++x) column[size_t(x)] += r.errorMap.at(x, y).r / 16.0;
    const int peak = int(std::max_element(column.begin(), column.end()) - column.begin());
    EXPECT_LE(std::abs(peak - 32), 2) << peak;
    EXPECT_GT(column[size_t(peak)], 0.5);
    double near = 0.0, total = 0.0;
    for (int x = 0; x < 64; ++x) {
        total += column[size_t(x)];
        if (std::abs(x - 32) <= 4) near += column[size_t(x)];
        // Beyond the reach of the widest filter (the CSF's 10 pixels at 67 pixels per degree) the
        // filtered images are equal.
        if (std::abs(x - 32) > 12) {
            EXPECT_EQ(column[size_t(x)], 0.0) << x;
        }
    }
    EXPECT_GT(near, 0.95 * total);
    // There the feature difference sharpens the colour error, deltaE = deltaE_c ^ (1 - deltaE_f).
    const std::vector<double> color = flipColorError(edgeAt(33), edgeAt(32), kDefaultPixelsPerDegree);
    const std::vector<double> feature = flipFeatureError(edgeAt(33), edgeAt(32), kDefaultPixelsPerDegree);
    for (size_t i = 0; i < color.size(); ++i)
        ASSERT_FLOAT_EQ(r.errorMap.pixels[i].r, float(std::pow(color[i], 1.0 - feature[i]))) << i;
    EXPECT_GT(r.errorMap.at(31, 8).r, color[8 * 64 + 31] + 0.05);
}

TEST(Flip, TheFeaturePipelineFindsAMovedEdgeWhereItMoved) {
    // The same one-pixel move through the feature pipeline alone: the edge and point detectors (19
    // pixels wide at 67 pixels per degree) answer differently only where they overlap column 32.
    Image reference(64, 16), test(64, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 64; ++x) {
            reference.at(x, y) = glm::vec3(x >= 32 ? 1.0f : 0.0f);
            test.at(x, y) = glm::vec3(x >= 33 ? 1.0f : 0.0f);
        }
    const std::vector<double> feature = flipFeatureError(test, reference, kDefaultPixelsPerDegree);
    std::vector<double> row(feature.begin() + 8 * 64, feature.begin() + 9 * 64);
    const int peak = int(std::max_element(row.begin(), row.end()) - row.begin());
    EXPECT_LE(std::abs(peak - 32), 1) << peak;
    EXPECT_GT(row[size_t(peak)], 0.3);
    for (int x = 0; x < 64; ++x) {
        if (std::abs(x - 32) > 10) {
            EXPECT_EQ(row[size_t(x)], 0.0) << x;
        }
    }
    // Flat fields have no features, whatever their colours.
    const Image red = flat(8, 8, {1.0f, 0.0f, 0.0f}), green = flat(8, 8, {0.0f, 1.0f, 0.0f});
    for (double f : flipFeatureError(red, green, kDefaultPixelsPerDegree)) EXPECT_NEAR(f, 0.0, 1e-6);
}

TEST(Flip, FineDetailFadesWithViewingDistance) {
    // A checker of single black and white pixels against its mean grey: up close (few pixels per
    // degree) the pattern is plain to see; far away the eye averages it to the grey. Measured in the
    // middle, beyond the filters' reach from the border (where the repeated edge pixels make stripes).
    Image checker(96, 96), grey = flat(96, 96, glm::vec3(0.5f));
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 96; ++x) checker.at(x, y) = glm::vec3(float((x + y) % 2));
    auto middle = [&](double ppd) {
        const FlipResult r = ldrFlip(checker, grey, ppd);
        double sum = 0.0;
        for (int y = 32; y < 64; ++y)
            for (int x = 32; x < 64; ++x) sum += r.errorMap.at(x, y).r;
        return sum / (32.0 * 32.0);
    };
    double previous = 2.0;
    for (double ppd : {5.0, 15.0, 30.0, kDefaultPixelsPerDegree}) {
        const double e = middle(ppd);
        EXPECT_LT(e, previous) << ppd;
        previous = e;
    }
    EXPECT_LE(middle(120.0), previous);
    EXPECT_GT(middle(5.0), 0.9);
    EXPECT_LT(middle(kDefaultPixelsPerDegree), 0.01);
}

TEST(Flip, RefusesMismatchedOrEmptyImagesAndBadViewing) {
    const Image a = flat(4, 4, glm::vec3(0.5f));
    EXPECT_THROW(ldrFlip(a, flat(4, 5, glm::vec3(0.5f))), Error);
    EXPECT_THROW(ldrFlip(Image(), Image()), Error);
    EXPECT_THROW(ldrFlip(a, a, 0.0), Error);
    EXPECT_THROW(ldrFlip(a, a, std::nan("")), Error);
    EXPECT_THROW(hdrFlip(a, flat(5, 4, glm::vec3(0.5f))), Error);
    EXPECT_THROW(hdrFlip(Image(), Image()), Error);
}

TEST(HdrFlip, IdenticalImagesGiveExactlyZero) {
    const Image image = noise(19, 13, 40.0f, 2);
    const FlipResult r = hdrFlip(image, image);
    EXPECT_EQ(r.mean, 0.0);
    for (const glm::vec3& p : r.errorMap.pixels) ASSERT_EQ(p, glm::vec3(0.0f));
}

TEST(HdrFlip, ExposureRangeFollowsThePaperFromTheReference) {
    // Grey pixels, so luminance = value * (0.2126 + 0.7152 + 0.0722) = value: the largest is 10, the
    // median 1. The tone curve t(x) = ACES(0.6 x) reaches 0.85 where
    // (2.51 - 0.85 * 2.43) u^2 + (0.03 - 0.85 * 0.59) u - 0.85 * 0.14 = 0, u = 0.6 x:
    // 0.4445 u^2 - 0.4715 u - 0.119 = 0, u = (0.4715 + sqrt(0.22231 + 0.211582)) / 0.889 = 1.271323,
    // x85 = 2.118872. start = log2(2.118872 / 10) = -2.238631, stop = log2(2.118872 / 1) = 1.083297,
    // count = max(2, ceil(3.321928)) = 4.
    Image reference(5, 1);
    const float values[5] = {0.25f, 0.5f, 1.0f, 2.0f, 10.0f};
    for (int x = 0; x < 5; ++x) reference.at(x, 0) = glm::vec3(values[x]);
    const FlipExposures e = hdrFlipExposures(reference);
    EXPECT_NEAR(e.start, -2.238631, 1e-5);
    EXPECT_NEAR(e.stop, 1.083297, 1e-5);
    EXPECT_EQ(e.count, 4);
    EXPECT_NEAR(hdrFlipToneMap(2.118872f), 0.85f, 1e-6f);
}

TEST(HdrFlip, ExposureRangeOfDarkOrBlackReferences) {
    // A median of 0 falls back to the median of the lit pixels (our choice, flip.h): 4 here.
    Image mostlyBlack(5, 1);
    mostlyBlack.at(3, 0) = glm::vec3(4.0f);
    mostlyBlack.at(4, 0) = glm::vec3(4.0f);
    const FlipExposures dark = hdrFlipExposures(mostlyBlack);
    EXPECT_DOUBLE_EQ(dark.start, dark.stop);
    EXPECT_EQ(dark.count, 2);
    const FlipExposures black = hdrFlipExposures(Image(3, 3));
    EXPECT_EQ(black.start, 0.0);
    EXPECT_EQ(black.stop, 0.0);
    EXPECT_EQ(black.count, 2);
}

TEST(HdrFlip, IsTheLargestLdrFlipOverTheExposures) {
    // A highlight error (10 against 12) is invisible at long exposures, where both clip to white, and
    // a shadow error (0.01 against 0.02) at short ones: HDR-FLIP keeps each at the exposure that shows it.
    // The highlight takes a quarter of the image, so the median (which sets the longest exposure) is
    // the shadow's.
    Image reference = flat(16, 16, glm::vec3(0.01f)), test = flat(16, 16, glm::vec3(0.02f));
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 4; ++x) {
            reference.at(x, y) = glm::vec3(10.0f);
            test.at(x, y) = glm::vec3(12.0f);
        }
    const FlipExposures e = hdrFlipExposures(reference);
    ASSERT_GE(e.count, 3);
    const FlipResult hdr = hdrFlip(test, reference, kDefaultPixelsPerDegree, e);
    std::vector<float> largest(hdr.errorMap.pixels.size(), 0.0f);
    for (int i = 0; i < e.count; ++i) {
        const double exposure = e.start + i * (e.stop - e.start) / (e.count - 1);
        const FlipResult one = hdrFlip(test, reference, kDefaultPixelsPerDegree, {exposure, exposure, 1});
        for (size_t p = 0; p < largest.size(); ++p)
            largest[p] = std::max(largest[p], one.errorMap.pixels[p].r);
    }
    double sum = 0.0;
    for (size_t p = 0; p < largest.size(); ++p) {
        ASSERT_EQ(hdr.errorMap.pixels[p].r, largest[p]) << p;
        sum += largest[p];
    }
    EXPECT_NEAR(hdr.mean, sum / double(largest.size()), 1e-12);
    const FlipResult shortest = hdrFlip(test, reference, kDefaultPixelsPerDegree, {e.start, e.start, 1});
    const FlipResult longest = hdrFlip(test, reference, kDefaultPixelsPerDegree, {e.stop, e.stop, 1});
    EXPECT_GT(shortest.errorMap.at(1, 8).r, longest.errorMap.at(1, 8).r);    // the highlight
    EXPECT_LT(shortest.errorMap.at(12, 8).r, longest.errorMap.at(12, 8).r);  // the shadow
}

}  // namespace
}  // namespace fp
