// The command-line reader: both GNU forms, aliases, negative values and the errors a user can make.
#include <gtest/gtest.h>

#include "core/error.h"
#include "request/args.h"

namespace fp {
namespace {

const std::vector<OptionGroup> kOptions = {{"Test",
                                            {{"--output", "-o", "FILE", "an output"},
                                             {"--spp", "", "N", "samples"},
                                             {"--eye", "", "X,Y,Z", "a point"},
                                             {"--quiet", "", "", "a switch"}}}};

Args read(const std::vector<std::string>& argv) {
    return Args(argv, kOptions);
}

std::string errorOf(const std::vector<std::string>& argv) {
    try {
        read(argv);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(Args, BothGnuFormsGiveTheSameValue) {
    EXPECT_EQ(read({"--spp", "16"}).integer("--spp", 1, 100), 16);
    EXPECT_EQ(read({"--spp=16"}).integer("--spp", 1, 100), 16);
}

TEST(Args, AnAliasIsStoredUnderItsOption) {
    Args a = read({"-o", "x.png"});
    EXPECT_EQ(a.text("--output"), "x.png");
    EXPECT_FALSE(a.has("-o"));
}

TEST(Args, NegativeValuesAndPositionalArguments) {
    Args a = read({"scene.obj", "--eye", "-1,0,-2.5", "--quiet"});
    EXPECT_EQ(a.vec3("--eye"), glm::vec3(-1.0f, 0.0f, -2.5f));
    EXPECT_TRUE(a.has("--quiet"));
    EXPECT_EQ(a.positional(), std::vector<std::string>{"scene.obj"});
}

TEST(Args, MistakesAreNamed) {
    EXPECT_NE(errorOf({"--sp", "4"}).find("unknown option --sp"), std::string::npos);
    EXPECT_NE(errorOf({"--quiet=yes"}).find("option --quiet takes no value"), std::string::npos);
    EXPECT_NE(errorOf({"--spp"}).find("option --spp needs a value"), std::string::npos);
    EXPECT_NE(errorOf({"--spp", "--quiet"}).find("option --spp needs a value"), std::string::npos);
    EXPECT_NE(errorOf({"--spp="}).find("option --spp needs a value"), std::string::npos);
    try {
        read({"--spp", "0"}).integer("--spp", 1, 100);
        ADD_FAILURE() << "0 is outside 1..100";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("not a whole number from 1 to 100"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace fp
