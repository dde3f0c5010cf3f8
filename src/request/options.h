#pragma once
// The options a command takes, grouped as its --help lists them. One table gives the reader
// (request/args.h) its flags and the help its text, so that the two cannot disagree.
#include <string>
#include <vector>

namespace fp {

struct Option {
    std::string flag;   // "--output"
    std::string alias;  // another spelling of the same option ("-o"), or empty
    std::string value;  // the value's name in the help ("FILE"); empty for a switch, which takes none
    std::string help;   // '\n' starts another line
};

struct OptionGroup {
    std::string title;
    std::vector<Option> options;
};

// The groups under their titles, one option a line ("  -o, --output FILE   help"), in order.
std::string formatOptions(const std::vector<OptionGroup>& groups);

// The group every command ends with: -h, --help.
OptionGroup helpOptions();

}  // namespace fp
