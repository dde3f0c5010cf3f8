#pragma once
// OpenEXR through tinyexr: 32-bit FLOAT R, G, B channels (lossless ZIP), so linear values round-trip
// bit-exactly, plus string attributes in the header for metadata such as sample ranges.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"

namespace fp {

// (name, value) pairs stored as OpenEXR "string" attributes, in order.
using ExrAttributes = std::vector<std::pair<std::string, std::string>>;

// Throws fp::Error for an attribute name that is empty, longer than 255 bytes, duplicated or one of
// the standard header attributes (channels, compression, dataWindow, ...), for a value containing a
// NUL byte, or for more than 128 attributes (what tinyexr reads back).
std::vector<std::uint8_t> encodeExr(const Image& image, const ExrAttributes& attributes = {});
// Scanline single-part files with R, G, B channels (HALF, FLOAT or UINT) or a single channel, which is
// replicated to grey. If `attributes` is given it receives the file's string attributes in file order;
// other attribute types are skipped. `name` is used in error messages.
Image decodeExr(const std::vector<std::uint8_t>& bytes, const std::string& name,
                ExrAttributes* attributes = nullptr);

void writeExr(const std::string& path, const Image& image, const ExrAttributes& attributes = {});
Image readExr(const std::string& path, ExrAttributes* attributes = nullptr);

}  // namespace fp
