#pragma once
// Byte-level file helpers shared by the image writers and readers.
#include <cstdint>
#include <string>
#include <vector>

namespace fp {

// Writes `bytes` to a temporary file next to `path` and renames it over `path`, so readers never see
// a half-written image and a failed write leaves any previous file untouched. On failure the temporary
// file is removed and fp::Error names `path` and the reason.
void writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes);

// Fails before a long render, not after it, when an image cannot be written at `path`: its extension
// must name a format writeImage knows (.png, .exr, .pfm; only .png with `pngOnly`) and its directory
// must be writable (core/file.h checkWritablePath). `label` says where the path came from ("output",
// "--screenshot").
void checkImageOutput(const std::string& path, const std::string& label, bool pngOnly = false);

}  // namespace fp
