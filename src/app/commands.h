#pragma once
// The subcommands of build/fragpath, one file each; `args` excludes the program and command names.
#include <string>
#include <vector>

namespace fp {

int renderCommand(const std::vector<std::string>& args);
int benchCommand(const std::vector<std::string>& args);
int viewCommand(const std::vector<std::string>& args);
int mergeCommand(const std::vector<std::string>& args);
int studyCommand(const std::vector<std::string>& args);
int compareCommand(const std::vector<std::string>& args);
int realtimeCommand(const std::vector<std::string>& args);

}  // namespace fp
