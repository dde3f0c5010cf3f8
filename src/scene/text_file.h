#pragma once
// Reading scene inputs as text, and refusing what is not text before any parser sees it: tinyobjloader
// would "load" a directory, a PNG or UTF-16 text as an empty or garbled scene without complaint.
#include <string>
#include <string_view>

#include "core/file.h"

namespace fp {

// Why `bytes` cannot be parsed as 8-bit text (a PNG image, UTF-16/32, NUL or other binary bytes), or an
// empty string if it can. Empty input is text; callers decide whether it is acceptable.
std::string nonTextReason(std::string_view bytes);

// `bytes` without a leading UTF-8 byte-order mark; parsers would otherwise read it as part of the
// first statement (tinyobjloader loses the first vertex).
std::string_view stripUtf8Bom(std::string_view bytes);

// For the top-level input files (OBJ, scene JSON): throws fp::Error naming `name` if `bytes` is empty
// or not text; returns the text without a UTF-8 BOM.
std::string_view requireText(std::string_view bytes, const std::string& name);

}  // namespace fp
