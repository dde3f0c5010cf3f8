#include "study/name_list.h"

#include <algorithm>

#include "core/error.h"

namespace fp::study {

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

size_t indexOfName(const std::vector<std::string>& known, const std::string& name, const std::string& what) {
    auto it = std::find(known.begin(), known.end(), name);
    if (it != known.end()) return size_t(it - known.begin());
    std::string choices;
    for (size_t i = 0; i < known.size(); ++i)
        choices += (i == 0 ? "" : i + 1 == known.size() ? " or " : ", ") + known[i];
    throw Error("unknown " + what + " '" + name + "' (choose " + choices + ")");
}

}  // namespace fp::study
