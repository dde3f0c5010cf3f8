#pragma once
// Reading whole input files, with one message for every way that can fail.
#include <string>

namespace fp {

// The bytes of a regular file (possibly none). Throws fp::Error naming `path` if the path is empty or
// the file is missing, a directory, not a regular file, or unreadable.
std::string readFileBytes(const std::string& path);

}  // namespace fp
