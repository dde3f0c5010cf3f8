// core/text.h: lower-casing, file extensions, comma-separated name lists and printf into a string.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "core/text.h"

namespace fp {
namespace {

using Names = std::vector<std::string>;

TEST(Text, ToLowerAsciiLowersOnlyAToZ) {
    EXPECT_EQ(toLowerAscii("FALSE No 0"), "false no 0");
    EXPECT_EQ(toLowerAscii(""), "");
    // Bytes of UTF-8 and punctuation next to the letters' range pass unchanged, in any locale.
    EXPECT_EQ(toLowerAscii("@[Z]`\xc3\x89"), "@[z]`\xc3\x89");
}

TEST(Text, LowerCaseExtensionIsTheFileNamesOwn) {
    EXPECT_EQ(lowerCaseExtension("out/Render.PFM"), ".pfm");
    EXPECT_EQ(lowerCaseExtension("image.Exr"), ".exr");
    EXPECT_EQ(lowerCaseExtension("archive.tar.GZ"), ".gz");
    EXPECT_EQ(lowerCaseExtension("dir.PNG/image"), "");  // the directory's dot is not the file's
    EXPECT_EQ(lowerCaseExtension("noextension"), "");
    EXPECT_EQ(lowerCaseExtension(""), "");
}

TEST(Text, SplitNameListSplitsAtCommas) {
    EXPECT_EQ(splitNameList("nee", "--x"), Names{"nee"});
    EXPECT_EQ(splitNameList("naive,bsdf,nee", "--x"), (Names{"naive", "bsdf", "nee"}));
    EXPECT_EQ(splitNameList("a b,c", "--x"), (Names{"a b", "c"}));  // no trimming: a name is as given
}

TEST(Text, SplitNameListRefusesEmptyAndRepeatedNames) {
    for (const char* text : {"", ",", "a,", ",a", "a,,b"}) {
        try {
            splitNameList(text, "--scenes");
            ADD_FAILURE() << "accepted '" << text << "'";
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()), "--scenes: empty name in '" + std::string(text) + "'");
        }
    }
    try {
        splitNameList("a,b,a", "--denoisers");
        ADD_FAILURE() << "accepted a repeated name";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "--denoisers: 'a' is listed twice");
    }
}

// The whole text however long (the study report's own copy cut it at 4095 bytes), and an empty one.
TEST(Text, FormatTextHasNoLengthLimit) {
    EXPECT_EQ(formatText("%d spp, %.2f s, %s", 16, 1.5, "nee"), "16 spp, 1.50 s, nee");
    EXPECT_EQ(formatText("%s", ""), "");
    const std::string longText(10000, 'x');
    EXPECT_EQ(formatText("<%s>", longText.c_str()), "<" + longText + ">");
}

}  // namespace
}  // namespace fp

namespace fp {
namespace {

enum class Fruit { Apple, Pear, Plum };
constexpr Fruit kAllFruit[] = {Fruit::Apple, Fruit::Pear, Fruit::Plum};
const char* fruitName(Fruit f) {
    static constexpr const char* kNames[] = {"apple", "pear", "plum"};
    return nameOf(f, kNames);
}

TEST(Names, NameOfIndexesByTheEnumeratorsValue) {
    EXPECT_STREQ(fruitName(Fruit::Pear), "pear");
    EXPECT_STREQ(fruitName(static_cast<Fruit>(7)), "?");
}

TEST(Names, ParseNameFindsTheChoiceOrListsThemAll) {
    EXPECT_EQ(parseName("plum", kAllFruit, fruitName, "fruit"), Fruit::Plum);
    try {
        parseName("kiwi", kAllFruit, fruitName, "fruit");
        ADD_FAILURE() << "kiwi is no fruit here";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "unknown fruit 'kiwi' (choose apple, pear or plum)");
    }
    EXPECT_EQ(choiceList({"a"}), "a");
    EXPECT_EQ(choiceList({"a", "b"}), "a or b");
}

}  // namespace
}  // namespace fp
