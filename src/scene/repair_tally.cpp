#include "scene/repair_tally.h"

#include "core/log.h"

namespace fp {

std::string RepairTally::describe(const std::string& verb, const std::string& noun,
                                  const std::string& rest) const {
    std::string text = verb + " " + std::to_string(count_) + " " + noun + (count_ == 1 ? "" : "s");
    if (!rest.empty()) text += " " + rest;
    return text;
}

void RepairTally::report(const std::string& file, const std::string& verb, const std::string& noun,
                         const std::string& rest) const {
    if (count_ == 0) return;
    warn(file + ": " + describe(verb, noun, rest) + " (first at line " + std::to_string(firstLine_) + ")");
}

}  // namespace fp
