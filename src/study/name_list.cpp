#include "study/name_list.h"

#include <algorithm>

#include "core/error.h"

namespace fp::study {

size_t indexOfName(const std::vector<std::string>& known, const std::string& name, const std::string& what) {
    auto it = std::find(known.begin(), known.end(), name);
    if (it != known.end()) return size_t(it - known.begin());
    std::string choices;
    for (size_t i = 0; i < known.size(); ++i)
        choices += (i == 0 ? "" : i + 1 == known.size() ? " or " : ", ") + known[i];
    throw Error("unknown " + what + " '" + name + "' (choose " + choices + ")");
}

}  // namespace fp::study
