#include "core/text.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <filesystem>

#include "core/error.h"

namespace fp {

std::string toLowerAscii(std::string text) {
    for (char& c : text)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return text;
}

std::string lowerCaseExtension(const std::string& path) {
    return toLowerAscii(std::filesystem::path(path).extension().string());
}

std::string formatText(const char* format, ...) {
    va_list args, again;
    va_start(args, format);
    va_copy(again, args);
    const int size = std::vsnprintf(nullptr, 0, format, args);
    va_end(args);
    std::string text(size_t(std::max(size, 0)) + 1, '\0');  // room for vsnprintf's NUL
    std::vsnprintf(text.data(), text.size(), format, again);
    va_end(again);
    text.resize(size_t(std::max(size, 0)));
    return text;
}

std::vector<std::string> splitNameList(const std::string& text, const std::string& flag) {
    std::vector<std::string> names;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = std::min(text.find(',', start), text.size());
        std::string name = text.substr(start, end - start);
        if (name.empty()) throw Error(flag + ": empty name in '" + text + "'");
        if (std::find(names.begin(), names.end(), name) != names.end())
            throw Error(flag + ": '" + name + "' is listed twice");
        names.push_back(name);
        start = end + 1;
    }
    return names;
}

std::string choiceList(const std::vector<std::string>& names) {
    std::string text;
    for (size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return text;
}

}  // namespace fp
