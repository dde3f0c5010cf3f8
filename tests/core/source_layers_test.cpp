// The folders of src/ are layers (docs/architecture.md, "Folders"): a file includes headers of its own
// folder and of folders below it, never above, so that a front end (the study, the viewer, the
// commands) can change without the stages beneath noticing. A new folder must be placed here.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace fp {
namespace {

namespace fs = std::filesystem;

// Lowest first.
const std::vector<std::string> kLayers = {"core",     "settings", "image", "gl",     "bvh",    "scene",
                                          "request",  "pack",     "gpu",   "native", "render", "denoise",
                                          "realtime", "viewer",   "bench", "study",  "app"};

int layerOf(const std::string& folder) {
    auto it = std::find(kLayers.begin(), kLayers.end(), folder);
    return it == kLayers.end() ? -1 : int(it - kLayers.begin());
}

TEST(SourceLayers, EveryIncludeIsOfTheSameLayerOrOneBelow) {
    const fs::path src = fs::path(FP_SOURCE_DIR) / "src";
    const std::regex include(R"re(^\s*#\s*include\s*"([a-z_]+)/[^"]+")re");
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(src)) {
        const std::string ext = entry.path().extension().string();
        if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
        const std::string folder = entry.path().lexically_relative(src).begin()->string();
        const int layer = layerOf(folder);
        ASSERT_GE(layer, 0) << "src/" << folder << "/ is in no layer: add it to kLayers";
        ++files;
        std::ifstream in(entry.path());
        std::string line;
        for (int number = 1; std::getline(in, line); ++number) {
            std::smatch m;
            if (!std::regex_match(line, m, include)) continue;
            const int included = layerOf(m[1].str());
            if (included < 0)
                continue;  // a library's header (<glm/...> is in <>, but "imgui/..." may not be)
            EXPECT_LE(included, layer)
                << entry.path().lexically_relative(src).generic_string() << ":" << number << " includes "
                << m[1].str() << "/, a layer above " << folder << "/";
        }
    }
    EXPECT_GT(files, 100);
}

}  // namespace
}  // namespace fp
