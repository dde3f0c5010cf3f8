#include "scene/text_syntax.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <limits>

namespace fp {

bool LineReader::next(std::string_view* line) {
    if (rest_.empty()) return false;
    size_t end = rest_.find_first_of("\r\n");
    ++number_;
    if (end == std::string_view::npos) {
        *line = rest_;
        rest_ = {};
        return true;
    }
    *line = rest_.substr(0, end);
    size_t terminator = (rest_[end] == '\r' && end + 1 < rest_.size() && rest_[end + 1] == '\n') ? 2 : 1;
    rest_.remove_prefix(end + terminator);
    return true;
}

static bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

void splitWords(std::string_view line, std::vector<std::string_view>* words) {
    words->clear();
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isBlank(line[i])) ++i;
        size_t start = i;
        while (i < line.size() && !isBlank(line[i])) ++i;
        if (i > start) words->push_back(line.substr(start, i - start));
    }
}

std::string_view trimBlanks(std::string_view line) {
    while (!line.empty() && isBlank(line.front())) line.remove_prefix(1);
    while (!line.empty() && isBlank(line.back())) line.remove_suffix(1);
    return line;
}

static bool equalsLower(std::string_view word, std::string_view lower) {
    return word.size() == lower.size() &&
           std::equal(word.begin(), word.end(), lower.begin(),
                      [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

static size_t skipDigits(std::string_view s, size_t i) {
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i;
}

// Roughly log10 of a well-formed decimal: tells whether a value out of double's range overflowed
// (becomes infinite) or underflowed (becomes zero).
static long long decimalMagnitude(std::string_view body) {
    size_t point = std::min(body.find_first_of(".eE"), body.size());
    size_t e = std::min(body.find_first_of("eE"), body.size());
    size_t first = body.find_first_of("123456789");
    if (first == std::string_view::npos || first > e) return std::numeric_limits<long long>::min();
    long long lead =
        first < point ? static_cast<long long>(point - first) - 1 : -static_cast<long long>(first - point);
    long long exponent = 0;
    if (e < body.size()) {
        std::string_view digits = body.substr(e + 1);
        bool negative = !digits.empty() && digits[0] == '-';
        if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) digits.remove_prefix(1);
        for (char c : digits) exponent = std::min(exponent * 10 + (c - '0'), 1000000000LL);
        if (negative) exponent = -exponent;
    }
    return lead + exponent;
}

std::optional<double> parseReal(std::string_view word) {
    std::string_view body = word;
    bool negative = false;
    if (!body.empty() && (body[0] == '+' || body[0] == '-')) {
        negative = body[0] == '-';
        body.remove_prefix(1);
    }
    if (equalsLower(body, "nan")) return std::numeric_limits<double>::quiet_NaN();
    if (equalsLower(body, "inf") || equalsLower(body, "infinity"))
        return negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();

    // Check the shape ourselves: from_chars alone would also take hex digits after "0x" and stop early
    // on trailing junk, and we want exactly the spelling tinyobjloader reads correctly.
    size_t intEnd = skipDigits(body, 0);
    size_t i = intEnd;
    size_t fracDigits = 0;
    if (i < body.size() && body[i] == '.') {
        size_t fracEnd = skipDigits(body, i + 1);
        fracDigits = fracEnd - (i + 1);
        i = fracEnd;
    }
    if (intEnd == 0 && fracDigits == 0) return std::nullopt;
    if (i < body.size() && (body[i] == 'e' || body[i] == 'E')) {
        size_t j = i + 1;
        if (j < body.size() && (body[j] == '+' || body[j] == '-')) ++j;
        size_t expEnd = skipDigits(body, j);
        if (expEnd == j) return std::nullopt;
        i = expEnd;
    }
    if (i != body.size()) return std::nullopt;

    double value = 0.0;
    std::from_chars_result r = std::from_chars(body.data(), body.data() + body.size(), value);
    if (r.ec == std::errc::result_out_of_range) {
        value = decimalMagnitude(body) < 0 ? 0.0 : std::numeric_limits<double>::infinity();
    } else if (r.ec != std::errc() || r.ptr != body.data() + body.size()) {
        return std::nullopt;
    }
    return negative ? -value : value;
}

std::optional<long long> parseInteger(std::string_view word) {
    std::string_view body = word;
    bool negative = false;
    if (!body.empty() && (body[0] == '+' || body[0] == '-')) {
        negative = body[0] == '-';
        body.remove_prefix(1);
    }
    if (body.empty() || !std::all_of(body.begin(), body.end(),
                                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }))
        return std::nullopt;
    long long value = 0;
    std::from_chars_result r = std::from_chars(body.data(), body.data() + body.size(), value);
    if (r.ec != std::errc() || r.ptr != body.data() + body.size()) return std::nullopt;
    return negative ? -value : value;
}

}  // namespace fp
