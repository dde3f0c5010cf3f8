#include "image/exr.h"

#include <tinyexr.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>
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

void checkLayers(const Image& image, const std::vector<ExrLayer>& layers) {
    std::set<std::string> seen = {"R", "G", "B"};
    for (const ExrLayer& layer : layers) {
        const std::string what = "EXR layer '" + layer.name + "'";
        if (layer.name.empty() || layer.name.find('.') != std::string::npos)
            throw Error("invalid " + what + " (a name without '.')");
        if (layer.channels.empty() || layer.channels.size() > 3)
            throw Error(what + " needs 1 to 3 channels, has " + std::to_string(layer.channels.size()));
        if (layer.image.width != image.width || layer.image.height != image.height ||
            layer.image.pixels.size() != image.pixels.size())
            throw Error(what + " is " + std::to_string(layer.image.width) + "x" +
                        std::to_string(layer.image.height) + ", not the image's " +
                        std::to_string(image.width) + "x" + std::to_string(image.height));
        for (const std::string& channel : layer.channels) {
            const std::string name = layer.name + "." + channel;
            if (channel.empty() || channel.find('.') != std::string::npos ||
                name.find('\0') != std::string::npos || name.size() > 255)
                throw Error("invalid EXR channel name '" + name + "' (1 to 255 bytes, no NUL)");
            if (!seen.insert(name).second) throw Error("duplicate EXR channel '" + name + "'");
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

// Where `channel` stands in the conventional order of the family it belongs to (R, G, B or X, Y, Z),
// or -1.
int conventionalRank(const std::string& family, const std::string& channel) {
    size_t at = channel.size() == 1 ? family.find(channel[0]) : std::string::npos;
    return at == std::string::npos ? -1 : int(at);
}

// The "<layer>.<channel>" channels of a loaded file, grouped by layer (the text before the last '.').
void readLayers(const ParsedExr& exr, std::vector<ExrLayer>& layers) {
    std::map<std::string, std::vector<std::pair<std::string, int>>> groups;  // layer -> (channel, index)
    for (int c = 0; c < exr.header.num_channels; ++c) {
        const std::string full = exr.header.channels[c].name;
        const size_t dot = full.rfind('.');
        if (dot == std::string::npos || dot == 0 || dot + 1 == full.size()) continue;
        groups[full.substr(0, dot)].emplace_back(full.substr(dot + 1), c);
    }
    layers.clear();
    for (auto& [layerName, channels] : groups) {
        if (channels.size() > 3) continue;
        for (const char* family : {"RGB", "XYZ"}) {
            bool all = std::all_of(channels.begin(), channels.end(),
                                   [&](const auto& c) { return conventionalRank(family, c.first) >= 0; });
            if (all)
                std::stable_sort(channels.begin(), channels.end(), [&](const auto& a, const auto& b) {
                    return conventionalRank(family, a.first) < conventionalRank(family, b.first);
                });
        }
        ExrLayer layer{layerName, {}, Image(exr.image.width, exr.image.height)};
        for (size_t k = 0; k < channels.size(); ++k) {
            layer.channels.push_back(channels[k].first);
            for (size_t i = 0; i < layer.image.pixels.size(); ++i)
                layer.image.pixels[i][int(k)] = channelValue(exr.image, exr.header, channels[k].second, i);
        }
        layers.push_back(std::move(layer));
    }
}

}  // namespace

std::vector<std::uint8_t> encodeExr(const Image& image, const ExrAttributes& attributes,
                                    const std::vector<ExrLayer>& layers) {
    checkImageShape(image, "cannot encode EXR");
    checkAttributes(attributes);
    checkLayers(image, layers);

    // Every channel as (full name, image, component); OpenEXR readers expect them sorted by name
    // (byte order, as strcmp), hence B, G, R, then the layers' channels.
    struct Channel {
        std::string name;
        const Image* image;
        int component;
    };
    std::vector<Channel> list = {{"R", &image, 0}, {"G", &image, 1}, {"B", &image, 2}};
    for (const ExrLayer& layer : layers)
        for (size_t c = 0; c < layer.channels.size(); ++c)
            list.push_back({layer.name + "." + layer.channels[c], &layer.image, int(c)});
    std::sort(list.begin(), list.end(), [](const Channel& a, const Channel& b) { return a.name < b.name; });

    const size_t count = list.size();
    std::vector<std::vector<float>> planes(count);
    std::vector<unsigned char*> planePointers(count);
    std::vector<EXRChannelInfo> channels(count);
    std::vector<int> pixelTypes(count, TINYEXR_PIXELTYPE_FLOAT);      // type of the data we hand over
    std::vector<int> requestedTypes(count, TINYEXR_PIXELTYPE_FLOAT);  // stored in the file: no HALF rounding
    bool longNames = false;
    for (size_t c = 0; c < count; ++c) {
        const Channel& channel = list[c];
        planes[c].resize(image.pixels.size());
        for (size_t i = 0; i < image.pixels.size(); ++i)
            planes[c][i] = channel.image->pixels[i][channel.component];
        planePointers[c] = reinterpret_cast<unsigned char*>(planes[c].data());
        std::memset(&channels[c], 0, sizeof channels[c]);
        std::strcpy(channels[c].name, channel.name.c_str());  // checkLayers keeps names under 256 bytes
        // Names over 31 bytes need the "long names" flag in the version field (OpenEXR file layout).
        longNames = longNames || channel.name.size() > 31;
    }

    EXRImage exrImage;
    InitEXRImage(&exrImage);
    exrImage.images = planePointers.data();
    exrImage.width = image.width;
    exrImage.height = image.height;
    exrImage.num_channels = int(count);

    // tinyexr copies attribute bytes while serialising, so they can point into `attributes`.
    std::vector<EXRAttribute> custom(attributes.size());
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
    header.num_channels = int(count);
    header.channels = channels.data();
    header.pixel_types = pixelTypes.data();
    header.requested_pixel_types = requestedTypes.data();
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

namespace {

// decodeExr, or with `radiance` decodeExrRadiance: the same reading, stricter about what it accepts.
Image decode(const std::vector<std::uint8_t>& bytes, const std::string& name, ExrAttributes* attributes,
             std::vector<ExrLayer>* layers, bool radiance) {
    const std::string context = "cannot read EXR '" + name + "': ";
    EXRVersion version;
    int code = ParseEXRVersionFromMemory(&version, bytes.data(), bytes.size());
    if (code != TINYEXR_SUCCESS) throw Error(context + "not an OpenEXR file");
    if (version.multipart) throw Error(context + "multi-part files are not supported (one part is)");
    if (version.non_image) throw Error(context + "deep files are not supported (a flat image is)");

    ParsedExr exr;
    const char* err = nullptr;
    code = ParseEXRHeaderFromMemory(&exr.header, &version, bytes.data(), bytes.size(), &err);
    if (code != TINYEXR_SUCCESS) throw Error(context + takeMessage(err, code));
    exr.headerLoaded = true;
    if (exr.header.tiled) throw Error(context + "tiled files are not supported (a scanline image is)");

    int r = -1, g = -1, b = -1, y = -1;
    std::string channelList;
    for (int c = 0; c < exr.header.num_channels; ++c) {
        const std::string channel = exr.header.channels[c].name;
        channelList += (c ? ", " : "") + channel;
        if (channel == "R") r = c;
        if (channel == "G") g = c;
        if (channel == "B") b = c;
        if (channel == "Y") y = c;
        if (exr.header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF) {
            exr.header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
        }
    }
    const bool rgb = r >= 0 && g >= 0 && b >= 0;
    if (radiance && !rgb && !(exr.header.num_channels == 1 && y == 0)) {
        throw Error(context + "a radiance image needs R, G and B channels (or a single Y), found " +
                    channelList);
    }
    if (!rgb && exr.header.num_channels == 1) {
        r = g = b = 0;  // greyscale (Y or any single channel)
    } else if (!rgb) {
        throw Error(context + "needs R, G and B channels or a single channel, found " + channelList);
    }
    if (radiance)
        for (int c : {r, g, b})
            if (exr.header.pixel_types[c] == TINYEXR_PIXELTYPE_UINT)
                throw Error(context + "channel " + exr.header.channels[c].name +
                            " holds 32-bit integers (UINT), not radiance (HALF or FLOAT)");

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

    if (layers) readLayers(exr, *layers);
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

}  // namespace

Image decodeExr(const std::vector<std::uint8_t>& bytes, const std::string& name, ExrAttributes* attributes,
                std::vector<ExrLayer>* layers) {
    return decode(bytes, name, attributes, layers, false);
}

Image decodeExrRadiance(const std::vector<std::uint8_t>& bytes, const std::string& name) {
    return decode(bytes, name, nullptr, nullptr, true);
}

void writeExr(const std::string& path, const Image& image, const ExrAttributes& attributes,
              const std::vector<ExrLayer>& layers) {
    checkImageShape(image, "cannot write '" + path + "'");
    std::vector<std::uint8_t> bytes;
    try {
        bytes = encodeExr(image, attributes, layers);
    } catch (const Error& e) {
        throw Error("cannot write '" + path + "': " + e.what());
    }
    writeFileAtomically(path, bytes);
}

Image readExr(const std::string& path, ExrAttributes* attributes, std::vector<ExrLayer>* layers) {
    const std::string bytes = readFileBytes(path);
    return decodeExr(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), path, attributes, layers);
}

Image readExrRadiance(const std::string& path) {
    const std::string bytes = readFileBytes(path);
    return decodeExrRadiance(std::vector<std::uint8_t>(bytes.begin(), bytes.end()), path);
}

}  // namespace fp
