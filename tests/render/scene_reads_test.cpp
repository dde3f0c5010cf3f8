// The two ways the trace shaders read the scene (gpu/scene_textures.h): imageLoad where the context has
// GL_ARB_shader_image_load_store, texelFetch elsewhere. They read the same texels, so every integrator,
// light tracing included, must render the same image bit for bit either way, on a plain scene, a
// textured one and one lit by an environment map (the optional textures are images too); llvmpipe has
// the extension, so both paths run here and a break in either fails.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

#include "core/error.h"
#include "render_test_util.h"
#include "scene/builtin_scene.h"
#include "scene/load.h"
#include "surface_maps_scene.h"

namespace fp::test {
namespace {

void expectTheSameBothWays(const Scene& scene, const Camera& camera) {
    Renderer images(scene, testShaders(), layout::bvhOptions(), SceneReads::Images);
    Renderer fetches(scene, testShaders(), layout::bvhOptions(), SceneReads::TexelFetch);
    ASSERT_EQ(images.stats().sceneReads, SceneReads::Images);
    ASSERT_EQ(fetches.stats().sceneReads, SceneReads::TexelFetch);
    // Every integrator: bdpt adds the light-tracing pass, which reads the lights and materials too.
    for (Integrator integrator : kAllIntegrators) {
        Accumulation a = renderScene(images, camera, integrator, 24, 4, 5, 7);
        Accumulation b = renderScene(fetches, camera, integrator, 24, 4, 5, 7);
        expectBitIdentical(a, b, integratorName(integrator));
    }
}

// Every kind of texture map (the tangents are an image too), coverage and single-sided surfaces.
TEST(SceneReads, ImageLoadAndTexelFetchRenderTheSameMapsAndCoverage) {
    ensureGlContext();
    expectTheSameBothWays(everyMapScene(), everyMapCamera());
}

TEST(SceneReads, ImageLoadAndTexelFetchRenderTheSameCornellBox) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    expectTheSameBothWays(scene, *scene.camera);
}

// The texture coordinates and the texture table are images too (the RGBA8 texels stay texel fetches).
TEST(SceneReads, ImageLoadAndTexelFetchRenderTheSameTexturedScene) {
    ensureGlContext();
    Scene scene = loadScene(FP_SOURCE_DIR "/assets/cornell_checker/cornell_checker.json");
    ASSERT_FALSE(scene.textures.empty());
    expectTheSameBothWays(scene, *scene.camera);
}

// The environment map (a 2D image) and its CDFs, with an emitter as well, so that light sampling
// chooses between the two.
TEST(SceneReads, ImageLoadAndTexelFetchRenderTheSameEnvironmentMap) {
    ensureGlContext();
    // Every texel different, and a bright patch that importance sampling favours.
    Image map(32, 16);
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
            map.at(x, y) = glm::vec3(0.1f + 0.02f * float(x), 0.2f + 0.03f * float(y), 0.5f) *
                           (x >= 10 && x < 13 && y >= 3 && y < 5 ? 300.0f : 1.0f);
    Scene scene = sphereUnderSky(map);
    scene.source += ", and a lamp";
    Material lamp;
    lamp.emission = glm::vec3(5.0f);
    scene.materials.push_back(lamp);
    Triangle t;
    t.p = {glm::vec3(-0.5f, 2.0f, -0.5f), glm::vec3(0.5f, 2.0f, -0.5f), glm::vec3(0.0f, 2.0f, 0.5f)};
    glm::vec3 down = glm::normalize(t.geometricNormal());
    t.n = {down, down, down};
    t.material = 1;
    ASSERT_LT(down.y, 0.0f);  // facing the sphere
    scene.triangles.push_back(t);
    scene.environment.rotationDegrees = 30.0f;
    Camera camera;
    camera.eye = glm::vec3(0.0f, 0.6f, -3.5f);
    camera.fovY = 45.0f;
    expectTheSameBothWays(scene, camera);
}

// Every texture read as an image needs its image unit, whether or not the scene has it, so a context
// with room for the five scene buffers but not the optional six reads everything with texelFetch.
TEST(SceneReads, ImagesNeedUnitsForEveryTextureReadAsAnImage) {
    // llvmpipe (Mesa 22.3)
    EXPECT_EQ(imageUnitShortfall({192, 32, 280, 8}), "");
    // Just enough: image units 0 to 11, eleven images and eight draw buffers.
    EXPECT_EQ(imageUnitShortfall({12, 11, 19, 8}), "");
    // One short of each: no unit 11 (the vertex colours), ten images, or too small a shared budget.
    EXPECT_NE(imageUnitShortfall({11, 32, 280, 8}), "");
    EXPECT_NE(imageUnitShortfall({192, 10, 280, 8}), "");
    EXPECT_NE(imageUnitShortfall({192, 32, 18, 8}), "");
    // The minimums of GL 4.2.
    EXPECT_NE(imageUnitShortfall({8, 8, 8, 8}), "");
}

TEST(SceneReads, AutoUsesImagesUnlessTheEnvironmentForcesTexelFetch) {
    ensureGlContext();
    {
        ScopedEnv unset("FRAGPATH_SCENE_READS", nullptr);
        EXPECT_EQ(resolveSceneReads(SceneReads::Auto), SceneReads::Images);
    }
    {
        ScopedEnv forced("FRAGPATH_SCENE_READS", "texelFetch");
        EXPECT_EQ(resolveSceneReads(SceneReads::Auto), SceneReads::TexelFetch);
        // An explicit request is not overridden.
        EXPECT_EQ(resolveSceneReads(SceneReads::Images), SceneReads::Images);
    }
    {
        ScopedEnv typo("FRAGPATH_SCENE_READS", "texelfetch");
        EXPECT_THROW(resolveSceneReads(SceneReads::Auto), Error);
    }
}

}  // namespace
}  // namespace fp::test
