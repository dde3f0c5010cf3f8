#pragma once
// OpenEXR through tinyexr: 32-bit FLOAT R, G, B channels (lossless ZIP), so linear values round-trip
// bit-exactly, plus string attributes in the header for metadata such as sample ranges, and optional
// extra layers in the same single-part file, named by OpenEXR's "layer.channel" convention (e.g.
// albedo.R, normal.X, depth.Z) next to the unprefixed R, G, B that every reader shows.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"

namespace fp {

// (name, value) pairs stored as OpenEXR "string" attributes, in order.
using ExrAttributes = std::vector<std::pair<std::string, std::string>>;

// A layer of extra channels stored next to R, G, B: channel i (1 to 3 of them) is stored as
// "<name>.<channels[i]>" and holds component i of `image`, which has the main image's size.
struct ExrLayer {
    std::string name;                   // non-empty, no '.'
    std::vector<std::string> channels;  // 1 to 3 non-empty names, no '.'
    Image image;
};

// Throws fp::Error for an attribute name that is empty, longer than 255 bytes, duplicated or one of
// the standard header attributes (channels, compression, dataWindow, ...), for a value containing a
// NUL byte, or for more than 128 attributes (what tinyexr reads back); for a layer whose name or
// channels are malformed or repeated, or whose image is not the main image's size. All channels are
// written in the order of their full names, as OpenEXR requires (B, G, R, albedo.B, ...).
std::vector<std::uint8_t> encodeExr(const Image& image, const ExrAttributes& attributes = {},
                                    const std::vector<ExrLayer>& layers = {});
// Scanline single-part files with R, G, B channels (HALF, FLOAT or UINT) or a single channel, which is
// replicated to grey. If `attributes` is given it receives the file's string attributes in file order;
// other attribute types are skipped. If `layers` is given it receives every layer of 1 to 3 channels
// named "<layer>.<channel>" (others are skipped), in the order of their names, each with its channels
// in the order R, G, B or X, Y, Z when it has those, else in file order. `name` is used in error
// messages.
Image decodeExr(const std::vector<std::uint8_t>& bytes, const std::string& name,
                ExrAttributes* attributes = nullptr, std::vector<ExrLayer>* layers = nullptr);

// An image of linear radiance, such as an environment map: a scanline single-part file (multi-part,
// deep and tiled files are refused) with R, G and B channels of HALF or FLOAT samples (others, such as
// A or layers, are ignored) or a single luminance channel Y, replicated to grey. Throws fp::Error naming
// `name` for any other layout (UINT channels, a lone channel that is not Y, no R, G, B), saying why.
Image decodeExrRadiance(const std::vector<std::uint8_t>& bytes, const std::string& name);
Image readExrRadiance(const std::string& path);

void writeExr(const std::string& path, const Image& image, const ExrAttributes& attributes = {},
              const std::vector<ExrLayer>& layers = {});
Image readExr(const std::string& path, ExrAttributes* attributes = nullptr,
              std::vector<ExrLayer>* layers = nullptr);

}  // namespace fp
