#pragma once
// Comma-separated lists of names on the command line ("nee,naive").
#include <string>
#include <vector>

namespace fp::study {

// "a,b,c" -> {"a", "b", "c"}; throws fp::Error naming `flag` for an empty entry or a repeated one.
std::vector<std::string> splitNameList(const std::string& text, const std::string& flag);
// The position of `name` in `known`; throws fp::Error "unknown <what> 'name' (choose a, b or c)".
size_t indexOfName(const std::vector<std::string>& known, const std::string& name, const std::string& what);

}  // namespace fp::study
