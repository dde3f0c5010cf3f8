// The README's options table is where users look first: every option that `render --help` lists
// (generated from the command's option table, src/request/options.h) must be in it.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <regex>
#include <set>
#include <sstream>

#include "cli/fragpath_runner.h"

namespace fp {
namespace {

std::set<std::string> optionsInHelp(const std::string& help) {
    // An option line starts with two spaces, then "-x, --name" or "--name".
    std::set<std::string> options;
    std::regex line(R"(^  (?:-\w, )?(--[a-z][a-z-]*))");
    std::istringstream in(help);
    for (std::string text; std::getline(in, text);) {
        std::smatch m;
        if (std::regex_search(text, m, line)) options.insert(m[1]);
    }
    return options;
}

TEST(Docs, TheReadmeListsEveryRenderOption) {
    test::CliRun r = test::runFragpath("render --help");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::set<std::string> options = optionsInHelp(r.output);
    ASSERT_GE(options.size(), 25u) << r.output;  // the parse found the table, not a stray line
    std::ifstream in(std::string(FP_SOURCE_DIR) + "/README.md");
    const std::string readme((std::istreambuf_iterator<char>(in)), {});
    ASSERT_FALSE(readme.empty());
    for (const std::string& option : options) {
        if (option == "--help") continue;
        EXPECT_NE(readme.find("`" + option), std::string::npos) << option;
    }
}

TEST(Docs, TheReadmeListsEveryCompareOption) {
    test::CliRun r = test::runFragpath("compare --help");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::set<std::string> options = optionsInHelp(r.output);
    ASSERT_GE(options.size(), 4u) << r.output;
    std::ifstream in(std::string(FP_SOURCE_DIR) + "/README.md");
    const std::string readme((std::istreambuf_iterator<char>(in)), {});
    EXPECT_NE(readme.find("`fragpath compare"), std::string::npos);
    for (const std::string& option : options) {
        if (option == "--help") continue;
        EXPECT_NE(readme.find("`" + option), std::string::npos) << option;
    }
}

}  // namespace
}  // namespace fp
