#pragma once
// Names chosen on the command line: the study's lists of integrators and denoisers ("nee,naive").
#include <string>
#include <vector>

#include "core/text.h"

namespace fp::study {

// The splitting lives in core/text.h; named here too for the callers that still write
// study::splitNameList (src/app/study_command.cpp), until they call fp::splitNameList.
using fp::splitNameList;
// The position of `name` in `known`; throws fp::Error "unknown <what> 'name' (choose a, b or c)".
size_t indexOfName(const std::vector<std::string>& known, const std::string& name, const std::string& what);

}  // namespace fp::study
