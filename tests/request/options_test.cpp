// --help text from the option table: groups in order, one aligned help column, long lines wrapped.
#include <gtest/gtest.h>

#include <sstream>

#include "request/options.h"

namespace fp {
namespace {

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

TEST(Options, GroupsUnderTheirTitlesWithOneHelpColumn) {
    std::string text =
        formatOptions({{"First", {{"--output", "-o", "FILE", "where"}, {"--quiet", "", "", "hush"}}},
                       {"Empty", {}},
                       {"Second", {{"--spp", "", "N", "samples\nper pixel"}}}});
    std::vector<std::string> l = lines(text);
    ASSERT_EQ(l.size(), 8u) << text;
    EXPECT_EQ(l[1], "First:");
    EXPECT_EQ(l[2].rfind("  -o, --output FILE", 0), 0u) << l[2];
    EXPECT_EQ(l[5], "Second:");  // the empty group is left out
    // Every help text starts in the same column, continuation lines too.
    size_t column = l[2].find("where");
    EXPECT_EQ(l[3].find("hush"), column);
    EXPECT_EQ(l[6].find("samples"), column);
    EXPECT_EQ(l[7].find("per pixel"), column);
    EXPECT_EQ(l[7].find_first_not_of(' '), column);
}

TEST(Options, LongHelpWrapsAtWordsWithinTheWidth) {
    std::string words;
    for (int i = 0; i < 40; ++i) words += (i ? " word" : "word") + std::to_string(i);
    std::string text = formatOptions({{"G", {{"--flag", "", "X", words}}}});
    std::vector<std::string> l = lines(text);
    ASSERT_GT(l.size(), 3u);
    for (const std::string& line : l) {
        EXPECT_LE(line.size(), 104u) << line;
    }
    // Every word survives, in order.
    std::string joined;
    for (size_t i = 2; i < l.size(); ++i) joined += (i > 2 ? " " : "") + l[i].substr(l[i].find("word"));
    EXPECT_EQ(joined, words);
}

}  // namespace
}  // namespace fp
