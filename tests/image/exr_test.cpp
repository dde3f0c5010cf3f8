#include "image/exr.h"

#include <gtest/gtest.h>
#include <tinyexr.h>

#include <cstring>
#include <random>
#include <string>

#include "image/test_files.h"

namespace fp {
namespace {

using test::bitsOf;
using test::errorMessage;
using test::TempDir;

void expectBitIdentical(const Image& loaded, const Image& original) {
    ASSERT_EQ(loaded.width, original.width);
    ASSERT_EQ(loaded.height, original.height);
    for (int y = 0; y < original.height; ++y) {
        for (int x = 0; x < original.width; ++x) {
            ASSERT_EQ(bitsOf(loaded.at(x, y)), bitsOf(original.at(x, y))) << "pixel " << x << "," << y;
        }
    }
}

TEST(Exr, RoundTripOfAwkwardValuesIsBitExact) {
    TempDir dir;
    const Image original = test::awkwardImage();
    writeImage(dir.file("a.exr"), original);
    expectBitIdentical(readImage(dir.file("a.exr")), original);
}

TEST(Exr, RoundTripOfMultiChunkImageIsBitExactAndKeepsOrientation) {
    // 37x41 spans several 16-scanline ZIP chunks; random bit patterns cover the whole float range.
    std::mt19937 random(12345);
    Image original(37, 41);
    for (glm::vec3& p : original.pixels) {
        p = {test::floatFromBits(random()), test::floatFromBits(random()), test::floatFromBits(random())};
    }
    original.at(0, 0) = {1.0f, 2.0f, 3.0f};  // a marker in the top-left corner
    TempDir dir;
    writeImage(dir.file("big.exr"), original);
    const Image loaded = readImage(dir.file("big.exr"));
    expectBitIdentical(loaded, original);
    EXPECT_EQ(loaded.at(0, 0), glm::vec3(1.0f, 2.0f, 3.0f));
}

TEST(Exr, StoresFloatChannelsBGR) {
    TempDir dir;
    const std::string path = dir.file("types.exr");
    writeExr(path, Image(2, 2));
    EXRVersion version;
    ASSERT_EQ(ParseEXRVersionFromFile(&version, path.c_str()), TINYEXR_SUCCESS);
    EXRHeader header;
    InitEXRHeader(&header);
    const char* err = nullptr;
    ASSERT_EQ(ParseEXRHeaderFromFile(&header, &version, path.c_str(), &err), TINYEXR_SUCCESS);
    ASSERT_EQ(header.num_channels, 3);
    const char* expected[] = {"B", "G", "R"};
    for (int c = 0; c < 3; ++c) {
        EXPECT_STREQ(header.channels[c].name, expected[c]);
        EXPECT_EQ(header.pixel_types[c], TINYEXR_PIXELTYPE_FLOAT);
    }
    FreeEXRHeader(&header);
}

TEST(Exr, CustomStringAttributesRoundTrip) {
    TempDir dir;
    const std::string path = dir.file("attrs.exr");
    const ExrAttributes attributes = {
        {"fragpath:sampleRange", "0 1023"},
        {"fragpath:scene", "cornell box, \"quoted\" and unicode \xc3\xa9"},
        {"empty", ""},
        {"a.name.longer.than.thirty.one.bytes.needs.the.long.name.flag", "long"},
    };
    writeExr(path, test::awkwardImage(), attributes);

    ExrAttributes loaded;
    const Image image = readExr(path, &loaded);
    EXPECT_EQ(loaded, attributes);
    expectBitIdentical(image, test::awkwardImage());
}

TEST(Exr, NoAttributesReadBackAsEmpty) {
    TempDir dir;
    writeExr(dir.file("plain.exr"), Image(1, 1));
    ExrAttributes loaded = {{"stale", "entry"}};
    readExr(dir.file("plain.exr"), &loaded);
    EXPECT_TRUE(loaded.empty());
}

TEST(Exr, InvalidAttributesAreRejectedAndLeaveNoFile) {
    TempDir dir;
    const std::string path = dir.file("bad.exr");
    const ExrAttributes invalid[] = {
        {{"compression", "none"}},
        {{"dataWindow", "x"}},
        {{"", "unnamed"}},
        {{"dup", "1"}, {"dup", "2"}},
        {{"nul", std::string("a\0b", 3)}},
        {{std::string(256, 'n'), "too long"}},
    };
    for (const ExrAttributes& attributes : invalid) {
        const std::string message = errorMessage([&] { writeExr(path, Image(1, 1), attributes); });
        EXPECT_NE(message.find(path), std::string::npos) << message;
    }
    ExrAttributes tooMany;
    for (int i = 0; i < 129; ++i) tooMany.emplace_back("k" + std::to_string(i), "v");
    EXPECT_THROW(writeExr(path, Image(1, 1), tooMany), Error);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(Exr, ReadsHalfChannelsAsFloat) {
    // A file written by tinyexr's own convenience writer with HALF channels; these values are exactly
    // representable in half precision, so they must come back unchanged.
    TempDir dir;
    const std::string path = dir.file("half.exr");
    const float rgb[] = {0.5f, -2.0f, 1024.0f, 0.0f, 65504.0f, 0.125f};  // 2x1, interleaved RGB
    const char* err = nullptr;
    ASSERT_EQ(SaveEXR(rgb, 2, 1, 3, 1, path.c_str(), &err), TINYEXR_SUCCESS);
    const Image image = readImage(path);
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 1);
    EXPECT_EQ(image.at(0, 0), glm::vec3(0.5f, -2.0f, 1024.0f));
    EXPECT_EQ(image.at(1, 0), glm::vec3(0.0f, 65504.0f, 0.125f));
}

TEST(Exr, SingleChannelIsReplicatedToGrey) {
    TempDir dir;
    const std::string path = dir.file("grey.exr");
    const float values[] = {0.25f, 4.0f};  // 1x2: top, bottom
    const char* err = nullptr;
    ASSERT_EQ(SaveEXR(values, 1, 2, 1, 0, path.c_str(), &err), TINYEXR_SUCCESS);
    const Image image = readImage(path);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.at(0, 0), glm::vec3(0.25f));
    EXPECT_EQ(image.at(0, 1), glm::vec3(4.0f));
}

TEST(Exr, NonExrAndMissingFilesAreRejectedNamingTheFile) {
    TempDir dir;
    const std::string text = dir.file("text.exr");
    test::writeBytes(text, test::bytesOf("this is not an image\n"));
    std::string message = errorMessage([&] { readImage(text); });
    EXPECT_NE(message.find(text), std::string::npos) << message;

    const std::string empty = dir.file("empty.exr");
    test::writeBytes(empty, {});
    message = errorMessage([&] { readImage(empty); });
    EXPECT_NE(message.find(empty), std::string::npos) << message;

    const std::string missing = dir.file("missing.exr");
    message = errorMessage([&] { readImage(missing); });
    EXPECT_NE(message.find(missing), std::string::npos) << message;
    EXPECT_NE(message.find("no such file"), std::string::npos) << message;
}

TEST(Exr, TruncatedFileIsRejectedNamingTheFile) {
    TempDir dir;
    const std::string path = dir.file("cut.exr");
    writeImage(path, test::awkwardImage());
    std::vector<std::uint8_t> bytes = test::readBytes(path);
    bytes.resize(bytes.size() / 2);
    test::writeBytes(path, bytes);
    const std::string message = errorMessage([&] { readImage(path); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
}

}  // namespace
}  // namespace fp
