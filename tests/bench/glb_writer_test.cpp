// bench/glb_writer.h: a scene written as a .glb reads back through the glTF loader (a separate parser)
// as the same triangles and materials.
#include <gtest/gtest.h>

#include "../image/test_files.h"
#include "bench/glb_writer.h"
#include "scene/load.h"
#include "scene/procedural.h"

namespace fp::bench {
namespace {

TEST(GlbWriter, SceneReadsBackAsTheSameTrianglesAndMaterials) {
    Scene scene = benchmarkSphereScene(1000);  // a sphere, a floor and walls, and a lamp (Ke above 1)
    test::TempDir dir;
    std::string path = dir.file("sphere.glb");
    writeGlb(scene, path);
    Scene loaded = loadScene(path);
    ASSERT_EQ(loaded.triangles.size(), scene.triangles.size());
    // Written one primitive per material, in the order of the materials' indices, keeping each one's
    // triangles in order: the same order when the scene's triangles are grouped by material already.
    std::vector<size_t> order(scene.triangles.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return scene.triangles[a].material < scene.triangles[b].material;
    });
    for (size_t i = 0; i < order.size(); ++i) {
        const Triangle &a = scene.triangles[order[i]], &b = loaded.triangles[i];
        for (int c = 0; c < 3; ++c) {
            ASSERT_EQ(a.p[c], b.p[c]) << "triangle " << i << " corner " << c;
            for (int k = 0; k < 3; ++k)  // the loader normalises normals again: within a rounding
                ASSERT_NEAR(a.n[c][k], b.n[c][k], 1e-6f) << "triangle " << i << " corner " << c;
        }
        const Material &ma = scene.materials[a.material], &mb = loaded.materials[b.material];
        ASSERT_EQ(mb.type, MaterialType::MetallicRoughness);
        ASSERT_EQ(mb.metallic, 0.0f);
        ASSERT_EQ(mb.roughness, 1.0f);
        ASSERT_TRUE(mb.doubleSided);
        ASSERT_EQ(mb.diffuse, ma.diffuse);
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(mb.emission[k], ma.emission[k], 1e-6f * ma.emission[k]);
    }
    bool emits = false;
    for (const Material& m : loaded.materials) emits = emits || m.isEmissive();
    EXPECT_TRUE(emits) << "the lamp's emission, above 1, through KHR_materials_emissive_strength";
}

}  // namespace
}  // namespace fp::bench
