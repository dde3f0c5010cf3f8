#pragma once
// Helpers for the scene tests: inputs are written to a fresh temporary directory by each test instead
// of being committed as dozens of tiny files.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>

#include "core/error.h"
#include "core/log.h"
#include "scene/scene.h"

namespace fp::test {

class TempDir {
  public:
    TempDir() {
        static std::atomic<int> counter{0};
        auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
        path_ = std::filesystem::temp_directory_path() /
                ("fp_scene_test_" + std::to_string(stamp) + "_" + std::to_string(counter++));
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    // Writes `bytes` (binary, exactly) to `name` inside the directory; returns its path.
    std::string write(const std::string& name, const std::string& bytes) const {
        std::filesystem::path file = path_ / name;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream out(file, std::ios::binary);
        out << bytes;
        return file.string();
    }
    std::string path(const std::string& name = "") const { return (path_ / name).string(); }

  private:
    std::filesystem::path path_;
};

// The fp::Error message `load` throws; fails the test (and returns "") if it throws nothing.
inline std::string errorOf(const std::function<void()>& load) {
    try {
        load();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected fp::Error, nothing was thrown";
    return "";
}

// Asserts every fragment occurs in `text`.
#define EXPECT_CONTAINS_ALL(text, ...)                                                          \
    do {                                                                                        \
        const std::string fp_text_ = (text);                                                    \
        for (const std::string& fp_fragment_ : std::initializer_list<std::string>{__VA_ARGS__}) \
            EXPECT_NE(fp_text_.find(fp_fragment_), std::string::npos)                           \
                << "missing '" << fp_fragment_ << "' in: " << fp_text_;                         \
    } while (0)

// All captured warnings, one per line, for failure messages.
inline std::string joined(const WarningCapture& capture) {
    std::string out;
    for (const std::string& m : capture.messages()) out += m + "\n";
    return out;
}

// One triangle of material 0, Lambertian and not emissive, without an environment.
inline Scene unlitTriangle() {
    Scene scene;
    scene.source = "unlit.obj";
    Triangle t;
    t.p = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
    scene.triangles.push_back(t);
    scene.materials.push_back(Material{});
    return scene;
}

}  // namespace fp::test
