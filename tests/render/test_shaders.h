#pragma once
// The shaders every GPU test renders with, from one place. testShaders() reads the glsl/ directory that
// FP_RENDER_TEST_SHADERS names, or else the source tree's glsl/, so that a copy with a deliberate bias can
// be tried on every test without rebuilding (how the tests' comments say what each one catches).
// testShadersEdited() gives a test a variant of those shaders (a strategy isolated, a choice undone)
// by editing a copy of them, so that the production shaders carry no test switches.
//
// A test that made its library any other way (ShaderLibrary(), the Renderer's default argument, a
// directory of its own) would render with shaders the variable never reaches. So the tests read their
// shaders from disk, never from the copy compiled into the binary (which
// tests/gl/shader_library_test.cpp checks is the source tree's glsl/), and after every test a listener
// checks that all the shaders read during it came from here (ShaderLibrary::takeSourcesRead): a test
// that bypasses testShaders() fails.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/error.h"
#include "gl/shader_source.h"

namespace fp::test {

// The glsl/ directory the tests render with.
inline std::string testShaderDirectory() {
    const char* dir = std::getenv("FP_RENDER_TEST_SHADERS");
    return dir && *dir ? std::string(dir) : std::string(FP_SOURCE_DIR "/glsl");
}

// The directories testShaders() and testShadersEdited() have handed out in this process.
class TestShaderSources {
  public:
    static void add(const std::string& directory) {
        std::lock_guard<std::mutex> lock(mutex());
        sources().insert(directory);
    }
    static bool contains(const std::string& directory) {
        std::lock_guard<std::mutex> lock(mutex());
        return sources().count(directory) != 0;
    }

  private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    static std::set<std::string>& sources() {
        static std::set<std::string> s;
        return s;
    }
};

// The one factory of the GPU tests' shader libraries.
inline ShaderLibrary testShaders() {
    std::string directory = testShaderDirectory();
    TestShaderSources::add(directory);
    return ShaderLibrary(directory);
}

// One change to a file below glsl/: `find`, which must occur exactly once, becomes `replace`; with `find`
// empty, `replace` is appended to the file.
struct ShaderEdit {
    std::string file, find, replace;
};

// A copy of testShaders()' directory with `edits` applied, removed when the test program exits. An edit
// whose text is not found exactly once is an fp::Error: the shader changed under the test, whose edit
// must follow it (a silent miss would test the unedited shaders).
inline ShaderLibrary testShadersEdited(const std::string& name, const std::vector<ShaderEdit>& edits) {
    namespace fs = std::filesystem;
    static std::atomic<int> copies{0};
    static std::vector<fs::path> made;
    static struct RemoveAtExit {
        ~RemoveAtExit() {
            for (const fs::path& d : made) fs::remove_all(d);
        }
    } removeAtExit;
    fs::path dir = fs::temp_directory_path() / ("fragpath_shaders_" + name + "_" +
                                                std::to_string(::getpid()) + "_" + std::to_string(copies++));
    fs::remove_all(dir);
    fs::copy(testShaderDirectory(), dir, fs::copy_options::recursive);
    made.push_back(dir);
    for (const ShaderEdit& edit : edits) {
        fs::path path = dir / edit.file;
        std::ifstream in(path, std::ios::binary);
        if (!in) throw Error("shader edit '" + name + "': no file glsl/" + edit.file);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        in.close();
        if (edit.find.empty()) {
            text += edit.replace;
        } else {
            size_t at = text.find(edit.find);
            if (at == std::string::npos || text.find(edit.find, at + 1) != std::string::npos)
                throw Error("shader edit '" + name + "': glsl/" + edit.file + " must hold exactly once:\n" +
                            edit.find);
            text.replace(at, edit.find.size(), edit.replace);
        }
        std::ofstream(path, std::ios::binary) << text;
    }
    TestShaderSources::add(dir.string());
    return ShaderLibrary(dir.string());
}

// After every test: the shaders read during it (and its suite's set-up) came from the factory above.
class ShaderSourceCheck : public ::testing::EmptyTestEventListener {
    void OnTestEnd(const ::testing::TestInfo&) override {
        for (const std::string& source : ShaderLibrary::takeSourcesRead())
            EXPECT_TRUE(TestShaderSources::contains(source))
                << "shaders read from " << (source.empty() ? "the copy compiled into the binary" : source)
                << ", not through testShaders() (tests/render/test_shaders.h): FP_RENDER_TEST_SHADERS "
                   "would not reach them";
    }
};

inline const bool kShaderSourceCheckInstalled = [] {
    ::testing::UnitTest::GetInstance()->listeners().Append(new ShaderSourceCheck);
    return true;
}();

}  // namespace fp::test
