#pragma once
// Small text helpers for names, flags and file names.
#include <string>
#include <vector>

namespace fp {

// `text` with A-Z lower-cased and every other byte as it is, whatever the locale: "PNG" -> "png".
std::string toLowerAscii(std::string text);

// The extension of the file name (not of a directory in the path), lower-cased, with its dot:
// "out/Render.PFM" -> ".pfm"; "" if there is none.
std::string lowerCaseExtension(const std::string& path);

// printf into a std::string, of any length: formatText("%d spp", 16) -> "16 spp".
std::string formatText(const char* format, ...) __attribute__((format(printf, 1, 2)));

// A comma-separated list of names on the command line: "a,b,c" -> {"a", "b", "c"}. Throws fp::Error
// naming `flag` for an empty entry ("a,,b", "", "a,") or a repeated one.
std::vector<std::string> splitNameList(const std::string& text, const std::string& flag);

}  // namespace fp
