// On a software renderer the scene's large arrays become the GPU buffers' storage in place
// (GL_AMD_pinned_memory, gpu/scene_textures.h) instead of being copied into fresh memory. The shaders then
// read the packer's arrays, which the scene textures keep alive, and must render what the copies render,
// bit for bit.
#include <gtest/gtest.h>

#include "gpu/scene_textures.h"
#include "render_test_util.h"

namespace fp::test {
namespace {

TEST(PinnedUpload, LargeArraysAreReadInPlaceAndRenderWhatCopiesRender) {
    ensureGlContext();
    ASSERT_TRUE(pinnedUploadAllowed()) << "llvmpipe offers GL_AMD_pinned_memory";
    // 50,000 triangles: the triangle and normal arrays (2.4 MB each) are HugePageVector blocks, which
    // start on 2 MiB boundaries; the materials and lights, a few hundred bytes, are copied.
    const Scene scene = benchmarkSphereScene(50000);
    const size_t perTriangleArray = size_t(50000) * 3 * sizeof(glm::vec4);
    Renderer pinned(scene, testShaders());
    EXPECT_GE(pinned.stats().gpuPinnedBytes, 2 * perTriangleArray);
    EXPECT_LT(pinned.stats().gpuPinnedBytes, pinned.stats().gpuBytes);
    const Accumulation a = renderScene(pinned, *scene.camera, Integrator::Nee, 24, 4, 5, 7);

    ScopedEnv copies("FRAGPATH_PINNED_UPLOAD", "0");
    ASSERT_FALSE(pinnedUploadAllowed());
    Renderer copied(scene, testShaders());
    EXPECT_EQ(copied.stats().gpuPinnedBytes, 0u);
    const Accumulation b = renderScene(copied, *scene.camera, Integrator::Nee, 24, 4, 5, 7);
    expectBitIdentical(a, b, "pinned against copied buffers");
}

}  // namespace
}  // namespace fp::test
