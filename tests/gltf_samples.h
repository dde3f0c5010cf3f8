#pragma once
// The Khronos Group's glTF sample models that ../shared/gltf-samples holds beside the checkout (CC0 and
// CC-BY 4.0: the credits are in ../shared/gltf-samples/README.md and each model's LICENSE.md). Tests of
// real files read them through this one function, so a missing folder fails the test with its path
// instead of skipping it.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace fp::test {

// ../shared/gltf-samples/NAME/VARIANT/FILE, e.g. gltfSample("TwoSidedPlane", "glTF", "TwoSidedPlane.gltf").
inline std::string gltfSample(const std::string& name, const std::string& variant, const std::string& file) {
    std::filesystem::path path =
        std::filesystem::path(FP_SOURCE_DIR) / ".." / "shared" / "gltf-samples" / name / variant / file;
    path = path.lexically_normal();
    EXPECT_TRUE(std::filesystem::is_regular_file(path))
        << path << " is missing: the Khronos samples live in ../shared/gltf-samples beside the checkout";
    return path.string();
}

}  // namespace fp::test
