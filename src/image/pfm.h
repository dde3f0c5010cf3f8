#pragma once
// Portable Float Map (PFM), the format of Debevec's HDRShop and of many reference renderers: a text
// header "PF" (RGB) or "Pf" (grey), "<width> <height>", and a scale whose sign gives the byte order
// (negative = little-endian), then 32-bit floats with the BOTTOM row first.
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace fp {

// Colour ("PF"), little-endian (scale -1.0), rows bottom to top. Bit-exact for every float value.
std::vector<std::uint8_t> encodePfm(const Image& image);
// Accepts "PF" and "Pf" (grey is replicated to RGB) in either byte order. The scale's magnitude is
// not applied: readers commonly ignore it and applying it would break bit-exact round trips.
// `name` is used in error messages; throws fp::Error on a malformed header or a size mismatch.
Image decodePfm(const std::vector<std::uint8_t>& bytes, const std::string& name);

void writePfm(const std::string& path, const Image& image);
Image readPfm(const std::string& path);

}  // namespace fp
