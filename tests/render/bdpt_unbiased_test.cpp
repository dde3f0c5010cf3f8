// bdpt against nee where the light subpaths' own bookkeeping matters (issue 15): an odd number of
// refractions through rough glass on one side of the join (the radiance scaling by the relative index
// does not cancel, as it does through a sphere), dispersion, an environment map beside an emitter, and
// shading normals that differ strongly from the facets. nee and bdpt share the BSDFs but not the
// light subpath's weights, so agreeing images, block by block, check those.
#include <gtest/gtest.h>

#include "render_test_util.h"

namespace fp::test {
namespace {

Material diffuseMaterial(float albedo) {
    Material m;
    m.diffuse = glm::vec3(albedo);
    return m;
}

Material lampMaterial(float radiance) {
    Material m;
    m.name = "lamp";
    m.diffuse = glm::vec3(0.0f);
    m.emission = glm::vec3(radiance);
    return m;
}

Material roughGlass(float roughness, float abbe = 0.0f) {
    Material m;
    m.name = "glass";
    m.type = MaterialType::Dielectric;
    m.roughness = roughness;
    m.ior = 1.5f;
    m.abbeNumber = abbe;
    return m;
}

Camera lookAt(glm::vec3 eye, glm::vec3 target, float fov) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.fovY = fov;
    return c;
}

void expectBdptMatchesNee(const Scene& scene, const Camera& camera, int bdptSpp, int neeSpp, float sharpness,
                          const std::string& what) {
    Renderer renderer(scene, testShaders());
    Accumulation bdpt = renderScene(renderer, camera, Integrator::Bdpt, 24, bdptSpp, 5, 1);
    Accumulation nee = renderScene(renderer, camera, Integrator::Nee, 24, neeSpp, 5, 2);
    expectSameImage(bdpt, nee, 3, sharpness, what);
}

// A lamp inside a block of rough glass above a diffuse floor: every light subpath refracts once (out of
// the glass) before it reaches the floor, which light tracing and the s >= 2 joins then use.
TEST(BdptUnbiased, LampInsideRoughGlassMatchesNee) {
    ensureGlContext();
    Scene scene;
    scene.source = "lamp inside rough glass";
    scene.materials = {diffuseMaterial(0.6f), roughGlass(0.3f), lampMaterial(30.0f)};
    appendQuad(scene, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, 0);
    appendBox(scene, {-0.6f, 1.0f, -0.6f}, {0.6f, 2.0f, 0.6f}, 1);
    appendQuad(scene, {-0.2f, 1.8f, -0.2f}, {0.2f, 1.8f, -0.2f}, {0.2f, 1.8f, 0.2f}, {-0.2f, 1.8f, 0.2f}, 2);
    expectBdptMatchesNee(scene, lookAt({0.4f, 1.2f, -3.2f}, {0.0f, 0.5f, 0.0f}, 50.0f), 256, 512, 0.03f,
                         "lamp inside rough glass");
}

// A diffuse floor inside a slab of rough glass, the lamp outside above it: light reaches the floor
// through one refraction, and the floor reaches the camera through one.
TEST(BdptUnbiased, FloorInsideRoughGlassMatchesNee) {
    ensureGlContext();
    Scene scene;
    scene.source = "floor inside rough glass";
    scene.materials = {diffuseMaterial(0.6f), roughGlass(0.3f), lampMaterial(20.0f)};
    appendBox(scene, {-1.0f, 0.0f, -1.0f}, {1.0f, 0.6f, 1.0f}, 1);
    appendQuad(scene, {-0.8f, 0.2f, -0.8f}, {-0.8f, 0.2f, 0.8f}, {0.8f, 0.2f, 0.8f}, {0.8f, 0.2f, -0.8f}, 0);
    appendQuad(scene, {-0.3f, 2.2f, -0.3f}, {0.3f, 2.2f, -0.3f}, {0.3f, 2.2f, 0.3f}, {-0.3f, 2.2f, 0.3f}, 2);
    expectBdptMatchesNee(scene, lookAt({0.3f, 1.6f, -2.4f}, {0.0f, 0.2f, 0.0f}, 45.0f), 512, 2048, 0.03f,
                         "floor inside rough glass");
}

// The caustic scene with a rough dispersive glass sphere (Abbe number 20): one wavelength per sample,
// drawn by whichever subpath meets the glass first, and its spectral weight on the joins.
TEST(BdptUnbiased, RoughDispersiveGlassMatchesNee) {
    ensureGlContext();
    Scene scene = causticScene(0.3f);
    scene.materials[1].abbeNumber = 20.0f;
    expectBdptMatchesNee(scene, *scene.camera, 256, 1024, 0.03f, "rough dispersive glass sphere");
}

// An environment map beside an emitter: bdpt finds the map only by camera subpaths that escape
// (s = 0, weight 1), and must not count those paths by any other strategy.
TEST(BdptUnbiased, EnvironmentMapAndALampMatchesNee) {
    ensureGlContext();
    Scene scene;
    scene.source = "map and lamp";
    scene.materials = {diffuseMaterial(0.5f), lampMaterial(8.0f)};
    appendQuad(scene, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, 0);
    appendQuad(scene, {-0.3f, 1.5f, -0.3f}, {0.3f, 1.5f, -0.3f}, {0.3f, 1.5f, 0.3f}, {-0.3f, 1.5f, 0.3f}, 1);
    appendBox(scene, {0.3f, 0.0f, -0.2f}, {0.8f, 0.5f, 0.3f}, 0);
    Image map(32, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x)
            map.at(x, y) = glm::vec3(0.2f, 0.3f, 0.5f) * (y < 8 ? 1.0f : 0.2f) * (x < 16 ? 1.0f : 2.0f);
    scene.environment.map = map;
    scene.environment.rotationDegrees = 30.0f;
    expectBdptMatchesNee(scene, lookAt({0.5f, 1.2f, -3.0f}, {0.0f, 0.3f, 0.0f}, 55.0f), 512, 1024, 0.03f,
                         "environment map and a lamp");
}

// Coarse smooth-shaded spheres (5 rings x 8 segments: shading normals up to about 25 degrees from the
// facets), one diffuse and one rough metal, on a floor under a lamp: the adjoint shading-normal
// correction of light subpaths, and the vertices where a direction is on different sides of the
// shading and geometric normals.
TEST(BdptUnbiased, SmoothShadedSpheresMatchNee) {
    ensureGlContext();
    Scene scene;
    scene.source = "smooth-shaded spheres";
    Material metal;
    metal.type = MaterialType::Conductor;
    metal.specular = glm::vec3(0.9f);
    metal.roughness = 0.4f;
    scene.materials = {diffuseMaterial(0.6f), lampMaterial(10.0f), diffuseMaterial(0.8f), metal};
    appendQuad(scene, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, 0);
    appendQuad(scene, {-0.4f, 2.0f, -0.4f}, {0.4f, 2.0f, -0.4f}, {0.4f, 2.0f, 0.4f}, {-0.4f, 2.0f, 0.4f}, 1);
    appendSphere(scene, {-0.55f, 0.5f, 0.0f}, 0.5f, 5, 8, 2, true);
    appendSphere(scene, {0.55f, 0.5f, 0.0f}, 0.5f, 5, 8, 3, true);
    expectBdptMatchesNee(scene, lookAt({0.0f, 1.3f, -2.6f}, {0.0f, 0.4f, 0.0f}, 50.0f), 256, 512, 0.03f,
                         "smooth-shaded spheres");
}

}  // namespace
}  // namespace fp::test
