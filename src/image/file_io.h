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

// The extension of the file name (not of a directory in the path), lower-cased, with its dot:
// "out/Render.PFM" -> ".pfm"; "" if there is none.
std::string lowerCaseExtension(const std::string& path);

}  // namespace fp
