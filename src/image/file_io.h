#pragma once
// Byte-level file helpers shared by the image writers and readers.
#include <cstdint>
#include <string>
#include <vector>

// lowerCaseExtension lives in core/text.h; included here only for the callers that still find it through
// this header (src/app/view_command.cpp), until they include core/text.h themselves.
#include "core/text.h"

namespace fp {

// Writes `bytes` to a temporary file next to `path` and renames it over `path`, so readers never see
// a half-written image and a failed write leaves any previous file untouched. On failure the temporary
// file is removed and fp::Error names `path` and the reason.
void writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes);

}  // namespace fp
