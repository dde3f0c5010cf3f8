// The two ways the trace shaders read the scene (gpu/scene_textures.h): imageLoad where the context has
// GL_ARB_shader_image_load_store, texelFetch elsewhere. They read the same texels, so every integrator,
// light tracing included, must render the same image bit for bit either way; llvmpipe has the
// extension, so both paths run here and a break in either fails.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

#include "core/error.h"
#include "render_test_util.h"
#include "scene/builtin_scene.h"

namespace fp::test {
namespace {

// Sets an environment variable for one scope, restoring what was there.
class ScopedEnv {
  public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value)
            setenv(name, value, 1);
        else
            unsetenv(name);
    }
    ~ScopedEnv() {
        if (old_)
            setenv(name_, old_->c_str(), 1);
        else
            unsetenv(name_);
    }

  private:
    const char* name_;
    std::optional<std::string> old_;
};

void expectBitIdentical(const Accumulation& a, const Accumulation& b, const char* what) {
    ASSERT_EQ(a.sum.size(), b.sum.size()) << what;
    EXPECT_EQ(std::memcmp(a.sum.data(), b.sum.data(), a.sum.size() * sizeof(glm::vec4)), 0) << what;
    EXPECT_EQ(std::memcmp(a.squares.data(), b.squares.data(), a.squares.size() * sizeof(glm::vec4)), 0)
        << what;
    // Something was rendered: a broken read that returned zeros everywhere on both paths must not pass.
    EXPECT_GT(estimate(a).mean.r, 0.01f) << what;
}

TEST(SceneReads, ImageLoadAndTexelFetchRenderTheSameCornellBox) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer images(scene, ShaderLibrary(), layout::bvhOptions(), SceneReads::Images);
    Renderer fetches(scene, ShaderLibrary(), layout::bvhOptions(), SceneReads::TexelFetch);
    ASSERT_EQ(images.stats().sceneReads, SceneReads::Images);
    ASSERT_EQ(fetches.stats().sceneReads, SceneReads::TexelFetch);
    // Every integrator: bdpt adds the light-tracing pass, which reads the lights and materials too.
    for (Integrator integrator : kAllIntegrators) {
        Accumulation a = renderScene(images, *scene.camera, integrator, 24, 4, 5, 7);
        Accumulation b = renderScene(fetches, *scene.camera, integrator, 24, 4, 5, 7);
        expectBitIdentical(a, b, integratorName(integrator));
    }
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
