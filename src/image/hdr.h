#pragma once
// Radiance HDR (.hdr, RGBE) images, read through stb_image: environment maps come in this format.
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace fp {

// Throws fp::Error naming `name` when the bytes are not a Radiance HDR image.
Image decodeHdr(const std::vector<std::uint8_t>& bytes, const std::string& name);
Image readHdr(const std::string& path);

}  // namespace fp
