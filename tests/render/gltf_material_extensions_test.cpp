// glTF's material extensions (README, the material table) rendered with the real shaders:
// - KHR_materials_unlit on the Khronos UnlitTest model: each object is its flat base colour, exactly,
//   in every integrator (no shading, no noise).
// - KHR_materials_volume: an absorbing glass cube of index 1 in a white furnace shows exactly the
//   attenuation colour where the path inside is attenuationDistance long (Beer-Lambert).
// - KHR_materials_specular: the blend with a tinted coat samples as its density says (chi-square).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bsdf_test_util.h"
#include "gltf_samples.h"
#include "image/tone_map.h"
#include "render_test_util.h"
#include "scene/gltf_test_util.h"
#include "scene/load.h"
#include "scene/scene_test_util.h"

namespace fp::test {
namespace {

using json = nlohmann::json;

const Integrator kIntegrators[] = {Integrator::Nee, Integrator::Bsdf, Integrator::Bdpt, Integrator::Naive};

// UnlitTest (Khronos sample, CC-BY 4.0: ../shared/gltf-samples/UnlitTest/LICENSE.md): an orange
// (#FF7F00) and a blue (#007FFF) object whose visible surface must be one uniform colour each (the
// model's README). Seen from the front (+z, set here rather than left to the default framing), under a
// white sky, every pixel a camera sample finds only unlit surface in is the base colour exactly, with
// every integrator; a lit surface would vary with its normal. The break-check: emittedRadiance without
// its unlit case leaves the objects black and the counts at 0.
TEST(GltfMaterialExtensions, UnlitTestShowsEachObjectInItsFlatBaseColour) {
    ensureGlContext();
    Scene scene = loadScene(gltfSample("UnlitTest", "glTF-Binary", "UnlitTest.glb"));
    std::vector<glm::vec3> colours;
    for (const Material& m : scene.materials) {
        EXPECT_EQ(m.type, MaterialType::Unlit) << m.name;
        EXPECT_FALSE(m.isEmissive()) << m.name;
        colours.push_back(m.diffuse);
    }
    ASSERT_EQ(colours.size(), 2u);
    // The README's sRGB colours, within two 8-bit steps (the file's 0.2176 encodes to 128.5, not 127).
    auto encoded = [](glm::vec3 c) {
        return glm::vec3(srgbEncode(c.r), srgbEncode(c.g), srgbEncode(c.b)) * 255.0f;
    };
    const glm::vec3 orange(255, 127, 0), blue(0, 127, 255);
    auto near = [](glm::vec3 x, glm::vec3 y) {
        return glm::all(glm::lessThan(glm::abs(x - y), glm::vec3(2.0f)));
    };
    glm::vec3 a = encoded(colours[0]), b = encoded(colours[1]);
    EXPECT_TRUE((near(a, orange) && near(b, blue)) || (near(a, blue) && near(b, orange)))
        << "sRGB " << a.r << " " << a.g << " " << a.b << " and " << b.r << " " << b.g << " " << b.b;

    scene.environment = Environment{};
    scene.environment.color = glm::vec3(1.0f);
    Aabb box = scene.bounds();
    glm::vec3 centre = 0.5f * (box.lo + box.hi), extent = box.hi - box.lo;
    Camera camera;
    camera.target = centre;
    camera.eye = centre + glm::vec3(0.0f, 0.0f, 1.5f * std::max(extent.x, extent.y) + extent.z);
    camera.fovY = 45.0f;
    Renderer renderer(scene, testShaders());
    constexpr int kSize = 48;
    for (Integrator integrator : kIntegrators) {
        Image mean = renderScene(renderer, camera, integrator, kSize, 4, 5, 7).mean();
        int exact[2] = {0, 0};
        for (const glm::vec3& p : mean.pixels)
            for (int k = 0; k < 2; ++k)
                exact[k] += glm::all(glm::lessThan(glm::abs(p - colours[size_t(k)]), glm::vec3(1e-5f)));
        for (int k = 0; k < 2; ++k)
            EXPECT_GT(exact[k], kSize * kSize / 20)
                << integratorName(integrator) << ": pixels of exactly material " << k << "'s base colour";
    }
}

// An unlit surface scatters nothing: bsdfEval and bsdfPdf are 0 everywhere, bsdfSample fails (the path
// ends on it), and it counts as delta-only, so that no light sample is spent on it.
TEST(GltfMaterialExtensions, UnlitScattersNothing) {
    BsdfProbe& probe = bsdfProbe();
    probe.setMaterial(makeMaterial(MaterialType::Unlit, 0.5f));
    std::vector<EvalQuery> queries;
    for (const glm::vec3& wi : sphereLattice(256)) queries.push_back({incidentDirection(30.0f), 1.5f, wi});
    int nonZero = 0;
    for (const ProbeEval& e : probe.eval(queries)) nonZero += e.value != glm::vec3(0.0f) || e.pdf != 0.0f;
    EXPECT_EQ(nonZero, 0);
    int sampled = 0;
    for (const ProbeSample& s : probe.sample(incidentDirection(30.0f), 1.5f, 9, BsdfProbe::kWidth))
        sampled += s.ok();
    EXPECT_EQ(sampled, 0);
}

// A closed cube [-1, 1]^3, its faces counter-clockwise seen from outside, as a non-indexed primitive.
json cubePrimitive(GltfBuilder& b, int material) {
    std::vector<glm::vec3> p;
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            glm::vec3 c[4];
            const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (int i = 0; i < 4; ++i) {
                c[i][axis] = side;
                c[i][u] = corners[i][0];
                c[i][v] = corners[i][1];
            }
            for (int tri : {0, 1}) {
                glm::vec3 t[3] = {c[0], c[1 + tri], c[2 + tri]};
                if (glm::dot(glm::cross(t[1] - t[0], t[2] - t[0]), t[0]) < 0.0f) std::swap(t[1], t[2]);
                p.insert(p.end(), t, t + 3);
            }
        }
    return {{"attributes", {{"POSITION", b.vec3(p)}}}, {"material", material}};
}

// KHR_materials_volume: a smooth glass cube of index 1 (no reflection, no bending: every path goes
// straight through) with attenuationColor (0.5, 0.25, 1) at attenuationDistance 2, its side, in a white
// furnace, seen face-on from 10 away through a 4 degree field: each path crosses the cube over a length
// of 2 / cos(theta) <= 2.0013, so every pixel shows the attenuation colour within 0.1 %, in every
// integrator (the light subpaths of bdpt too). The break-check: without absorbInside in nee.glsl the
// cube is white.
TEST(GltfMaterialExtensions, VolumeAttenuatesThePathInsideTheGlassByBeerLambert) {
    ensureGlContext();
    GltfBuilder b;
    b.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume"};
    int glass = b.material({{"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.0}}},
                            {"extensions",
                             {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                              {"KHR_materials_ior", {{"ior", 1.0}}},
                              {"KHR_materials_volume",
                               {{"thicknessFactor", 2.0},
                                {"attenuationColor", {0.5, 0.25, 1.0}},
                                {"attenuationDistance", 2.0}}}}}});
    b.mesh(json::array({cubePrimitive(b, glass)}));
    b.node({{"mesh", 0}});
    b.scene({0});
    TempDir dir;
    Scene scene = loadScene(dir.write("cube.gltf", b.gltf()));
    ASSERT_EQ(scene.materials[0].type, MaterialType::Dielectric);
    scene.environment = Environment{};
    scene.environment.color = glm::vec3(1.0f);
    Camera camera;
    camera.eye = glm::vec3(0.0f, 0.0f, 10.0f);
    camera.target = glm::vec3(0.0f);
    camera.fovY = 4.0f;
    Renderer renderer(scene, testShaders());
    for (Integrator integrator : kIntegrators) {
        ImageEstimate e = estimate(renderScene(renderer, camera, integrator, 16, 4, 8, 5));
        const glm::vec3 expected(0.5f, 0.25f, 1.0f);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(e.mean[c], expected[c], 1e-3f * expected[c] + 5.0f * e.standardError[c])
                << integratorName(integrator) << ", channel " << c;
    }
}

// KHR_materials_specular on the blend (metallic 0.5): the coat tinted by the specular colour changes
// which lobe is sampled (plasticSpecularProbability weighs it), so the sampled directions are tested
// against bsdfPdf as the other models' are (bsdf_chi_square_test.cpp).
TEST(GltfMaterialExtensions, TintedCoatSamplesAsItsDensitySays) {
    BsdfProbe& probe = bsdfProbe();
    Material m = makeMetallicRoughness(0.5f, 0.3f);
    m.specularColor = glm::vec3(0.2f, 0.6f, 1.0f);
    probe.setMaterial(m);
    const double significance = 0.01 / double(incidentAngles().size());
    for (size_t a = 0; a < incidentAngles().size(); ++a) {
        const glm::vec3 wo = incidentDirection(incidentAngles()[a]);
        std::vector<ProbeSample> samples = probe.sample(wo, 1.5f, uint32_t(4100 + a), kSampleCount);
        ChiSquareResult r = chiSquareTest(probe, samples, wo, 1.5f);
        EXPECT_GT(r.pValue, significance) << "theta_o " << incidentAngles()[a] << ": chi2 " << r.statistic;
    }
}

}  // namespace
}  // namespace fp::test
