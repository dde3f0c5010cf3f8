// readFileBytes: the whole file, byte for byte, whatever the file system says its size is;
// checkWritablePath: why an output cannot be written, said before the work that would write it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/file.h"

namespace fp {
namespace {

TEST(ReadFileBytes, ReturnsEveryByteOfABinaryFile) {
    std::string bytes;
    for (unsigned i = 0; i < 300000; ++i) bytes.push_back(char(i * 7919u % 256u));  // zeros, high bytes too
    const std::string path = (std::filesystem::temp_directory_path() / "fragpath_file_test.bin").string();
    std::ofstream(path, std::ios::binary) << bytes;
    EXPECT_EQ(readFileBytes(path), bytes);
    std::ofstream(path, std::ios::binary | std::ios::trunc);  // empty
    EXPECT_EQ(readFileBytes(path), "");
    std::filesystem::remove(path);
}

// /proc files report a size of 0 and still have contents.
TEST(ReadFileBytes, ReadsFilesThatReportNoSize) {
    ASSERT_EQ(std::filesystem::file_size("/proc/self/status"), 0u);
    EXPECT_NE(readFileBytes("/proc/self/status").find("Name:"), std::string::npos);
}

TEST(ReadFileBytes, RefusesWhatIsNotARegularFile) {
    EXPECT_THROW(readFileBytes(""), Error);
    EXPECT_THROW(readFileBytes("/nonexistent/fragpath"), Error);
    EXPECT_THROW(readFileBytes(std::filesystem::temp_directory_path().string()), Error);
}

// The message of the fp::Error checkWritablePath throws, "" for none.
std::string writeRefusal(const std::string& path) {
    try {
        checkWritablePath(path, "--json");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(CheckWritablePath, SaysWhyAFileCannotBeWrittenThere) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("fragpath_writable_" + std::to_string(getpid()));
    fs::create_directories(dir / "sub");
    const std::string file = (dir / "out.json").string();
    EXPECT_EQ(writeRefusal(file), "");
    EXPECT_EQ(writeRefusal("relative.json"), "");  // in the current directory
    const std::string missing = (dir / "missing" / "out.json").string();
    EXPECT_EQ(writeRefusal(missing),
              "--json " + missing + ": directory " + (dir / "missing").string() + " does not exist");
    EXPECT_EQ(writeRefusal((dir / "sub").string()), "--json " + (dir / "sub").string() + " is a directory");
    // A directory no one may create files in, root included.
    EXPECT_EQ(writeRefusal("/proc/self/out.json"),
              "--json /proc/self/out.json: directory /proc/self is not writable");
    fs::remove_all(dir);
}

}  // namespace
}  // namespace fp
