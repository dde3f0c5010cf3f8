// The documentation stays true to the program, both ways: every option that `COMMAND --help` lists
// (generated from the command's option table, src/request/options.h, and the settings table) is in the
// README; every fragpath command line the README and docs/ show takes the options it is shown with; and
// every scene-file key `render.KEY` they name is a row of the settings table.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "cli/fragpath_runner.h"
#include "core/log.h"
#include "scene/load.h"
#include "settings/setting_table.h"

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

// The user's pages: the README and docs/*.md, but not the optimisation log, which records history.
std::map<std::string, std::string> userPages() {
    std::map<std::string, std::string> pages = {{"README.md", readme()}};
    for (const auto& entry : std::filesystem::directory_iterator(std::string(FP_SOURCE_DIR) + "/docs")) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".md" || name == "optimisation-log.md") continue;
        std::ifstream in(entry.path());
        pages["docs/" + name] = std::string((std::istreambuf_iterator<char>(in)), {});
    }
    return pages;
}

// Command lines as the pages show them: `fragpath CMD ...` in backticks, and lines of fenced code that
// start with fragpath or build/fragpath; each cut at a pipe, a redirection or a second command.
std::vector<std::string> shownCommandLines(const std::string& page) {
    std::vector<std::string> lines;
    const std::regex inline_(R"(`(?:build/)?(fragpath [^`]*)`)");
    for (auto it = std::sregex_iterator(page.begin(), page.end(), inline_); it != std::sregex_iterator();
         ++it)
        lines.push_back((*it)[1]);
    std::istringstream in(page);
    bool code = false;
    const std::regex codeLine(R"(^\s*(?:\$ )?(?:[A-Z_]+=\S+ )*(?:\./)?(?:build/)?(fragpath .*))");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("```", 0) == 0) code = !code;
        std::smatch m;
        if (code && std::regex_search(line, m, codeLine)) lines.push_back(m[1]);
    }
    for (std::string& line : lines) line = line.substr(0, line.find_first_of("|;>&#"));
    return lines;
}

TEST(Docs, EveryCommandLineShownTakesItsOptions) {
    std::map<std::string, std::set<std::string>> takes;
    for (const char* command : {"render", "view", "realtime", "study", "compare", "merge", "bench"}) {
        test::CliRun r = test::runFragpath(std::string(command) + " --help");
        ASSERT_EQ(r.exitCode, 0) << r.output;
        takes[command] = optionsInHelp(r.output);
        takes[command].insert("--help");
    }
    int checked = 0;
    for (const auto& [name, page] : userPages())
        for (const std::string& line : shownCommandLines(page)) {
            std::istringstream words(line);
            std::string fragpath, command;
            words >> fragpath >> command;
            if (command.rfind("--", 0) == 0) continue;  // fragpath --version, --help
            if (!takes.count(command)) {
                // Prose that starts with the program's name ("fragpath renders ...") is not a command line.
                EXPECT_EQ(line.find("  "), std::string::npos)
                    << name << ": unknown command in `" << line << "`";
                continue;
            }
            for (std::string word; words >> word;) {
                if (word.rfind("--", 0) != 0) continue;
                const std::string option = word.substr(0, word.find('='));
                EXPECT_TRUE(takes[command].count(option))
                    << name << ": `" << line << "`: " << command << " does not take " << option;
            }
            ++checked;
        }
    EXPECT_GE(checked, 50) << "the pages show fragpath command lines";
}

// Every render block the pages show loads under --strict (an unknown key is then an error), every
// `render.KEY` they name is a scene-file setting, and the scene files' page names every one.
class DocsScene : public test::TempDirTest {};

TEST_F(DocsScene, EveryRenderBlockShownLoadsUnderStrict) {
    write("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::regex block(R"("render": \{[^}]*\})"), key(R"(`render\.([a-z_]+)`)");
    int blocks = 0, keys = 0;
    for (const auto& [name, page] : userPages()) {
        for (auto it = std::sregex_iterator(page.begin(), page.end(), block); it != std::sregex_iterator();
             ++it) {
            const std::string scene = write("scene.json", "{\"mesh\": \"mesh.obj\", " + it->str() + "}");
            setStrictWarnings(true);
            EXPECT_NO_THROW(loadScene(scene)) << name << ": " << it->str();
            setStrictWarnings(false);
            ++blocks;
        }
        for (auto it = std::sregex_iterator(page.begin(), page.end(), key); it != std::sregex_iterator();
             ++it) {
            const Setting* s = findSetting((*it)[1]);
            EXPECT_TRUE(s && s->sceneFile)
                << name << ": render." << (*it)[1] << " is not a scene-file setting";
            ++keys;
        }
    }
    EXPECT_GE(blocks, 3) << "the pages show render blocks";
    const std::string page = userPages()["docs/scene-files.md"];
    for (const Setting& s : settingTable())
        if (s.sceneFile) {
            EXPECT_NE(page.find('"' + std::string(s.name) + '"'), std::string::npos) << s.name;
        }
}

}  // namespace
}  // namespace fp
