#include "image/pfm.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "image/test_files.h"

namespace fp {
namespace {

using test::bitsOf;
using test::bytesOf;
using test::errorMessage;
using test::floatFromBits;
using test::readBytes;
using test::TempDir;
using test::writeBytes;

// Big-endian bytes of a float, for hand-made files.
void appendBigEndian(std::vector<std::uint8_t>& out, float value) {
    const std::uint32_t bits = bitsOf(value);
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(bits >> shift));
}

float littleEndianAt(const std::vector<std::uint8_t>& bytes, size_t offset) {
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) bits |= std::uint32_t(bytes[offset + size_t(i)]) << (8 * i);
    return floatFromBits(bits);
}

TEST(Pfm, RoundTripIsBitExact) {
    TempDir dir;
    const Image original = test::awkwardImage();
    writeImage(dir.file("a.pfm"), original);
    const Image loaded = readImage(dir.file("a.pfm"));
    ASSERT_EQ(loaded.width, original.width);
    ASSERT_EQ(loaded.height, original.height);
    for (int y = 0; y < original.height; ++y) {
        for (int x = 0; x < original.width; ++x) {
            EXPECT_EQ(bitsOf(loaded.at(x, y)), bitsOf(original.at(x, y))) << "pixel " << x << "," << y;
        }
    }
}

TEST(Pfm, WritesColourLittleEndianHeader) {
    Image image(3, 2);
    const std::vector<std::uint8_t> bytes = encodePfm(image);
    const std::string header = "PF\n3 2\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 3 * 2 * 12);
    EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + std::ptrdiff_t(header.size())), header);
}

TEST(Pfm, FileStoresBottomRowFirstAndReadsBackTopRowOnTop) {
    TempDir dir;
    Image image(2, 2);
    image.at(0, 0) = {1.0f, 2.0f, 3.0f};  // top row
    image.at(1, 0) = {4.0f, 5.0f, 6.0f};
    image.at(0, 1) = {-1.0f, -2.0f, -3.0f};  // bottom row
    image.at(1, 1) = {-4.0f, -5.0f, -6.0f};
    const std::string path = dir.file("rows.pfm");
    writeImage(path, image);

    const std::vector<std::uint8_t> bytes = readBytes(path);
    const size_t data = std::string("PF\n2 2\n-1.0\n").size();
    ASSERT_EQ(bytes.size(), data + 4 * 12);
    // The first stored pixel is the bottom-left one, the second row stored is the top row.
    EXPECT_EQ(littleEndianAt(bytes, data + 0), -1.0f);
    EXPECT_EQ(littleEndianAt(bytes, data + 8), -3.0f);
    EXPECT_EQ(littleEndianAt(bytes, data + 12), -4.0f);
    EXPECT_EQ(littleEndianAt(bytes, data + 24), 1.0f);
    EXPECT_EQ(littleEndianAt(bytes, data + 44), 6.0f);

    const Image loaded = readImage(path);
    EXPECT_EQ(loaded.at(0, 0), glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(loaded.at(1, 0), glm::vec3(4.0f, 5.0f, 6.0f));
    EXPECT_EQ(loaded.at(0, 1), glm::vec3(-1.0f, -2.0f, -3.0f));
    EXPECT_EQ(loaded.at(1, 1), glm::vec3(-4.0f, -5.0f, -6.0f));
}

TEST(Pfm, ReadsHandMadeBigEndianGreyscale) {
    TempDir dir;
    // 2x2 "Pf" with a positive scale (big-endian); stored rows: bottom (0.25, 2), then top (-8, 1e20).
    std::vector<std::uint8_t> bytes = bytesOf("Pf\n2 2\n1.0\n");
    for (float v : {0.25f, 2.0f, -8.0f, 1e20f}) appendBigEndian(bytes, v);
    const std::string path = dir.file("grey.pfm");
    writeBytes(path, bytes);

    const Image image = readImage(path);
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.at(0, 0), glm::vec3(-8.0f));
    EXPECT_EQ(image.at(1, 0), glm::vec3(1e20f));
    EXPECT_EQ(image.at(0, 1), glm::vec3(0.25f));
    EXPECT_EQ(image.at(1, 1), glm::vec3(2.0f));
}

TEST(Pfm, ReadsHandMadeBigEndianColourWithOtherWhitespaceAndScale) {
    // Fields may be separated by any whitespace; the scale's magnitude is not applied.
    std::vector<std::uint8_t> bytes = bytesOf("PF 1\t1\r\n2.5\n");
    for (float v : {0.5f, -0.75f, 3.0f}) appendBigEndian(bytes, v);
    const Image image = decodePfm(bytes, "memory");
    ASSERT_EQ(image.width, 1);
    ASSERT_EQ(image.height, 1);
    EXPECT_EQ(image.at(0, 0), glm::vec3(0.5f, -0.75f, 3.0f));
}

TEST(Pfm, DataStartingWithWhitespaceBytesIsNotSkipped) {
    // 0x0a0a0a0a little-endian is a valid float whose bytes are all '\n'.
    std::vector<std::uint8_t> bytes = bytesOf("Pf\n1 1\n-1\n");
    bytes.insert(bytes.end(), {0x0a, 0x0a, 0x0a, 0x0a});
    const Image image = decodePfm(bytes, "memory");
    EXPECT_EQ(bitsOf(image.at(0, 0).r), 0x0a0a0a0au);
}

TEST(Pfm, TruncatedFileIsRejectedNamingTheFile) {
    TempDir dir;
    const std::string path = dir.file("cut.pfm");
    writeImage(path, test::awkwardImage());
    std::vector<std::uint8_t> bytes = readBytes(path);
    bytes.pop_back();
    writeBytes(path, bytes);
    const std::string message = errorMessage([&] { readImage(path); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST(Pfm, TrailingBytesAreRejected) {
    std::vector<std::uint8_t> bytes = encodePfm(Image(1, 1));
    bytes.push_back(0);
    EXPECT_THROW(decodePfm(bytes, "memory"), Error);
}

TEST(Pfm, MalformedHeadersAreRejectedNamingTheFile) {
    const char* headers[] = {"",
                             "P6\n1 1\n255\n",
                             "PF",
                             "PF\n0 1\n-1\n",
                             "PF\n1 -1\n-1\n",
                             "PF\n1\n-1\n",
                             "PF\n1 1\n0\n",
                             "PF\n1 1\nabc\n",
                             "PF\n1 1\nnan\n",
                             "PF\n99999999999 1\n-1\n",
                             "PF\n1 1\n-1"};
    for (const char* header : headers) {
        const std::string message = errorMessage([&] { decodePfm(bytesOf(header), "bad.pfm"); });
        EXPECT_NE(message.find("'bad.pfm'"), std::string::npos) << "header: " << header;
    }
}

TEST(Pfm, HugeDeclaredSizeIsRejectedWithoutAllocating) {
    // 2^31-1 squared pixels would need exabytes; the size check must come before allocation.
    EXPECT_THROW(decodePfm(bytesOf("PF\n2147483647 2147483647\n-1\n"), "big.pfm"), Error);
}

TEST(Pfm, MissingFileIsRejectedNamingTheFile) {
    TempDir dir;
    const std::string path = dir.file("absent.pfm");
    const std::string message = errorMessage([&] { readImage(path); });
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("no such file"), std::string::npos) << message;
}

}  // namespace
}  // namespace fp
