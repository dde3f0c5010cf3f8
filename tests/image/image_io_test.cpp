// writeImage / readImage: dispatch by extension and the failure behaviour shared by all formats.
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "image/image.h"
#include "image/test_files.h"

namespace fp {
namespace {

using test::errorMessage;
using test::TempDir;

std::string prefixOf(const std::string& path, size_t n) {
    const std::vector<std::uint8_t> bytes = test::readBytes(path);
    return std::string(bytes.begin(), bytes.begin() + std::ptrdiff_t(std::min(n, bytes.size())));
}

void expectMentions(const std::string& message, const std::string& a, const std::string& b = "") {
    EXPECT_NE(message.find(a), std::string::npos) << "'" << a << "' not in: " << message;
    if (!b.empty()) {
        EXPECT_NE(message.find(b), std::string::npos) << "'" << b << "' not in: " << message;
    }
}

TEST(ImageIo, ExtensionPicksFormatCaseInsensitively) {
    TempDir dir;
    const Image image(2, 2);
    writeImage(dir.file("a.PFM"), image);
    writeImage(dir.file("b.Exr"), image);
    writeImage(dir.file("c.pNg"), image);
    EXPECT_EQ(prefixOf(dir.file("a.PFM"), 3), "PF\n");
    EXPECT_EQ(prefixOf(dir.file("b.Exr"), 4), std::string("\x76\x2f\x31\x01", 4));  // OpenEXR magic
    EXPECT_EQ(prefixOf(dir.file("c.pNg"), 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(readImage(dir.file("a.PFM")).width, 2);
    EXPECT_EQ(readImage(dir.file("b.Exr")).width, 2);
    // Only the final files remain: no temporaries.
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.PFM", "b.Exr", "c.pNg"}));
}

TEST(ImageIo, UnknownExtensionThrowsNamingThePathAndWritesNothing) {
    TempDir dir;
    for (const char* name : {"out.jpg", "out", "out.pfm.bak", ".png"}) {
        const std::string path = dir.file(name);
        expectMentions(errorMessage([&] { writeImage(path, Image(1, 1)); }), path, "extension");
    }
    // A directory whose name looks like an image does not make its contents one.
    const std::string path = dir.file("dir.png/out");
    expectMentions(errorMessage([&] { writeImage(path, Image(1, 1)); }), path);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageIo, MissingDirectoryThrowsWithReason) {
    TempDir dir;
    for (const char* name : {"missing/out.png", "missing/out.exr", "missing/out.pfm"}) {
        const std::string path = dir.file(name);
        expectMentions(errorMessage([&] { writeImage(path, Image(1, 1)); }), path,
                       "No such file or directory");
    }
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageIo, ParentThatIsAFileThrowsWithReason) {
    TempDir dir;
    test::writeBytes(dir.file("plain"), test::bytesOf("x"));
    const std::string path = dir.file("plain/out.pfm");
    expectMentions(errorMessage([&] { writeImage(path, Image(1, 1)); }), path, "Not a directory");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"plain"});
}

TEST(ImageIo, FailedRenameRemovesTheTemporaryFile) {
    // The target is a directory, so the temporary file is written but cannot replace it.
    TempDir dir;
    std::filesystem::create_directory(dir.file("taken.exr"));
    const std::string path = dir.file("taken.exr");
    expectMentions(errorMessage([&] { writeImage(path, Image(3, 3)); }), path, "Is a directory");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken.exr"});
    EXPECT_TRUE(std::filesystem::is_empty(path));
}

TEST(ImageIo, OverwritesAnExistingFileCompletely) {
    TempDir dir;
    const std::string path = dir.file("again.pfm");
    writeImage(path, Image(8, 8));
    Image small(1, 1);
    small.at(0, 0) = {1.0f, 2.0f, 3.0f};
    writeImage(path, small);
    const Image loaded = readImage(path);
    EXPECT_EQ(loaded.width, 1);
    EXPECT_EQ(loaded.at(0, 0), glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"again.pfm"});
}

TEST(ImageIo, MalformedImagesAreRejectedBeforeWriting) {
    TempDir dir;
    Image lying(2, 2);
    lying.pixels.pop_back();
    for (const char* name : {"a.png", "a.exr", "a.pfm"}) {
        const std::string path = dir.file(name);
        expectMentions(errorMessage([&] { writeImage(path, Image()); }), path, "empty");
        expectMentions(errorMessage([&] { writeImage(path, lying); }), path);
    }
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageIo, ReadErrorsNameTheFile) {
    TempDir dir;
    const std::string missing = dir.file("none.exr");
    expectMentions(errorMessage([&] { readImage(missing); }), missing, "no such file");

    const std::string png = dir.file("shown.png");
    writeImage(png, Image(1, 1));
    expectMentions(errorMessage([&] { readImage(png); }), png, "extension");

    const std::string unknown = dir.file("data.txt");
    test::writeBytes(unknown, test::bytesOf("hello"));
    expectMentions(errorMessage([&] { readImage(unknown); }), unknown);

    const std::string notPfm = dir.file("fake.pfm");
    test::writeBytes(notPfm, test::bytesOf("hello"));
    expectMentions(errorMessage([&] { readImage(notPfm); }), notPfm);

    const std::string folder = dir.file("folder.pfm");
    std::filesystem::create_directory(folder);
    expectMentions(errorMessage([&] { readImage(folder); }), folder, "is a directory");
}

TEST(ImageIo, ReadImageOrPngDecodesPngToLinear) {
    TempDir dir;
    Image image(3, 1);
    image.at(0, 0) = glm::vec3(0.0f, 0.2f, 1.0f);
    image.at(1, 0) = glm::vec3(0.5f, 0.05f, 0.8f);
    image.at(2, 0) = glm::vec3(2.0f, -1.0f, 0.001f);  // a display shows these clamped
    const std::string png = dir.file("shown.png");
    writeImage(png, image);
    const Image read = readImageOrPng(png);
    ASSERT_EQ(read.width, 3);
    ASSERT_EQ(read.height, 1);
    for (int x = 0; x < 3; ++x)
        for (int c = 0; c < 3; ++c) {
            // Half an 8-bit step of the sRGB curve, at its steepest in linear terms near 1.
            const float expected = std::min(std::max(image.at(x, 0)[c], 0.0f), 1.0f);
            EXPECT_NEAR(read.at(x, 0)[c], expected, 0.0045f) << x << " " << c;
        }
    // Linear formats go through readImage unchanged; errors name the file.
    const std::string pfm = dir.file("linear.pfm");
    writeImage(pfm, image);
    EXPECT_EQ(readImageOrPng(pfm).pixels, readImage(pfm).pixels);
    const std::string broken = dir.file("broken.png");
    test::writeBytes(broken, test::bytesOf("hello"));
    expectMentions(errorMessage([&] { readImageOrPng(broken); }), broken);
}

}  // namespace
}  // namespace fp
