#include "study/name_list.h"

#include <algorithm>

#include "core/error.h"
#include "core/text.h"

namespace fp::study {

size_t indexOfName(const std::vector<std::string>& known, const std::string& name, const std::string& what) {
    auto it = std::find(known.begin(), known.end(), name);
    if (it != known.end()) return size_t(it - known.begin());
    throw Error("unknown " + what + " '" + name + "' (choose " + choiceList(known) + ")");
}

}  // namespace fp::study
