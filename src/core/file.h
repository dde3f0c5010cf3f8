#pragma once
// Reading whole input files, with one message for every way that can fail; checking an output's place.
#include <string>

namespace fp {

// The bytes of a regular file (possibly none). Throws fp::Error naming `path` if the path is empty or
// the file is missing, a directory, not a regular file, or unreadable.
std::string readFileBytes(const std::string& path);

// Fails before a long run, not after it, when no file can be written at `path`: throws fp::Error
// "<label> <path>: directory <dir> does not exist", "<label> <path>: directory <dir> is not writable" or
// "<label> <path> is a directory". `label` says where the path came from ("output", "--json").
void checkWritablePath(const std::string& path, const std::string& label);

}  // namespace fp
