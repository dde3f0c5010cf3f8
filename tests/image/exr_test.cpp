#include "image/exr.h"

#include <gtest/gtest.h>
#include <tinyexr.h>

#include <cstdlib>
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

// The channels of an EXR's header as (name, pixel type), in file order, as tinyexr's own parser reads
// them.
std::vector<std::pair<std::string, int>> headerChannels(const std::string& path) {
    std::vector<std::pair<std::string, int>> channels;
    EXRVersion version;
    EXRHeader header;
    InitEXRHeader(&header);
    const char* err = nullptr;
    if (ParseEXRVersionFromFile(&version, path.c_str()) != TINYEXR_SUCCESS ||
        ParseEXRHeaderFromFile(&header, &version, path.c_str(), &err) != TINYEXR_SUCCESS) {
        ADD_FAILURE() << "cannot parse the header of " << path << ": " << (err ? err : "");
        if (err) FreeEXRErrorMessage(err);
        return channels;
    }
    for (int c = 0; c < header.num_channels; ++c)
        channels.emplace_back(header.channels[c].name, header.pixel_types[c]);
    FreeEXRHeader(&header);
    return channels;
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
    EXPECT_EQ(
        headerChannels(path),
        (std::vector<std::pair<std::string, int>>{
            {"B", TINYEXR_PIXELTYPE_FLOAT}, {"G", TINYEXR_PIXELTYPE_FLOAT}, {"R", TINYEXR_PIXELTYPE_FLOAT}}));
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

// Extra layers (render --aovs) go next to R, G, B as "<layer>.<channel>", all channels in name order
// as OpenEXR requires; they read back bit-exactly, each with its channels in R, G, B or X, Y, Z order,
// and a reader that asks only for the beauty still gets it.
TEST(Exr, LayersRoundTripBitExactlyInNameOrder) {
    std::mt19937 random(7);
    auto randomImage = [&](int channels) {
        Image image(5, 3);
        for (glm::vec3& p : image.pixels)
            for (int c = 0; c < channels; ++c) p[c] = test::floatFromBits(random());
        return image;
    };
    const Image beauty = randomImage(3);
    const std::vector<ExrLayer> layers = {{"normal", {"X", "Y", "Z"}, randomImage(3)},
                                          {"albedo", {"R", "G", "B"}, randomImage(3)},
                                          {"depth", {"Z"}, randomImage(1)},
                                          {"diffuse", {"red", "green", "blue"}, randomImage(3)}};
    TempDir dir;
    const std::string path = dir.file("layers.exr");
    writeExr(path, beauty, {{"fragpath.samples", "4"}}, layers);

    std::vector<std::string> names;
    for (const auto& [name, type] : headerChannels(path)) names.push_back(name);
    EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "R", "albedo.B", "albedo.G", "albedo.R", "depth.Z",
                                               "diffuse.blue", "diffuse.green", "diffuse.red", "normal.X",
                                               "normal.Y", "normal.Z"}));

    ExrAttributes attributes;
    std::vector<ExrLayer> read;
    expectBitIdentical(readExr(path, &attributes, &read), beauty);
    EXPECT_EQ(attributes, (ExrAttributes{{"fragpath.samples", "4"}}));
    expectBitIdentical(readImage(path), beauty);
    ASSERT_EQ(read.size(), 4u);
    // In the order of their names; channels in the conventional order, else the file's (sorted) order.
    const std::vector<std::pair<const ExrLayer*, std::vector<int>>> expected = {
        {&layers[1], {0, 1, 2}}, {&layers[2], {0}}, {&layers[3], {2, 1, 0}}, {&layers[0], {0, 1, 2}}};
    for (size_t l = 0; l < read.size(); ++l) {
        const ExrLayer& original = *expected[l].first;
        const std::vector<int>& order = expected[l].second;
        EXPECT_EQ(read[l].name, original.name);
        ASSERT_EQ(read[l].channels.size(), order.size()) << original.name;
        for (size_t c = 0; c < order.size(); ++c) {
            EXPECT_EQ(read[l].channels[c], original.channels[size_t(order[c])]);
            for (size_t i = 0; i < original.image.pixels.size(); ++i)
                ASSERT_EQ(bitsOf(read[l].image.pixels[i][int(c)]), bitsOf(original.image.pixels[i][order[c]]))
                    << original.name << "." << original.channels[size_t(order[c])] << " pixel " << i;
        }
    }
}

TEST(Exr, InvalidLayersAreRejectedAndLeaveNoFile) {
    TempDir dir;
    const std::string path = dir.file("bad.exr");
    const Image one(1, 1);
    const std::vector<std::vector<ExrLayer>> invalid = {
        {{"", {"R"}, one}},
        {{"a.b", {"R"}, one}},
        {{"albedo", {}, one}},
        {{"albedo", {"R", "G", "B", "A"}, one}},
        {{"albedo", {"R", ""}, one}},
        {{"albedo", {"R.x"}, one}},
        {{"albedo", {"R", "R"}, one}},
        {{"albedo", {"R"}, one}, {"albedo", {"R"}, one}},
        {{"albedo", {"R"}, Image(2, 1)}},
        {{std::string(250, 'n'), {"channel"}, one}},
    };
    for (const std::vector<ExrLayer>& layers : invalid) {
        const std::string message = errorMessage([&] { writeExr(path, one, {}, layers); });
        EXPECT_NE(message.find(path), std::string::npos) << message;
    }
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

// --- Radiance images (environment maps): decodeExrRadiance ---

// One channel as a test writes it: its name, how the file stores it, and its values (one per pixel).
struct TestChannel {
    std::string name;
    int stored = TINYEXR_PIXELTYPE_FLOAT;
    std::vector<float> values;
};

// The bytes of an EXR of `channels` (given in name order, as OpenEXR wants), written by tinyexr: one
// scanline part, or with `tiled` one tile covering the image.
std::vector<std::uint8_t> exrBytes(int width, int height, const std::vector<TestChannel>& channels,
                                   bool tiled = false) {
    const size_t count = channels.size(), pixels = size_t(width) * size_t(height);
    std::vector<std::vector<std::uint32_t>> planes(count);
    std::vector<unsigned char*> pointers(count);
    std::vector<EXRChannelInfo> info(count);
    std::vector<int> given(count), stored(count);
    for (size_t c = 0; c < count; ++c) {
        planes[c].resize(pixels);
        for (size_t i = 0; i < pixels; ++i) {
            const float v = channels[c].values[i];
            planes[c][i] = channels[c].stored == TINYEXR_PIXELTYPE_UINT ? std::uint32_t(v) : test::bitsOf(v);
        }
        pointers[c] = reinterpret_cast<unsigned char*>(planes[c].data());
        std::memset(&info[c], 0, sizeof info[c]);
        std::strcpy(info[c].name, channels[c].name.c_str());
        stored[c] = channels[c].stored;
        given[c] = stored[c] == TINYEXR_PIXELTYPE_UINT ? TINYEXR_PIXELTYPE_UINT : TINYEXR_PIXELTYPE_FLOAT;
    }
    EXRTile tile;
    std::memset(&tile, 0, sizeof tile);
    tile.width = width;
    tile.height = height;
    tile.images = pointers.data();
    EXRImage image;
    InitEXRImage(&image);
    image.width = width;
    image.height = height;
    image.num_channels = int(count);
    if (tiled) {
        image.tiles = &tile;
        image.num_tiles = 1;
    } else {
        image.images = pointers.data();
    }
    EXRHeader header;
    InitEXRHeader(&header);
    header.num_channels = int(count);
    header.channels = info.data();
    header.pixel_types = given.data();
    header.requested_pixel_types = stored.data();
    header.compression_type = TINYEXR_COMPRESSIONTYPE_NONE;
    if (tiled) {
        header.tiled = 1;
        header.tile_size_x = width;
        header.tile_size_y = height;
        header.tile_level_mode = TINYEXR_TILE_ONE_LEVEL;
        header.tile_rounding_mode = TINYEXR_TILE_ROUND_DOWN;
    }
    unsigned char* memory = nullptr;
    const char* err = nullptr;
    const size_t size = SaveEXRImageToMemory(&image, &header, &memory, &err);
    if (size == 0 || !memory) {
        ADD_FAILURE() << "tinyexr cannot write the test file: " << (err ? err : "");
        if (err) FreeEXRErrorMessage(err);
        std::free(memory);
        return {};
    }
    std::vector<std::uint8_t> bytes(memory, memory + size);
    std::free(memory);
    return bytes;
}

// A 2x1 image's R, G, B (and A) channels.
std::vector<TestChannel> rgbChannels(int stored = TINYEXR_PIXELTYPE_FLOAT) {
    return {{"A", stored, {1.0f, 1.0f}},
            {"B", stored, {0.75f, 8.0f}},
            {"G", stored, {0.5f, 4.0f}},
            {"R", stored, {0.25f, 2.0f}}};
}

TEST(ExrRadiance, ReadsRgbOfHalfOrFloatIgnoringOtherChannels) {
    for (int stored : {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_HALF}) {
        std::vector<TestChannel> channels = rgbChannels(stored);
        channels.push_back({"diffuse.R", stored, {9.0f, 9.0f}});
        const Image image = decodeExrRadiance(exrBytes(2, 1, channels), "sky.exr");
        ASSERT_EQ(image.width, 2);
        ASSERT_EQ(image.height, 1);
        EXPECT_EQ(image.at(0, 0), glm::vec3(0.25f, 0.5f, 0.75f));
        EXPECT_EQ(image.at(1, 0), glm::vec3(2.0f, 4.0f, 8.0f));
    }
}

TEST(ExrRadiance, ASingleLuminanceChannelIsGrey) {
    const Image image =
        decodeExrRadiance(exrBytes(2, 1, {{"Y", TINYEXR_PIXELTYPE_HALF, {0.5f, 3.0f}}}), "y.exr");
    EXPECT_EQ(image.at(0, 0), glm::vec3(0.5f));
    EXPECT_EQ(image.at(1, 0), glm::vec3(3.0f));
}

// decodeExrRadiance's message for `bytes`, which must name the file.
std::string radianceError(const std::vector<std::uint8_t>& bytes) {
    std::string message = errorMessage([&] { decodeExrRadiance(bytes, "sky.exr"); });
    EXPECT_NE(message.find("cannot read EXR 'sky.exr': "), std::string::npos) << message;
    return message;
}

TEST(ExrRadiance, OtherChannelLayoutsAreClearErrors) {
    // A lone channel that is not luminance: alpha, depth (the general reader shows them as grey).
    EXPECT_NE(radianceError(exrBytes(2, 1, {{"A", TINYEXR_PIXELTYPE_FLOAT, {1, 1}}}))
                  .find("needs R, G and B channels (or a single Y), found A"),
              std::string::npos);
    EXPECT_NO_THROW(decodeExr(exrBytes(2, 1, {{"A", TINYEXR_PIXELTYPE_FLOAT, {1, 1}}}), "a.exr"));
    // Luminance and chroma (Y, RY, BY), and colour only in a layer.
    EXPECT_NE(radianceError(exrBytes(2, 1,
                                     {{"BY", TINYEXR_PIXELTYPE_HALF, {0, 0}},
                                      {"RY", TINYEXR_PIXELTYPE_HALF, {0, 0}},
                                      {"Y", TINYEXR_PIXELTYPE_HALF, {1, 1}}}))
                  .find("found BY, RY, Y"),
              std::string::npos);
    EXPECT_NE(radianceError(exrBytes(2, 1,
                                     {{"sky.B", TINYEXR_PIXELTYPE_FLOAT, {0, 0}},
                                      {"sky.G", TINYEXR_PIXELTYPE_FLOAT, {0, 0}},
                                      {"sky.R", TINYEXR_PIXELTYPE_FLOAT, {1, 1}}}))
                  .find("found sky.B, sky.G, sky.R"),
              std::string::npos);
    // Integers are ids or counts, not radiance.
    std::vector<TestChannel> integers = rgbChannels();
    integers[2].stored = TINYEXR_PIXELTYPE_UINT;
    EXPECT_NE(radianceError(exrBytes(2, 1, integers)).find("channel G holds 32-bit integers (UINT)"),
              std::string::npos);
}

TEST(ExrRadiance, MultiPartDeepAndTiledFilesAreClearErrors) {
    EXPECT_NE(radianceError(exrBytes(2, 1, rgbChannels(), true)).find("tiled files are not supported"),
              std::string::npos);
    // Debian's tinyexr writes neither multi-part nor deep files: the version field's flags say what a
    // file is (OpenEXR file layout: bit 11 "non-image", bit 12 "multi-part"), and they are read first.
    for (auto [bit, why] :
         {std::pair{0x10, "multi-part files are not supported"}, {0x08, "deep files are not supported"}}) {
        std::vector<std::uint8_t> bytes = exrBytes(2, 1, rgbChannels());
        ASSERT_GT(bytes.size(), 8u);
        bytes[5] |= std::uint8_t(bit);
        EXPECT_NE(radianceError(bytes).find(why), std::string::npos);
    }
    // And anything else is not an EXR at all.
    EXPECT_NE(radianceError(test::bytesOf("#?RADIANCE\n")).find("not an OpenEXR file"), std::string::npos);
}

TEST(ExrRadiance, ReadsAFileWrittenByWriteExrBitForBit) {
    TempDir dir;
    Image sky(3, 2);
    for (size_t i = 0; i < sky.pixels.size(); ++i) sky.pixels[i] = glm::vec3(float(i) / 7.0f, 1e-3f, 1e4f);
    writeExr(dir.file("sky.exr"), sky);
    expectBitIdentical(readExrRadiance(dir.file("sky.exr")), sky);
}

}  // namespace
}  // namespace fp
