#include "scene/text_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.h"

namespace fp {

namespace fs = std::filesystem;

static bool startsWith(std::string_view s, std::string_view prefix) {
    return s.size() >= prefix.size() && s.substr(0, prefix.size()) == prefix;
}

std::string nonTextReason(std::string_view bytes) {
    using namespace std::string_view_literals;
    if (startsWith(bytes, "\x89PNG"sv)) return "is a PNG image, not a text file";
    // UTF-32 first: its little-endian BOM begins with the UTF-16 one.
    if (startsWith(bytes, "\xFF\xFE\0\0"sv) || startsWith(bytes, "\0\0\xFE\xFF"sv))
        return "is UTF-32 text; save it as UTF-8 or ASCII";
    if (startsWith(bytes, "\xFE\xFF"sv) || startsWith(bytes, "\xFF\xFE"sv))
        return "is UTF-16 text; save it as UTF-8 or ASCII";
    // Text has no control bytes other than whitespace (and the DOS end-of-file mark ^Z). A NUL is the
    // surest sign of binary data, and C-string parsers would silently stop reading at it.
    auto binary = std::find_if(bytes.begin(), bytes.end(), [](char c) {
        unsigned char u = static_cast<unsigned char>(c);
        return u < 0x20 && u != '\t' && u != '\n' && u != '\r' && u != '\v' && u != '\f' && u != 0x1A;
    });
    if (binary == bytes.end()) return "";
    long line = 1 + std::count(bytes.begin(), binary, '\n');
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(*binary)));
    return std::string("contains binary data (") +
           (*binary == '\0' ? "NUL byte" : std::string("byte ") + hex) + " at line " + std::to_string(line) +
           "), not text";
}

std::string_view stripUtf8Bom(std::string_view bytes) {
    return startsWith(bytes, "\xEF\xBB\xBF") ? bytes.substr(3) : bytes;
}

std::string_view requireText(std::string_view bytes, const std::string& name) {
    if (bytes.empty()) throw Error(name + ": file is empty");
    std::string reason = nonTextReason(bytes);
    if (!reason.empty()) throw Error(name + ": " + reason);
    std::string_view text = stripUtf8Bom(bytes);
    if (text.find_first_not_of(" \t\r\n\v\f") == std::string_view::npos)
        throw Error(name + ": file is empty (only whitespace)");
    return text;
}

}  // namespace fp
