#pragma once
// Helpers for the image tests: a scratch directory removed afterwards, raw byte I/O and bit comparison.
#include <stdlib.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "core/error.h"
#include "image/image.h"

namespace fp::test {

class TempDir {
  public:
    TempDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "fp_image_test_XXXXXX").string();
        if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string path() const { return path_; }
    std::string file(const std::string& name) const { return path_ + "/" + name; }
    // Names of the entries directly inside the directory, sorted.
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& entry : std::filesystem::directory_iterator(path_)) {
            names.push_back(entry.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }

  private:
    std::string path_;
};

inline std::vector<std::uint8_t> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + path);
}

inline std::vector<std::uint8_t> bytesOf(const std::string& text) {
    return {text.begin(), text.end()};
}

inline std::uint32_t bitsOf(float value) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

inline float floatFromBits(std::uint32_t bits) {
    float value = 0.0f;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

// Bit patterns of the three channels, so NaNs and -0.0 compare exactly.
inline std::vector<std::uint32_t> bitsOf(const glm::vec3& pixel) {
    return {bitsOf(pixel.r), bitsOf(pixel.g), bitsOf(pixel.b)};
}

// A 4x3 image whose channels run through values that lossy or careless float I/O would change:
// signed zero, extremes, subnormals, infinities and NaNs with a payload.
inline Image awkwardImage() {
    using limits = std::numeric_limits<float>;
    const float values[] = {0.0f,
                            -0.0f,
                            1.0f,
                            -1.5f,
                            1e30f,
                            -1e30f,
                            limits::max(),
                            -limits::max(),
                            limits::min(),
                            limits::denorm_min(),
                            -1e-40f,
                            limits::infinity(),
                            -limits::infinity(),
                            floatFromBits(0x7fc12345u),  // quiet NaN with a payload
                            floatFromBits(0xffc00001u),  // negative quiet NaN
                            3.14159274f,
                            0.1f,
                            65504.5f,
                            1.0f / 3.0f,
                            -123456.789f,
                            6.0e-8f,
                            2.5e-3f,
                            7.0f,
                            -7.0f};
    const size_t count = sizeof values / sizeof values[0];
    Image image(4, 3);
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        // Different strides per channel so no two channels of a pixel share a pattern.
        image.pixels[i] = {values[i % count], values[(i * 5 + 3) % count], values[(i * 7 + 11) % count]};
    }
    return image;
}

// The message of the fp::Error that `f` throws; records a test failure if it throws nothing.
template <typename F>
std::string errorMessage(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected fp::Error";
    return "";
}

}  // namespace fp::test
