#include "request/options.h"

#include <algorithm>
#include <sstream>

namespace fp {

namespace {

std::string spelling(const Option& option) {
    std::string text = option.alias.empty() ? option.flag : option.alias + ", " + option.flag;
    return option.value.empty() ? text : text + " " + option.value;
}

}  // namespace

std::string formatOptions(const std::vector<OptionGroup>& groups) {
    // The help column starts after the longest spelling that fits in kMaxColumn; longer ones get a
    // line of their own, so that a long flag does not push every help text to the right.
    constexpr size_t kMaxColumn = 24, kWidth = 104;
    size_t column = 0;
    for (const OptionGroup& group : groups)
        for (const Option& option : group.options)
            if (spelling(option).size() + 2 <= kMaxColumn)
                column = std::max(column, spelling(option).size() + 4);
    std::ostringstream out;
    for (const OptionGroup& group : groups) {
        if (group.options.empty()) continue;
        out << "\n" << group.title << ":\n";
        for (const Option& option : group.options) {
            std::string left = "  " + spelling(option);
            std::istringstream help(option.help);
            std::string line;
            bool first = true;
            if (left.size() + 2 > column) {
                out << left << "\n";
                first = false;
            }
            while (std::getline(help, line)) {
                // Words that would pass kWidth go on to a line of their own.
                while (!line.empty()) {
                    size_t cut = line.size();
                    if (column + cut > kWidth) {
                        cut = line.rfind(' ', kWidth - column);
                        if (cut == std::string::npos || cut == 0) cut = line.size();
                    }
                    std::string margin =
                        first ? left + std::string(column - left.size(), ' ') : std::string(column, ' ');
                    out << margin << line.substr(0, cut) << "\n";
                    line = cut < line.size() ? line.substr(cut + 1) : "";
                    first = false;
                }
            }
        }
    }
    return out.str();
}

OptionGroup helpOptions() {
    return {"General", {{"--help", "-h", "", "this text"}}};
}

}  // namespace fp
