#pragma once
// A small command-line reader: flags with values, positional arguments, and typed conversions that
// fail with a message naming the flag.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace fp {

class Args {
  public:
    // `valued` flags take the next argument as their value, or the text after '=' (--spp=16);
    // `switches` take none. Throws fp::Error on an unknown flag or a missing value.
    Args(const std::vector<std::string>& argv, const std::set<std::string>& valued,
         const std::set<std::string>& switches);

    bool has(const std::string& flag) const { return values_.count(flag) > 0; }
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
