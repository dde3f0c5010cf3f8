// Instances through the two-level BVH (pack/layout.h, glsl/common/intersect.glsl): a scene whose meshes
// are stored once and placed by transforms renders as its flattened copy (scene/instancing.h
// flattenInstances, one level, every triangle in the world), image block by image block within the
// noise, with every integrator that finds surfaces differently: nee (camera, bounce and shadow rays),
// bsdf and bdpt (light subpaths hitting instances, joins to the eye).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "render_test_util.h"
#include "scene/instancing.h"
#include "scene/procedural.h"
#include "surface_maps_scene.h"

namespace fp::test {
namespace {

// A mesh made of what `build` appends to a scene.
template <class Build>
InstancedMesh meshOf(const char* name, Build build) {
    Scene scratch;
    build(scratch);
    InstancedMesh mesh;
    mesh.name = name;
    mesh.triangles = std::move(scratch.triangles);
    return mesh;
}

glm::mat4 placed(glm::vec3 at, float angle, glm::vec3 axis, glm::vec3 scale) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), at);
    m = glm::rotate(m, angle, glm::normalize(axis));
    return glm::scale(m, scale);
}

Camera viewOfTheFloor() {
    Camera c;
    c.eye = glm::vec3(0.0f, 2.2f, 3.2f);
    c.target = glm::vec3(0.0f, 0.3f, 0.0f);
    c.fovY = 50.0f;
    return c;
}

// A floor, a lamp above it and a dim sky (world triangles), and two meshes: an ellipsoid (a sphere
// squashed and turned by its transforms) placed three times, and a box placed twice.
Scene instancedScene() {
    Scene scene;
    scene.source = "instanced scene";
    scene.materials = {diffuseMaterial(0.5f), lampMaterial(glm::vec3(6.0f)), diffuseMaterial(0.8f),
                       diffuseMaterial(0.3f)};
    scene.materials[2].diffuse = glm::vec3(0.8f, 0.3f, 0.2f);
    appendQuad(scene, glm::vec3(-3, 0, 3), glm::vec3(3, 0, 3), glm::vec3(3, 0, -3), glm::vec3(-3, 0, -3), 0);
    appendQuad(scene, glm::vec3(-0.5f, 3, -0.5f), glm::vec3(0.5f, 3, -0.5f), glm::vec3(0.5f, 3, 0.5f),
               glm::vec3(-0.5f, 3, 0.5f), 1);
    scene.environment.color = glm::vec3(0.1f);
    scene.meshes.push_back(
        meshOf("ellipsoid", [](Scene& s) { appendSphere(s, glm::vec3(0.0f), 1.0f, 8, 16, 2, true); }));
    scene.meshes.push_back(
        meshOf("box", [](Scene& s) { appendBox(s, glm::vec3(-0.5f), glm::vec3(0.5f), 3); }));
    scene.instances = {{0, placed({-1.2f, 0.4f, 0.0f}, 0.6f, {0, 1, 0}, {0.5f, 0.4f, 0.3f})},
                       {0, placed({0.0f, 0.5f, -0.8f}, 1.1f, {1, 1, 0}, {0.3f, 0.5f, 0.4f})},
                       {0, placed({1.2f, 0.35f, 0.3f}, 0.0f, {0, 1, 0}, {0.35f, 0.35f, 0.35f})},
                       {1, placed({0.2f, 0.3f, 0.9f}, 0.5f, {0, 1, 0}, {0.8f, 0.6f, 0.5f})},
                       {1, placed({-0.4f, 1.2f, -0.2f}, 0.8f, {1, 0, 1}, {0.3f, 0.3f, 0.3f})}};
    return scene;
}

// What this catches: a ray not taken into the instance's space (or not back out), a hit's position or
// normals not taken back to the world, an instance's box wrong in the top level, t measured in
// different units in the two spaces (nearer world surfaces would be hidden behind instances), and
// shadow rays or light subpaths that miss instances.
TEST(InstancedRender, InstancedSceneRendersAsItsFlattenedCopy) {
    ensureGlContext();
    Scene scene = instancedScene();
    Scene flat = flattenInstances(scene);
    ASSERT_EQ(flat.triangles.size(), scene.triangleCount());
    Renderer instanced(scene, testShaders()), flattened(flat, testShaders());
    EXPECT_EQ(instanced.stats().instances, 5u);
    EXPECT_EQ(instanced.stats().storedTriangles,
              scene.triangles.size() + scene.meshes[0].triangles.size() + scene.meshes[1].triangles.size());
    EXPECT_EQ(instanced.stats().triangles, flat.triangles.size());
    for (Integrator integrator : {Integrator::Nee, Integrator::Bsdf, Integrator::Bdpt}) {
        Accumulation a = renderScene(instanced, viewOfTheFloor(), integrator, 48, 64, 4, 1);
        Accumulation b = renderScene(flattened, viewOfTheFloor(), integrator, 48, 64, 4, 2);
        expectSameImage(a, b, 8, 0.03f, std::string("instanced vs flattened, ") + integratorName(integrator));
    }
}

// A normal-mapped, single-sided quad placed twice, once turned to face away from the camera: the
// tangents of the map must be turned with the instance (a map that tilts normals toward +u would tilt
// them along the unturned u), and the back face must vanish for camera rays traced in the instance's
// space as in the world's. What this catches: tangents left in the mesh's space, the camera test made
// on the instance-space ray (whose origin is not the lens point).
TEST(InstancedRender, NormalMapsAndSingleSidedSurfacesFollowTheInstance) {
    ensureGlContext();
    Scene scene;
    scene.source = "mapped instances";
    Material mapped = diffuseMaterial(0.8f);
    mapped.normalTexture = 0;
    mapped.doubleSided = false;
    scene.materials = {diffuseMaterial(0.5f), lampMaterial(glm::vec3(6.0f)), mapped};
    // A normal leaning 45 degrees toward +u: (1, 0, 1) / sqrt(2) encoded as rgb.
    scene.textures.push_back(makeTexture("tilt", 1, 1, {218, 128, 218, 255}));
    appendQuad(scene, glm::vec3(-3, 0, 3), glm::vec3(3, 0, 3), glm::vec3(3, 0, -3), glm::vec3(-3, 0, -3), 0);
    appendQuad(scene, glm::vec3(-0.5f, 3, -0.5f), glm::vec3(0.5f, 3, -0.5f), glm::vec3(0.5f, 3, 0.5f),
               glm::vec3(-0.5f, 3, 0.5f), 1);
    scene.environment.color = glm::vec3(0.2f);
    scene.meshes.push_back(meshOf("panel", [](Scene& s) {
        appendMappedQuad(s, glm::vec3(-0.5f, -0.5f, 0), glm::vec3(0.5f, -0.5f, 0), glm::vec3(0.5f, 0.5f, 0),
                         glm::vec3(-0.5f, 0.5f, 0), 2);
    }));
    scene.instances = {{0, placed({-0.7f, 0.6f, 0.5f}, -0.9f, {1, 0.3f, 0.2f}, glm::vec3(1.1f))},
                       {0, placed({0.8f, 0.6f, 0.0f}, 3.0f, {0, 1, 0}, glm::vec3(0.9f))}};
    Scene flat = flattenInstances(scene);
    Renderer instanced(scene, testShaders()), flattened(flat, testShaders());
    for (Integrator integrator : {Integrator::Nee, Integrator::Bdpt}) {
        Accumulation a = renderScene(instanced, viewOfTheFloor(), integrator, 48, 64, 4, 3);
        Accumulation b = renderScene(flattened, viewOfTheFloor(), integrator, 48, 64, 4, 4);
        expectSameImage(a, b, 8, 0.03f,
                        std::string("mapped instances vs flattened, ") + integratorName(integrator));
    }
}

}  // namespace
}  // namespace fp::test
