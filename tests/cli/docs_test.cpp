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

std::string readme() {
    std::ifstream in(std::string(FP_SOURCE_DIR) + "/README.md");
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

// Every option `fragpath COMMAND --help` lists (at least `minimum`, so that the parse found the table,
// not a stray line) is in the README, written as `--option.
void expectReadmeListsOptionsOf(const std::string& command, size_t minimum) {
    test::CliRun r = test::runFragpath(command + " --help");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::set<std::string> options = optionsInHelp(r.output);
    ASSERT_GE(options.size(), minimum) << r.output;
    const std::string text = readme();
    ASSERT_FALSE(text.empty());
    EXPECT_NE(text.find("`fragpath " + command), std::string::npos);
    for (const std::string& option : options) {
        if (option == "--help") continue;
        EXPECT_NE(text.find("`" + option), std::string::npos) << command << " " << option;
    }
}

TEST(Docs, TheReadmeListsEveryRenderOption) {
    expectReadmeListsOptionsOf("render", 25);
}
TEST(Docs, TheReadmeListsEveryCompareOption) {
    expectReadmeListsOptionsOf("compare", 4);
}
TEST(Docs, TheReadmeListsEveryRealtimeOption) {
    expectReadmeListsOptionsOf("realtime", 25);
}
TEST(Docs, TheReadmeListsEveryStudyOption) {
    expectReadmeListsOptionsOf("study", 20);
}

}  // namespace
}  // namespace fp
