#pragma once
// The lexical layer shared by the OBJ and MTL checks: lines, words and numbers, spelled strictly.
#include <optional>
#include <string_view>
#include <vector>

namespace fp {

// Splits text into lines the way tinyobjloader does ("\n", "\r\n" or a lone "\r" ends a line), so that
// line numbers in our messages match what an editor shows.
class LineReader {
  public:
    explicit LineReader(std::string_view text) : rest_(text) {}
    // The next line without its terminator; false at the end of the text.
    bool next(std::string_view* line);
    // 1-based number of the line last returned.
    int number() const { return number_; }

  private:
    std::string_view rest_;
    int number_ = 0;
};

// Blank-separated words of `line` (space, tab, vertical tab, form feed), replacing `words`' contents.
void splitWords(std::string_view line, std::vector<std::string_view>* words);

// `line` without leading and trailing blanks.
std::string_view trimBlanks(std::string_view line);

// A decimal real as OBJ and MTL write it: [+-] digits [. digits] [e [+-] digits], or nan / inf /
// infinity in any case. nullopt for anything else (tinyobjloader would read "abc" or "1,5" as 0). The
// value may be NaN or infinite; so may its float conversion (1e39).
std::optional<double> parseReal(std::string_view word);

// A decimal integer, [+-] digits; nullopt if malformed or outside the range of long long.
std::optional<long long> parseInteger(std::string_view word);

}  // namespace fp
