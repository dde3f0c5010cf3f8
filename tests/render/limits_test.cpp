// Scenes and images beyond what the GPU can hold are refused with a message, before any upload.
#include <gtest/gtest.h>

#include "core/error.h"
#include "gpu/scene_textures.h"
#include "pack/layout.h"
#include "render_test_util.h"

namespace fp::test {
namespace {

TEST(Limits, SceneOverTheBufferTextureLimitIsAClearError) {
    ensureGlContext();
    Scene scene = furnaceBox(0.5f, 0.0f);  // 12 triangles: 36 triangle texels, the largest buffer
    AabbArray bounds;
    for (const Triangle& t : scene.triangles) bounds.push_back(t.bounds());
    PackedScene packed = packScene(scene, buildBinnedSah(bounds));
    EXPECT_NO_THROW(SceneTextures(packed, 36));
    try {
        SceneTextures textures(packed, 35);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        std::string message = e.what();
        EXPECT_NE(message.find("scene too large for this GPU"), std::string::npos) << message;
        EXPECT_NE(message.find("GL_MAX_TEXTURE_BUFFER_SIZE is 35"), std::string::npos) << message;
        EXPECT_NE(message.find("12 triangles"), std::string::npos) << message;
    }
}

TEST(Limits, BvhNodesOverTheBufferTextureLimitAreAClearError) {
    // One triangle: 3 triangle texels, but one BVH node of pack/quantised_node.h's 4 texels.
    ensureGlContext();
    Scene scene = furnaceBox(0.5f, 1.0f);
    scene.triangles.resize(1);
    AabbArray bounds = {scene.triangles[0].bounds()};
    PackedScene packed = packScene(scene, buildBinnedSah(bounds));
    ASSERT_EQ(packed.nodes.size(), size_t(layout::kNodeTexels));
    EXPECT_NO_THROW(SceneTextures(packed, size_t(layout::kMaterialTexels)));  // the one material's
    try {
        SceneTextures textures(packed, 3);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        std::string message = e.what();
        EXPECT_NE(message.find("BVH nodes buffer needs 4 texels"), std::string::npos) << message;
        EXPECT_NE(message.find("GL_MAX_TEXTURE_BUFFER_SIZE is 3"), std::string::npos) << message;
    }
}

TEST(Limits, ImageLargerThanTheTextureLimitIsAClearError) {
    ensureGlContext();
    Renderer renderer(furnaceBox(0.5f, 1.0f), testShaders());
    RenderSettings settings;
    settings.width = 100000;
    settings.height = 4;
    EXPECT_THROW(renderer.configure(settings, insideCamera()), Error);
    settings.width = 4;
    EXPECT_NO_THROW(renderer.configure(settings, insideCamera()));
}

}  // namespace
}  // namespace fp::test
