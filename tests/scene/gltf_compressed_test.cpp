// Compressed glTF meshes load to the triangles of their uncompressed originals:
// - KHR_mesh_quantization: the Khronos sample AnimatedMorphCube, quantized by gltfpack (BYTE normals,
//   UNSIGNED_SHORT positions dequantized by its node's scale and translation), against its float
//   glTF-Binary variant.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gltf_samples.h"
#include "gltf_test_util.h"
#include "scene/load.h"
#include "scene_test_util.h"

namespace fp {
namespace {

using json = nlohmann::json;

float maxDistance(const glm::vec3& a, const glm::vec3& b) {
    glm::vec3 d = glm::abs(a - b);
    return std::max({d.x, d.y, d.z});
}

// Whether triangle `t` has the corners of `u` within `tolerance` (per coordinate), in the same winding
// (any of its three rotations).
bool sameTriangle(const Triangle& t, const Triangle& u, float tolerance) {
    for (int r = 0; r < 3; ++r) {
        bool all = true;
        for (int k = 0; k < 3; ++k)
            all = all && maxDistance(t.p[size_t(k)], u.p[size_t((k + r) % 3)]) <= tolerance;
        if (all) return true;
    }
    return false;
}

// Every triangle of `a` is one of `b` (as many of each), within `tolerance`; the triangles' order may
// differ (compressors reorder them).
void expectSameTriangles(const Scene& a, const Scene& b, float tolerance) {
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    std::vector<bool> used(b.triangles.size(), false);
    for (size_t i = 0; i < a.triangles.size(); ++i) {
        bool found = false;
        for (size_t j = 0; j < b.triangles.size() && !found; ++j)
            if (!used[j] && sameTriangle(a.triangles[i], b.triangles[j], tolerance)) found = used[j] = true;
        EXPECT_TRUE(found) << "triangle " << i << " (" << a.triangles[i].p[0].x << ", "
                           << a.triangles[i].p[0].y << ", " << a.triangles[i].p[0].z
                           << ") ... has no counterpart";
    }
}

TEST(GltfQuantized, AnimatedMorphCubeLoadsAsItsFloatVariant) {
    Scene quantized =
        loadScene(test::gltfSample("AnimatedMorphCube", "glTF-Quantized", "AnimatedMorphCube.gltf"));
    Scene plain = loadScene(test::gltfSample("AnimatedMorphCube", "glTF-Binary", "AnimatedMorphCube.glb"));
    // The positions' quantization step in world units: UNSIGNED_SHORT steps times the node's scale
    // (3.64900689e-06) times its parent's (100); rounding is within half a step.
    const float step = 3.64900689e-06f * 100.0f;
    Aabb q = quantized.bounds(), p = plain.bounds();
    EXPECT_LE(maxDistance(q.lo, p.lo), step) << "quantized bounds differ from the float file's";
    EXPECT_LE(maxDistance(q.hi, p.hi), step);
    EXPECT_GT(maxDistance(p.lo, p.hi), 1000.0f * step);  // the cube spans many steps
    expectSameTriangles(quantized, plain, step);
    // Normals from normalized BYTEs (steps of 1/127), renormalized after the node's transform.
    for (const Triangle& t : quantized.triangles) {
        glm::vec3 geometric = glm::normalize(t.geometricNormal());
        for (const glm::vec3& n : t.n) {
            EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
            EXPECT_GT(glm::dot(n, geometric), 0.999f) << "a cube's normals are its faces'";
        }
    }
}

}  // namespace
}  // namespace fp
