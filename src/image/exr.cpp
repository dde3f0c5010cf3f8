#include "image/exr.h"

#include <tinyexr.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <set>

#include "core/error.h"
#include "core/file.h"
#include "image/file_io.h"
#include "image/image_check.h"

namespace fp {

namespace {

// tinyexr keeps at most this many non-standard attributes when reading (TINYEXR_MAX_CUSTOM_ATTRIBUTES).
constexpr size_t kMaxAttributes = TINYEXR_MAX_CUSTOM_ATTRIBUTES;

// Attribute names the OpenEXR 2 file layout gives a fixed meaning; tinyexr writes the first ones itself.
const std::set<std::string>& reservedNames() {
    static const std::set<std::string> names = {"channels",
                                                "compression",
                                                "dataWindow",
                                                "displayWindow",
                                                "lineOrder",
                                                "pixelAspectRatio",
                                                "screenWindowCenter",
                                                "screenWindowWidth",
                                                "tiles",
                                                "name",
                                                "type",
                                                "version",
                                                "chunkCount",
                                                "maxSamplesPerPixel",
                                                "view"};
    return names;
}

void checkAttributes(const ExrAttributes& attributes) {
    if (attributes.size() > kMaxAttributes) {
        throw Error("too many EXR attributes (" + std::to_string(attributes.size()) + ", at most " +
                    std::to_string(kMaxAttributes) + ")");
    }
    std::set<std::string> seen;
    for (const auto& [name, value] : attributes) {
        if (name.empty() || name.size() > 255 || name.find('\0') != std::string::npos) {
            throw Error("invalid EXR attribute name '" + name + "' (1 to 255 bytes, no NUL)");
        }
        if (reservedNames().count(name)) throw Error("EXR attribute name '" + name + "' is reserved");
        if (!seen.insert(name).second) throw Error("duplicate EXR attribute '" + name + "'");
        if (value.find('\0') != std::string::npos) {
            throw Error("EXR attribute '" + name + "' contains a NUL byte");
        }
    }
}

// Owns what tinyexr allocates while reading, so every error path below releases it.
struct ParsedExr {
    EXRHeader header;
    EXRImage image;
    bool headerLoaded = false, imageLoaded = false;
    ParsedExr() {
        InitEXRHeader(&header);
        InitEXRImage(&image);
    }
    ~ParsedExr() {
        if (imageLoaded) FreeEXRImage(&image);
        if (headerLoaded) FreeEXRHeader(&header);
    }
    ParsedExr(const ParsedExr&) = delete;
    ParsedExr& operator=(const ParsedExr&) = delete;
};

// Takes ownership of tinyexr's error string (which must be released with FreeEXRErrorMessage).
std::string takeMessage(const char* err, int code) {
    std::string message = err ? std::string(err) : "tinyexr error " + std::to_string(code);
    if (err) FreeEXRErrorMessage(err);
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    return message;
}

float channelValue(const EXRImage& image, const EXRHeader& header, int channel, size_t index) {
    const unsigned char* plane = image.images[channel];
    if (header.requested_pixel_types[channel] == TINYEXR_PIXELTYPE_UINT) {
        std::uint32_t value = 0;
        std::memcpy(&value, plane + 4 * index, 4);
        return static_cast<float>(value);
    }
    float value = 0.0f;
    std::memcpy(&value, plane + 4 * index, 4);
    return value;
}

}  // namespace

std::vector<std::uint8_t> encodeExr(const Image& image, const ExrAttributes& attributes) {
    checkImageShape(image, "cannot encode EXR");
    checkAttributes(attributes);

    // OpenEXR readers expect channels sorted by name, hence B, G, R.
    const char* names[3] = {"B", "G", "R"};
    std::vector<float> planes[3];
    for (int c = 0; c < 3; ++c) {
        const int component = 2 - c;
        planes[c].resize(image.pixels.size());
        for (size_t i = 0; i < image.pixels.size(); ++i) planes[c][i] = image.pixels[i][component];
    }
    unsigned char* planePointers[3] = {reinterpret_cast<unsigned char*>(planes[0].data()),
                                       reinterpret_cast<unsigned char*>(planes[1].data()),
                                       reinterpret_cast<unsigned char*>(planes[2].data())};

    EXRImage exrImage;
    InitEXRImage(&exrImage);
    exrImage.images = planePointers;
    exrImage.width = image.width;
    exrImage.height = image.height;
    exrImage.num_channels = 3;

    EXRChannelInfo channels[3];
    int pixelTypes[3], requestedTypes[3];
    for (int c = 0; c < 3; ++c) {
        std::memset(&channels[c], 0, sizeof channels[c]);
        std::strcpy(channels[c].name, names[c]);
        pixelTypes[c] = TINYEXR_PIXELTYPE_FLOAT;      // type of the data we hand over
        requestedTypes[c] = TINYEXR_PIXELTYPE_FLOAT;  // type stored in the file: no HALF rounding
    }

    // tinyexr copies attribute bytes while serialising, so they can point into `attributes`.
    std::vector<EXRAttribute> custom(attributes.size());
    bool longNames = false;
    for (size_t i = 0; i < attributes.size(); ++i) {
        std::memset(&custom[i], 0, sizeof custom[i]);
        std::strcpy(custom[i].name, attributes[i].first.c_str());
        std::strcpy(custom[i].type, "string");
        custom[i].value = reinterpret_cast<unsigned char*>(const_cast<char*>(attributes[i].second.data()));
        custom[i].size = static_cast<int>(attributes[i].second.size());
        // Names over 31 bytes need the "long names" flag in the version field (OpenEXR file layout).
        longNames = longNames || attributes[i].first.size() > 31;
    }

    EXRHeader header;
    InitEXRHeader(&header);
    header.num_channels = 3;
    header.channels = channels;
    header.pixel_types = pixelTypes;
    header.requested_pixel_types = requestedTypes;
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;  // lossless
    header.num_custom_attributes = static_cast<int>(custom.size());
    header.custom_attributes = custom.empty() ? nullptr : custom.data();
    header.long_name = longNames ? 1 : 0;

    unsigned char* memory = nullptr;
    const char* err = nullptr;
    const size_t size = SaveEXRImageToMemory(&exrImage, &header, &memory, &err);
    if (size == 0 || !memory) {
        std::free(memory);
        throw Error("cannot encode EXR: " + takeMessage(err, 0));
    }
    std::vector<std::uint8_t> bytes(memory, memory + size);
    std::free(memory);  // tinyexr allocates the buffer with malloc
    return bytes;
}

Image decodeExr(const std::vector<std::uint8_t>& bytes, const std::string& name, ExrAttributes* attributes) {
    const std::string context = "cannot read EXR '" + name + "': ";
    EXRVersion version;
    int code = ParseEXRVersionFromMemory(&version, bytes.data(), bytes.size());
    if (code != TINYEXR_SUCCESS) throw Error(context + "not an OpenEXR file");
    if (version.multipart || version.non_image) {
        throw Error(context + "multi-part and deep files are not supported");
    }

    ParsedExr exr;
    const char* err = nullptr;
    code = ParseEXRHeaderFromMemory(&exr.header, &version, bytes.data(), bytes.size(), &err);
    if (code != TINYEXR_SUCCESS) throw Error(context + takeMessage(err, code));
    exr.headerLoaded = true;
    if (exr.header.tiled) throw Error(context + "tiled files are not supported");

    int r = -1, g = -1, b = -1;
    std::string channelList;
    for (int c = 0; c < exr.header.num_channels; ++c) {
        const std::string channel = exr.header.channels[c].name;
        channelList += (c ? ", " : "") + channel;
        if (channel == "R") r = c;
        if (channel == "G") g = c;
        if (channel == "B") b = c;
        if (exr.header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF) {
            exr.header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
        }
    }
    if (exr.header.num_channels == 1) {
        r = g = b = 0;  // greyscale (Y or any single channel)
    } else if (r < 0 || g < 0 || b < 0) {
        throw Error(context + "needs R, G and B channels or a single channel, found " + channelList);
    }

    err = nullptr;
    code = LoadEXRImageFromMemory(&exr.image, &exr.header, bytes.data(), bytes.size(), &err);
    if (code != TINYEXR_SUCCESS) throw Error(context + takeMessage(err, code));
    exr.imageLoaded = true;
    if (exr.image.width <= 0 || exr.image.height <= 0 || !exr.image.images) {
        throw Error(context + "no scanline image data");
    }

    Image image(exr.image.width, exr.image.height);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        image.pixels[i] = {channelValue(exr.image, exr.header, r, i),
                           channelValue(exr.image, exr.header, g, i),
                           channelValue(exr.image, exr.header, b, i)};
    }

    if (attributes) {
        attributes->clear();
        for (int i = 0; i < exr.header.num_custom_attributes; ++i) {
            const EXRAttribute& attribute = exr.header.custom_attributes[i];
            if (std::strcmp(attribute.type, "string") != 0) continue;
            std::string value;
            if (attribute.value && attribute.size > 0) {
                value.assign(reinterpret_cast<const char*>(attribute.value), size_t(attribute.size));
            }
            // tinyexr stores an empty string as one NUL byte; OpenEXR strings carry no NULs anyway.
            value.erase(std::find(value.begin(), value.end(), '\0'), value.end());
            attributes->emplace_back(attribute.name, value);
        }
    }
    return image;
}

void writeExr(const std::string& path, const Image& image, const ExrAttributes& attributes) {
    checkImageShape(image, "cannot write '" + path + "'");
    std::vector<std::uint8_t> bytes;
    try {
        bytes = encodeExr(image, attributes);
    } catch (const Error& e) {
        throw Error("cannot write '" + path + "': " + e.what());
    }
    writeFileAtomically(path, bytes);
}

Image readExr(const std::string& path, ExrAttributes* attributes) {
    const std::string bytes = readFileBytes(path);
    return decodeExr(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), path, attributes);
}

}  // namespace fp
