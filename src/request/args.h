#pragma once
// A small command-line reader: the options of a table (request/options.h) in either GNU form
// (--spp 16, --spp=16), positional arguments, and typed conversions that fail with a message naming the
// option. (Debian's CLI11 2.1 was considered: it would do the same at 5.6 s more compile time per file
// that includes it, and the typed conversions below, "WxH" and "X,Y,Z", would still be ours.)
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "request/options.h"

namespace fp {

class Args {
  public:
    // Options with a value name take the next argument as their value, or the text after '='; switches
    // take none. An alias is stored under its option's flag. Throws fp::Error on an unknown option or a
    // missing value.
    Args(const std::vector<std::string>& argv, const std::vector<OptionGroup>& options);

    bool has(const std::string& flag) const { return values_.count(flag) > 0; }
    bool wantsHelp() const { return has("--help"); }
    std::optional<std::string> text(const std::string& flag) const;
    std::optional<int> integer(const std::string& flag, int min, int max) const;
    std::optional<float> number(const std::string& flag) const;
    std::optional<glm::vec3> vec3(const std::string& flag) const;   // "X,Y,Z"
    std::optional<glm::ivec2> size(const std::string& flag) const;  // "WxH"
    const std::vector<std::string>& positional() const { return positional_; }

  private:
    std::map<std::string, std::string> values_;
    std::vector<std::string> positional_;
};

}  // namespace fp
