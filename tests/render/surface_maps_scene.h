#pragma once
// Scenes with texture maps, coverage and single-sided surfaces for the GPU tests (surface_maps_test.cpp,
// scene_reads_test.cpp).
#include <string>
#include <utility>
#include <vector>

#include "render_test_util.h"

namespace fp::test {

// A texture of w x h texels given as RGBA bytes, top row first.
inline Texture makeTexture(const std::string& name, int w, int h, std::vector<uint8_t> rgba) {
    Texture t;
    t.name = name;
    t.image.width = w;
    t.image.height = h;
    t.image.texels = std::move(rgba);
    return t;
}

// The quad a b c d as appendQuad makes it, with texture coordinates (0, 0) (s, 0) (s, s) (0, s) at its
// corners: u runs along a -> b, v along b -> c.
inline void appendMappedQuad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
                             uint32_t material, float s = 1.0f) {
    size_t first = scene.triangles.size();
    appendQuad(scene, a, b, c, d, material);
    scene.triangles[first].uv = {glm::vec2(0.0f), glm::vec2(s, 0.0f), glm::vec2(s)};
    scene.triangles[first + 1].uv = {glm::vec2(0.0f), glm::vec2(s), glm::vec2(0.0f, s)};
}

// A floor with base colour, metallic-roughness and normal maps (metallic-roughness model), a plastic box
// with specular and roughness maps, a quad of BLEND coverage from an alpha map's checker, a
// single-sided quad facing away from the camera, a lamp and a dim sky: every kind of map, coverage and
// culling at once.
inline Scene everyMapScene() {
    Scene scene;
    scene.source = "every map at once";
    Material floor;
    floor.type = MaterialType::MetallicRoughness;
    floor.diffuse = glm::vec3(1.0f);
    floor.metallic = 1.0f;
    floor.roughness = 1.0f;
    floor.diffuseTexture = 0;
    floor.metallicRoughnessTexture = 1;
    floor.normalTexture = 2;
    floor.normalScale = 0.8f;
    Material box;
    box.type = MaterialType::Plastic;
    box.diffuse = glm::vec3(0.3f, 0.5f, 0.7f);
    box.specular = glm::vec3(1.0f);
    box.roughness = 1.0f;
    box.specularTexture = 3;
    box.metallicRoughnessTexture = 1;
    Material leaf;
    leaf.diffuse = glm::vec3(0.2f, 0.7f, 0.2f);
    leaf.alphaMode = AlphaMode::Blend;
    leaf.alpha = 0.9f;
    leaf.alphaTexture = 4;
    Material oneSided;
    oneSided.diffuse = glm::vec3(0.8f, 0.3f, 0.3f);
    oneSided.doubleSided = false;
    scene.materials = {floor, box, lampMaterial(glm::vec3(12.0f)), leaf, oneSided};
    scene.textures.push_back(makeTexture(
        "base", 2, 2, {230, 200, 120, 255, 90, 160, 230, 255, 90, 160, 230, 255, 230, 200, 120, 255}));
    scene.textures.push_back(
        makeTexture("mr", 2, 2, {0, 60, 255, 255, 0, 200, 0, 255, 0, 200, 0, 255, 0, 60, 255, 255}));
    scene.textures.push_back(makeTexture("normal", 2, 1, {200, 128, 230, 255, 80, 170, 235, 255}));
    scene.textures.push_back(makeTexture("specular", 1, 2, {255, 255, 255, 255, 60, 60, 60, 255}));
    scene.textures.push_back(
        makeTexture("coverage", 2, 2, {0, 0, 0, 255, 0, 0, 0, 40, 0, 0, 0, 40, 0, 0, 0, 255}));
    appendMappedQuad(scene, glm::vec3(-3.0f, 0.0f, 3.0f), glm::vec3(3.0f, 0.0f, 3.0f),
                     glm::vec3(3.0f, 0.0f, -3.0f), glm::vec3(-3.0f, 0.0f, -3.0f), 0, 3.0f);
    size_t first = scene.triangles.size();
    appendBox(scene, glm::vec3(-0.4f, 0.0f, -0.2f), glm::vec3(0.4f, 0.8f, 0.6f), 1);
    for (size_t i = first; i < scene.triangles.size(); ++i)
        scene.triangles[i].uv = {glm::vec2(0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(1.0f)};
    appendQuad(scene, glm::vec3(-1.0f, 2.5f, -1.0f), glm::vec3(1.0f, 2.5f, -1.0f),
               glm::vec3(1.0f, 2.5f, 1.0f), glm::vec3(-1.0f, 2.5f, 1.0f), 2);
    // A standing leaf left of the box, facing the camera, and a single-sided panel right of it whose
    // front faces away from the camera (seen from behind: not there; its front still shadows the floor).
    appendMappedQuad(scene, glm::vec3(-1.6f, 0.0f, 0.2f), glm::vec3(-0.7f, 0.0f, 0.2f),
                     glm::vec3(-0.7f, 1.2f, 0.2f), glm::vec3(-1.6f, 1.2f, 0.2f), 3, 4.0f);
    appendQuad(scene, glm::vec3(0.7f, 0.0f, 0.0f), glm::vec3(1.6f, 0.0f, 0.0f), glm::vec3(1.6f, 1.0f, 0.0f),
               glm::vec3(0.7f, 1.0f, 0.0f), 4);
    scene.environment.color = glm::vec3(0.1f);
    return scene;
}

inline Camera everyMapCamera() {
    Camera c;
    c.eye = glm::vec3(0.5f, 1.8f, -3.5f);
    c.target = glm::vec3(0.0f, 0.3f, 0.3f);
    c.fovY = 45.0f;
    return c;
}

}  // namespace fp::test
