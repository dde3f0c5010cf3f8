// bench/bench_suite.h: the suite's scenes and which of them a command line selects.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bench/bench_suite.h"

namespace fp::bench {
namespace {

using Names = std::vector<std::string>;

TEST(BenchSuite, ScenesRunSmallestFirstWithTheBunnyAmongThem) {
    EXPECT_EQ(suiteSceneNames(), (Names{"cornell", "sphere-1k", "bunny", "sphere-100k", "soup-100k",
                                        "sphere-1m", "sphere-1m-glb"}));
}

TEST(BenchSuite, DefaultIsEverySceneButTheBunny) {
    EXPECT_EQ(selectSuiteScenes({}, false),
              (Names{"cornell", "sphere-1k", "sphere-100k", "soup-100k", "sphere-1m", "sphere-1m-glb"}));
    EXPECT_EQ(selectSuiteScenes({}, true), suiteSceneNames());
}

TEST(BenchSuite, NamedScenesRunInTheSuitesOrder) {
    EXPECT_EQ(selectSuiteScenes({"soup-100k", "cornell"}, false), (Names{"cornell", "soup-100k"}));
    EXPECT_EQ(selectSuiteScenes({"sphere-1m"}, true), (Names{"bunny", "sphere-1m"}));
    EXPECT_EQ(selectSuiteScenes({"bunny"}, false), Names{"bunny"});
    EXPECT_EQ(selectSuiteScenes({"no-such-scene"}, false), Names{});
}

}  // namespace
}  // namespace fp::bench
