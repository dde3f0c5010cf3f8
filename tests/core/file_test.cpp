// readFileBytes: the whole file, byte for byte, whatever the file system says its size is.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace fp
