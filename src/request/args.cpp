#include "request/args.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/error.h"

namespace fp {

Args::Args(const std::vector<std::string>& argv, const std::vector<OptionGroup>& options) {
    std::map<std::string, const Option*> known;  // by flag and by alias
    for (const OptionGroup& group : options)
        for (const Option& option : group.options) {
            known[option.flag] = &option;
            if (!option.alias.empty()) known[option.alias] = &option;
        }
    auto find = [&](const std::string& name) {
        auto it = known.find(name);
        if (it == known.end()) throw UsageError("unknown option " + name + " (see --help)");
        return it->second;
    };
    for (size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        size_t equals = a.find('=');
        if (a.rfind("--", 0) == 0 && equals != std::string::npos) {  // the GNU form, --option=value
            const Option* option = find(a.substr(0, equals));
            if (option->value.empty()) throw UsageError("option " + option->flag + " takes no value");
            if (equals + 1 == a.size()) throw UsageError("option " + option->flag + " needs a value");
            values_[option->flag] = a.substr(equals + 1);
        } else if (a.size() > 1 && a[0] == '-' && !std::isdigit(static_cast<unsigned char>(a[1]))) {
            const Option* option = find(a);
            if (option->value.empty()) {
                values_[option->flag] = "";
                continue;
            }
            // A value may be negative ("--eye -1,0,0") but is never another option.
            bool nextIsOption = i + 1 < argv.size() && argv[i + 1].size() > 1 && argv[i + 1][0] == '-' &&
                                !std::isdigit(static_cast<unsigned char>(argv[i + 1][1])) &&
                                argv[i + 1][1] != '.';
            if (i + 1 >= argv.size() || nextIsOption) throw UsageError("option " + a + " needs a value");
            values_[option->flag] = argv[++i];
        } else {
            positional_.push_back(a);
        }
    }
}

std::optional<std::string> Args::text(const std::string& flag) const {
    auto it = values_.find(flag);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

static float parseFloat(const std::string& flag, const std::string& s) {
    char* end = nullptr;
    float v = std::strtof(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v))
        throw Error("option " + flag + ": '" + s + "' is not a finite number");
    return v;
}

std::optional<int> Args::integer(const std::string& flag, int min, int max) const {
    auto s = text(flag);
    if (!s) return std::nullopt;
    char* end = nullptr;
    long v = std::strtol(s->c_str(), &end, 10);
    if (s->empty() || end != s->c_str() + s->size() || v < min || v > max)
        throw Error("option " + flag + ": '" + *s + "' is not a whole number from " + std::to_string(min) +
                    " to " + std::to_string(max));
    return int(v);
}

std::optional<float> Args::number(const std::string& flag) const {
    auto s = text(flag);
    if (!s) return std::nullopt;
    return parseFloat(flag, *s);
}

std::optional<glm::vec3> Args::vec3(const std::string& flag) const {
    auto s = text(flag);
    if (!s) return std::nullopt;
    std::vector<std::string> parts;
    std::stringstream in(*s);
    for (std::string part; std::getline(in, part, ',');) parts.push_back(part);
    if (parts.size() != 3) throw Error("option " + flag + ": expected X,Y,Z, got '" + *s + "'");
    return glm::vec3(parseFloat(flag, parts[0]), parseFloat(flag, parts[1]), parseFloat(flag, parts[2]));
}

std::optional<glm::ivec2> Args::size(const std::string& flag) const {
    auto s = text(flag);
    if (!s) return std::nullopt;
    size_t x = s->find('x');
    char* end = nullptr;
    long w = x == std::string::npos ? 0 : std::strtol(s->c_str(), &end, 10);
    bool ok = x != std::string::npos && end == s->c_str() + x;
    long h = ok ? std::strtol(s->c_str() + x + 1, &end, 10) : 0;
    ok = ok && end == s->c_str() + s->size() && w >= 1 && h >= 1 && w <= 65536 && h <= 65536;
    if (!ok) throw Error("option " + flag + ": expected WIDTHxHEIGHT such as 512x512, got '" + *s + "'");
    return glm::ivec2(int(w), int(h));
}

}  // namespace fp
