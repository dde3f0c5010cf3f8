// The strict lexical layer: what counts as a number, a line and text.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/text_file.h"
#include "scene/text_syntax.h"

namespace fp {
namespace {

TEST(TextSyntax, RealsAcceptedWithTheirValues) {
    const std::pair<const char*, double> cases[] = {
        {"0", 0.0},       {"-1", -1.0},
        {"+2.5", 2.5},    {".5", 0.5},
        {"-.25", -0.25},  {"3.", 3.0},
        {"1e3", 1000.0},  {"1E-2", 0.01},
        {"2.5e+1", 25.0}, {"548.7", 548.7},
        {"1e-400", 0.0},  {"0.0000000000000000000000000000000000000000000000000000000000001e-300", 0.0},
    };
    for (const auto& [text, value] : cases) {
        std::optional<double> parsed = parseReal(text);
        ASSERT_TRUE(parsed.has_value()) << text;
        EXPECT_EQ(*parsed, value) << text;
    }
}

TEST(TextSyntax, NonFiniteRealsAreNumbersToo) {
    EXPECT_TRUE(std::isnan(*parseReal("nan")));
    EXPECT_TRUE(std::isnan(*parseReal("-NaN")));
    EXPECT_EQ(*parseReal("inf"), INFINITY);
    EXPECT_EQ(*parseReal("-Infinity"), -INFINITY);
    EXPECT_EQ(*parseReal("1e400"), INFINITY);
    EXPECT_EQ(*parseReal("-1e400"), -INFINITY);
    EXPECT_EQ(*parseReal("12345678901234567890e300"), INFINITY);
    EXPECT_FALSE(std::isfinite(static_cast<float>(*parseReal("1e39"))));
}

TEST(TextSyntax, MalformedRealsRejected) {
    for (const char* text : {"", "abc", "1,5", "0x10", "1e", "1e+", "e5", ".", "-", "+", "1.2.3", "1-2",
                             "--1", "nanx", "infinit", "1 ", " 1", "1f", "١"})
        EXPECT_FALSE(parseReal(text).has_value()) << "'" << text << "'";
}

TEST(TextSyntax, Integers) {
    EXPECT_EQ(parseInteger("42"), 42);
    EXPECT_EQ(parseInteger("-3"), -3);
    EXPECT_EQ(parseInteger("+7"), 7);
    for (const char* text : {"", "-", "1.0", "x", "1e3", "99999999999999999999", "0x1"})
        EXPECT_FALSE(parseInteger(text).has_value()) << "'" << text << "'";
}

TEST(TextSyntax, LinesEndAtLfCrlfOrCr) {
    LineReader lines("a\nb\r\nc\rd");
    std::string_view line;
    std::vector<std::string> seen;
    while (lines.next(&line)) seen.push_back(std::to_string(lines.number()) + ":" + std::string(line));
    EXPECT_EQ(seen, (std::vector<std::string>{"1:a", "2:b", "3:c", "4:d"}));
    LineReader blank("\n\r\n");
    int count = 0;
    while (blank.next(&line)) ++count;
    EXPECT_EQ(count, 2);
}

TEST(TextSyntax, WordsSplitOnBlanks) {
    std::vector<std::string_view> words;
    splitWords(" \tf  1\v2\f3 \t", &words);
    EXPECT_EQ(words, (std::vector<std::string_view>{"f", "1", "2", "3"}));
    EXPECT_EQ(trimBlanks("\t a b \t"), "a b");
}

TEST(TextFile, NonTextDetected) {
    EXPECT_EQ(nonTextReason("v 1 2 3\r\n\tf 1 2 3\f\v\x1a"), "");
    EXPECT_EQ(nonTextReason("caf\xC3\xA9"), "");  // UTF-8 is text
    EXPECT_NE(nonTextReason(std::string("a\nb\0", 4)).find("NUL byte at line 2"), std::string::npos);
    EXPECT_NE(nonTextReason("\x89PNG\r\n").find("PNG"), std::string::npos);
    EXPECT_NE(nonTextReason("\xFE\xFF").find("UTF-16"), std::string::npos);
    EXPECT_NE(nonTextReason("x\x1b[0m").find("byte 0x1B"), std::string::npos);
    EXPECT_EQ(stripUtf8Bom("\xEF\xBB\xBFv"), "v");
    EXPECT_EQ(stripUtf8Bom("v"), "v");
}

}  // namespace
}  // namespace fp
