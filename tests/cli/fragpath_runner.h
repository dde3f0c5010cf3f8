#pragma once
// Running build/fragpath as a user would, from the CLI tests, in a fresh temporary directory per test.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace fp::test {

struct CliRun {
    int exitCode;
    std::string output;  // stdout and stderr together
};

// Any shell command (the native reference, the viewer under xvfb-run), with stdout and stderr together.
inline CliRun runCommand(const std::string& command) {
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    std::string output;
    char buffer[4096];
    while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
    int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

// `environment` is prepended as VAR=value assignments; LP_NUM_THREADS=2 unless it sets its own.
inline CliRun runFragpath(const std::string& args, const std::string& environment = "LP_NUM_THREADS=2") {
    return runCommand(environment + " " + FP_BINARY + " " + args);
}

class TempDirTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("fragpath_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name, std::ios::binary) << text;
        return path(name);
    }
    std::filesystem::path dir_;
};

}  // namespace fp::test
