#pragma once
// Small text helpers for names, flags and file names.
#include <cstddef>
#include <string>
#include <vector>

#include "core/error.h"

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

// "a", "a or b", "a, b or c": the choices an error message offers.
std::string choiceList(const std::vector<std::string>& names);

// names[e] for an enumerator numbered 0, 1, ... in the order of `names`; "?" for any other value.
template <typename Enum, std::size_t N>
const char* nameOf(Enum e, const char* const (&names)[N]) {
    const auto i = static_cast<std::size_t>(e);
    return i < N ? names[i] : "?";
}

// The one of `all` that `nameOf` calls `name`: how every --flag NAME and scene-file name is read.
// Throws fp::Error "unknown <what> '<name>' (choose a, b or c)".
template <typename Enum, std::size_t N>
Enum parseName(const std::string& name, const Enum (&all)[N], const char* (*nameOf)(Enum), const char* what) {
    std::vector<std::string> names;
    for (Enum e : all) {
        if (name == nameOf(e)) return e;
        names.push_back(nameOf(e));
    }
    throw Error("unknown " + std::string(what) + " '" + name + "' (choose " + choiceList(names) + ")");
}

}  // namespace fp
