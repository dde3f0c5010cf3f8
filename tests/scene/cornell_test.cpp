// The Cornell box asset, through the file loaders and through the built-in (embedded) copy.
#include <gtest/gtest.h>

#include "scene/builtin_scene.h"
#include "scene/load.h"
#include "scene_test_util.h"

namespace fp {
namespace {

const std::string kCornellJson = FP_SOURCE_DIR "/assets/cornell/cornell.json";
const std::string kCornellObj = FP_SOURCE_DIR "/assets/cornell/cornell.obj";

const Material& materialOf(const Scene& scene, const Triangle& t) {
    return scene.materials.at(t.material);
}

TEST(CornellAsset, ObjLoadsWithoutWarnings) {
    WarningCapture capture;
    Scene scene = loadObj(kCornellObj);
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    // 6 room quads (floor, light, ceiling, 3 walls) + 2 blocks x 5 quads = 16 quads.
    EXPECT_EQ(scene.triangles.size(), 32u);
    ASSERT_EQ(scene.materials.size(), 4u);
    EXPECT_EQ(scene.materials[0].name, "white");
    EXPECT_EQ(scene.materials[1].name, "red");
    EXPECT_EQ(scene.materials[2].name, "green");
    EXPECT_EQ(scene.materials[3].name, "light");
    EXPECT_FALSE(scene.camera.has_value());
    EXPECT_EQ(scene.source, kCornellObj);
}

TEST(CornellAsset, MaterialsMatchTheMtl) {
    Scene scene = loadObj(kCornellObj);
    const Material& light = scene.materials.at(3);
    EXPECT_EQ(light.emission, glm::vec3(17.0f, 12.0f, 4.0f));
    EXPECT_EQ(light.diffuse, glm::vec3(0.78f));
    EXPECT_TRUE(light.isEmissive());
    EXPECT_EQ(scene.materials[0].diffuse, glm::vec3(0.73f));
    EXPECT_EQ(scene.materials[1].diffuse, glm::vec3(0.63f, 0.065f, 0.05f));
    EXPECT_EQ(scene.materials[2].diffuse, glm::vec3(0.14f, 0.45f, 0.091f));
    for (int i = 0; i < 3; ++i) EXPECT_FALSE(scene.materials[static_cast<size_t>(i)].isEmissive());

    size_t lightTriangles = 0;
    float lightArea = 0.0f;
    for (const Triangle& t : scene.triangles) {
        if (materialOf(scene, t).name != "light") continue;
        ++lightTriangles;
        lightArea += t.area();
    }
    EXPECT_EQ(lightTriangles, 2u);
    EXPECT_NEAR(lightArea, 130.0f * 105.0f, 0.5f);
}

TEST(CornellAsset, NormalsFollowTheWinding) {
    Scene scene = loadObj(kCornellObj);
    const glm::vec3 roomCenter(278.0f, 274.4f, 279.6f);
    for (size_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& t = scene.triangles[i];
        glm::vec3 geometric = glm::normalize(t.geometricNormal());
        for (const glm::vec3& n : t.n) {
            EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f) << "triangle " << i;
            EXPECT_GT(glm::dot(n, geometric), 0.9999f) << "triangle " << i;  // no normals in the file
        }
        // The room (first 12 triangles) is wound to face inwards; the blocks (the rest) outwards.
        glm::vec3 centroid = (t.p[0] + t.p[1] + t.p[2]) / 3.0f;
        float towardCenter = glm::dot(geometric, roomCenter - centroid);
        if (i < 12) {
            EXPECT_GT(towardCenter, 0.0f) << "room triangle " << i;
        }
    }
    // Spot checks: the floor faces up, the light down into the room.
    EXPECT_GT(scene.triangles[0].n[0].y, 0.999f);
    EXPECT_LT(scene.triangles[2].n[0].y, -0.999f);
    EXPECT_EQ(materialOf(scene, scene.triangles[2]).name, "light");
    // Both blocks' tops face up and each block's sides face away from its own centre.
    for (size_t block = 0; block < 2; ++block) {
        glm::vec3 center(0.0f);
        for (size_t i = 12 + block * 10; i < 22 + block * 10; ++i)
            for (const glm::vec3& p : scene.triangles[i].p) center += p / 30.0f;
        for (size_t i = 12 + block * 10; i < 22 + block * 10; ++i) {
            const Triangle& t = scene.triangles[i];
            glm::vec3 centroid = (t.p[0] + t.p[1] + t.p[2]) / 3.0f;
            EXPECT_GT(glm::dot(t.geometricNormal(), centroid - center), 0.0f) << "block triangle " << i;
        }
    }
}

TEST(CornellAsset, SceneFileGivesCameraAndRenderDefaults) {
    WarningCapture capture;
    Scene scene = loadScene(kCornellJson);
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    EXPECT_EQ(scene.triangles.size(), 32u);
    EXPECT_EQ(scene.materials.size(), 4u);
    ASSERT_TRUE(scene.camera.has_value());
    EXPECT_EQ(scene.camera->eye, glm::vec3(278.0f, 273.0f, -800.0f));
    EXPECT_EQ(scene.camera->target, glm::vec3(278.0f, 273.0f, 0.0f));
    EXPECT_EQ(scene.camera->up, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_FLOAT_EQ(scene.camera->fovY, 39.3f);
    EXPECT_EQ(scene.fileSettings.get("width"), 512);
    EXPECT_EQ(scene.fileSettings.get("height"), 512);
    EXPECT_EQ(scene.fileSettings.get("spp"), 64);
    EXPECT_EQ(scene.fileSettings.get("max_depth"), 5);
    EXPECT_FALSE(scene.fileSettings.get("seed").has_value());
    EXPECT_FALSE(scene.fileSettings.get("integrator").has_value());
    EXPECT_EQ(scene.source, kCornellJson);
}

TEST(CornellAsset, BuiltinEqualsTheAssetFiles) {
    Scene files = loadScene(kCornellJson);
    WarningCapture capture;
    Scene builtin = builtinCornellBox();
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);

    ASSERT_EQ(builtin.triangles.size(), files.triangles.size());
    for (size_t i = 0; i < files.triangles.size(); ++i) {
        const Triangle &a = builtin.triangles[i], &b = files.triangles[i];
        EXPECT_EQ(a.p, b.p) << "triangle " << i;
        EXPECT_EQ(a.n, b.n) << "triangle " << i;
        EXPECT_EQ(a.material, b.material) << "triangle " << i;
    }
    ASSERT_EQ(builtin.materials.size(), files.materials.size());
    for (size_t i = 0; i < files.materials.size(); ++i) {
        EXPECT_EQ(builtin.materials[i].name, files.materials[i].name);
        EXPECT_EQ(builtin.materials[i].diffuse, files.materials[i].diffuse);
        EXPECT_EQ(builtin.materials[i].emission, files.materials[i].emission);
    }
    ASSERT_TRUE(builtin.camera.has_value());
    EXPECT_EQ(builtin.camera->eye, files.camera->eye);
    EXPECT_EQ(builtin.camera->target, files.camera->target);
    EXPECT_EQ(builtin.camera->up, files.camera->up);
    EXPECT_EQ(builtin.camera->fovY, files.camera->fovY);
    EXPECT_EQ(builtin.fileSettings.get("width"), files.fileSettings.get("width"));
    EXPECT_EQ(builtin.fileSettings.get("height"), files.fileSettings.get("height"));
    EXPECT_EQ(builtin.fileSettings.get("spp"), files.fileSettings.get("spp"));
    EXPECT_EQ(builtin.fileSettings.get("max_depth"), files.fileSettings.get("max_depth"));
    EXPECT_FALSE(builtin.source.empty());
}

TEST(CornellAsset, EmbeddedFilesAreTheAssets) {
    const auto& files = embeddedCornellBox();
    EXPECT_EQ(files.size(), 3u);
    for (const char* name : {"cornell.obj", "cornell.mtl", "cornell.json"})
        EXPECT_EQ(files.count(name), 1u) << name;
}

}  // namespace
}  // namespace fp
