// A compressed glTF renders as its uncompressed variant: the Khronos sample AnimatedMorphCube quantized by
// gltfpack (KHR_mesh_quantization: UNSIGNED_SHORT positions dequantized by its node, BYTE normals) against
// its float glTF-Binary, under a directional light and a dim sky, compared block by block with z-scores
// (independent seeds).
#include <gtest/gtest.h>

#include "gltf_samples.h"
#include "render_test_util.h"
#include "scene/load.h"

namespace fp::test {
namespace {

Scene litCube(const std::string& variant, const std::string& file) {
    Scene scene = loadScene(gltfSample("AnimatedMorphCube", variant, file));
    PunctualLight sun;
    sun.type = PunctualLightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.6f));
    sun.intensity = glm::vec3(2.0f);
    scene.punctualLights.push_back(sun);
    scene.environment.color = glm::vec3(0.2f);
    return scene;
}

TEST(GltfCompressedRender, QuantizedAnimatedMorphCubeRendersAsItsFloatVariant) {
    Scene quantized = litCube("glTF-Quantized", "AnimatedMorphCube.gltf");
    Scene plain = litCube("glTF-Binary", "AnimatedMorphCube.glb");
    Camera camera;  // three faces in view, each lit differently, the silhouette against the sky
    camera.eye = glm::vec3(3.0f, 2.5f, 4.0f);
    camera.target = glm::vec3(0.0f);
    camera.fovY = 35.0f;
    ensureGlContext();
    Renderer a(quantized, testShaders()), b(plain, testShaders());
    Accumulation qa = renderScene(a, camera, Integrator::Nee, 48, 64, 4, 7);
    Accumulation pb = renderScene(b, camera, Integrator::Nee, 48, 64, 4, 8);
    expectSameImage(qa, pb, 8, 0.02f, "quantized vs float AnimatedMorphCube");
}

}  // namespace
}  // namespace fp::test
