// The settings table (settings/setting_table.h) walked row by row: every flag and every scene-file key
// it declares is accepted, under --strict too, arrives in RenderSettings, and its help, its range and its
// fingerprint rule are what the row says.
#include <gtest/gtest.h>

#include <set>

#include "core/error.h"
#include "core/log.h"
#include "core/text.h"
#include "request/render_request.h"
#include "scene/load.h"
#include "scene/scene_test_util.h"
#include "settings/integrators.h"
#include "settings/setting_table.h"

namespace fp {
namespace {

RenderRequest request(const std::vector<std::string>& argv) {
    return RenderRequest(Args(argv, requestOptionGroups(kAllRequestOptions)));
}

// Values a row takes that are not its default: every choice, the range's ends, the special name.
std::vector<std::string> valuesToTry(const Setting& s) {
    std::vector<std::string> values;
    for (const SettingChoice& c : s.choices) values.push_back(c.name);
    if (s.kind != SettingKind::Choice) {
        values.push_back(settingText(s, s.min));
        if (std::isfinite(s.max)) values.push_back(settingText(s, s.max));
        if (s.specialName) values.push_back(s.specialName);
    }
    return values;
}

// The value `text` of a row, set through its flag, reaches RenderSettings; with --strict nothing warns.
TEST(SettingTable, EveryFlagIsAcceptedUnderStrictAndArrives) {
    int tried = 0;
    for (const Setting& s : settingTable()) {
        if (!*s.flag) continue;
        for (const std::string& text : valuesToTry(s)) {
            std::string value = text;
            if (isSizePart(s)) value = std::string(s.name) == "width" ? text + "x7" : "7x" + text;
            WarningCapture capture;
            const RenderRequest r = request({s.flag, value, "--strict"});
            setStrictWarnings(false);
            EXPECT_EQ(settingText(s, s.get(r.settings(Scene()))), text) << s.flag << " " << value;
            EXPECT_TRUE(capture.messages().empty()) << s.flag;
            ++tried;
        }
    }
    EXPECT_GE(tried, 35);
}

TEST(SettingTable, EverySceneFileKeyIsAcceptedUnderStrictAndArrives) {
    test::TempDir dir;
    dir.write("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    int tried = 0;
    for (const Setting& s : settingTable()) {
        if (!s.sceneFile) continue;
        for (const std::string& text : valuesToTry(s)) {
            const bool named = s.kind == SettingKind::Choice || (s.specialName && text == s.specialName);
            const std::string json = R"({"mesh": "mesh.obj", "render": {")" + std::string(s.name) +
                                     "\": " + (named ? "\"" + text + "\"" : text) + "}}";
            WarningCapture capture;
            setStrictWarnings(true);
            Scene scene;
            EXPECT_NO_THROW(scene = loadScene(dir.write("scene.json", json))) << json;
            setStrictWarnings(false);
            EXPECT_EQ(settingText(s, s.get(request({}).settings(scene))), text) << json;
            EXPECT_TRUE(capture.messages().empty()) << json;
            ++tried;
        }
    }
    EXPECT_GE(tried, 25);
}

// Each row's range and choices are enforced where values come in: a value beyond it fails, naming the flag.
TEST(SettingTable, ValuesOutsideARowAreRefusedNamingTheFlag) {
    for (const Setting& s : settingTable()) {
        if (!*s.flag || isSizePart(s)) continue;
        const bool zeroIsSpecial = s.specialName && s.specialValue == s.min - 1.0;
        std::vector<std::string> bad = {"nonsense"};
        if (s.kind != SettingKind::Choice && !zeroIsSpecial) bad.push_back(formatText("%.10g", s.min - 1.0));
        if (s.kind == SettingKind::Integer) {
            bad.push_back(formatText("%.10g", s.max + 1.0));
            bad.push_back("1.5");
        }
        for (const std::string& text : bad) {
            try {
                request({s.flag, text});
                ADD_FAILURE() << s.flag << " " << text << " was accepted";
            } catch (const Error& e) {
                EXPECT_NE(std::string(e.what()).find(s.flag), std::string::npos) << e.what();
            }
        }
    }
}

// --help lists each visible row once, with its default; the hidden rows not at all.
TEST(SettingTable, HelpListsEveryVisibleFlagOnceWithItsDefault) {
    const std::string help = formatOptions(requestOptionGroups(kAllRequestOptions));
    std::set<std::string> flags;
    for (const Setting& s : settingTable()) {
        if (!*s.flag) {
            EXPECT_TRUE(s.hidden) << s.name << ": a row without a flag is set by front ends only";
            continue;
        }
        flags.insert(s.flag);
    }
    for (const std::string& flag : flags) {
        const size_t at = help.find("  " + flag + " ");
        ASSERT_NE(at, std::string::npos) << flag;
        EXPECT_EQ(help.find("  " + flag + " ", at + 1), std::string::npos) << flag << " twice";
    }
    EXPECT_NE(help.find("nee | bdpt (default: the scene file's, else nee)\n"), std::string::npos) << help;
    EXPECT_NE(help.find("(default: the scene file's, else 512x512)"), std::string::npos) << help;
    EXPECT_NE(help.find("1 to 16, or auto (default: auto)\n"), std::string::npos) << help;
}

// The fingerprint rule as data: a row that enters it always changes it; one that enters it only when
// chosen changes it only away from its default; one that does not, never.
TEST(SettingTable, SettingsEnterTheFingerprintAsTheirRowSays) {
    for (const Setting& s : settingTable()) {
        const bool always = s.effects & kEntersFingerprint, ifChosen = s.effects & kEntersFingerprintIfChosen;
        EXPECT_FALSE(always && ifChosen) << s.name;
        // Anything a part's pixels depend on must enter it (or restart, for a viewer).
        if (s.effects & kRecompiles) {
            EXPECT_TRUE(always || ifChosen || !s.sceneFile) << s.name;
        }
    }
    EXPECT_FALSE(findSetting("spp")->effects & (kEntersFingerprint | kEntersFingerprintIfChosen));
    EXPECT_FALSE(findSetting("samples_per_pass")->effects &
                 (kEntersFingerprint | kEntersFingerprintIfChosen));
    EXPECT_FALSE(findSetting("sample_offset")->effects & (kEntersFingerprint | kEntersFingerprintIfChosen));
}

TEST(SettingTable, SameSettingsComparesOnlyTheRowsOfAnEffect) {
    RenderSettings a, b;
    b.spp = 3;  // no effect: a viewer's new target keeps its accumulation
    EXPECT_TRUE(sameSettings(a, b, kRestartsAccumulation | kRecompiles));
    b.seed = 4;  // restarts, not a define
    EXPECT_FALSE(sameSettings(a, b, kRestartsAccumulation));
    EXPECT_TRUE(sameSettings(a, b, kRecompiles));
    b.sampler = Sampler::Independent;
    EXPECT_FALSE(sameSettings(a, b, kRecompiles));
}

TEST(SettingTable, CheckSettingsRefusesWhatNoFlagCouldGive) {
    RenderSettings s;
    EXPECT_NO_THROW(checkSettings(s));
    s.maxDepth = -1;
    EXPECT_THROW(checkSettings(s), Error);
    s = RenderSettings();
    s.clampIndirect = std::numeric_limits<float>::infinity();
    EXPECT_THROW(checkSettings(s), Error);
    s = RenderSettings();
    s.integrator = Integrator(7);
    EXPECT_THROW(checkSettings(s), Error);
}

// An integrator's facts: bdpt's depth cap is said, not silent; each integrator honours what its row says.
TEST(Integrators, TheDepthCapIsShown) {
    EXPECT_EQ(integratorDepth(Integrator::Bdpt, 64), integratorFacts(Integrator::Bdpt).depthCap);
    EXPECT_EQ(integratorDepth(Integrator::Nee, 64), 64);
    EXPECT_FALSE(depthCapNote(Integrator::Bdpt, 5));
    EXPECT_EQ(depthCapNote(Integrator::Bdpt, 64).value_or(""),
              "bdpt traces at most 12 bounces: --max-depth 64 renders depth 12");
    EXPECT_FALSE(integratorHonours(Integrator::Bdpt, *findSetting("clamp_indirect")));
    EXPECT_TRUE(integratorHonours(Integrator::Nee, *findSetting("caustics")));
    EXPECT_FALSE(integratorHonours(Integrator::Bsdf, *findSetting("caustics")));
    for (Integrator i : kAllIntegrators) EXPECT_EQ(parseIntegrator(integratorName(i)), i);
}

}  // namespace
}  // namespace fp
