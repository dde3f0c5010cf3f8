// glTF's metallic-roughness model (MaterialType::MetallicRoughness, glsl/common/bsdf.glsl) at its two
// ends is exactly the models it blends: metallic 1 the GGX conductor with F0 = the base colour, metallic
// 0 the plastic with a coat of the same index over the base colour, white or tinted by its specular
// colour (KHR_materials_specular) as the plastic's Ks tints it. Checked bit for bit, in the
// BSDF functions through the probe and in whole renders with every integrator (whose shaders are
// compiled for different material types: MATERIAL_TYPES). The blend in between is tested with the other
// models (chi-square, formulas, weights, reciprocity, energy: bsdf_*_test.cpp).
#include <gtest/gtest.h>

#include <cstring>

#include "bsdf_test_util.h"

namespace fp::test {
namespace {

// The material metallic-roughness is at an end: the conductor or the plastic.
Material endpointModel(const Material& mr) {
    Material m = mr;
    m.metallic = 0.0f;
    if (mr.metallic >= 1.0f) {
        m.type = MaterialType::Conductor;
        m.specular = mr.diffuse;
        m.diffuse = glm::vec3(0.8f);  // unused by the conductor: anything
    } else {
        m.type = MaterialType::Plastic;
        m.specular = mr.specularColor;
        m.specularColor = glm::vec3(1.0f);
    }
    return m;
}

// Metallic-roughness materials at an end, with every coat tint tested: white (glTF's plain model) and
// one that KHR_materials_specular gives.
std::vector<Material> endpointMaterials(float metallic, float roughness) {
    Material white = makeMetallicRoughness(metallic, roughness), tinted = white;
    tinted.specularColor = glm::vec3(0.5f, 0.25f, 1.0f);
    return metallic >= 1.0f ? std::vector<Material>{white} : std::vector<Material>{white, tinted};
}

std::vector<EvalQuery> evalPairs() {
    std::vector<EvalQuery> queries;
    for (float angle : {0.0f, 30.0f, 60.0f, 85.0f})
        for (const glm::vec3& wi : sphereLattice(1024))
            queries.push_back({incidentDirection(angle), 1.5f, wi});
    return queries;
}

bool sameBits(const void* a, const void* b, size_t size) {
    return std::memcmp(a, b, size) == 0;
}

// bsdfEval, bsdfPdf and bsdfSample (direction, density, weight, delta flag) give the same bits for
// metallic 1 as the conductor and for metallic 0 as the plastic, smooth and rough. What this catches: a
// blend that is not exactly the model at its ends (a lobe weighted 0 that still adds a rounding or a
// NaN, a lobe chosen with a probability other than 0 or 1, a coat that is not white or not tinted by the
// specular colour, a base colour that is not the conductor's F0).
TEST(MetallicRoughness, EndpointsAreTheConductorAndThePlasticBitForBit) {
    BsdfProbe& probe = bsdfProbe();
    const std::vector<EvalQuery> queries = evalPairs();
    for (float metallic : {1.0f, 0.0f})
        for (float roughness : {0.0f, 0.3f, 0.8f})
            for (const Material& mr : endpointMaterials(metallic, roughness)) {
                const Material other = endpointModel(mr);
                const std::string what = "metallic " + std::to_string(metallic) + " roughness " +
                                         std::to_string(roughness) + " coat " +
                                         std::to_string(mr.specularColor.g);
                probe.setMaterial(mr);
                std::vector<ProbeEval> a = probe.eval(queries);
                probe.setMaterial(other);
                std::vector<ProbeEval> b = probe.eval(queries);
                int differ = 0, nonZero = 0;
                for (size_t k = 0; k < a.size(); ++k) {
                    differ += !sameBits(&a[k].value, &b[k].value, sizeof(glm::vec3)) ||
                              !sameBits(&a[k].pdf, &b[k].pdf, 4);
                    nonZero += a[k].value.x > 0.0f;
                }
                EXPECT_EQ(differ, 0) << what << ": bsdfEval or bsdfPdf";
                if (roughness > 0.0f || metallic < 1.0f) {  // (a smooth metal is a delta lobe: 0 everywhere)
                    EXPECT_GT(nonZero, int(queries.size() / 8)) << what;
                }
                for (float angle : incidentAngles()) {
                    const glm::vec3 wo = incidentDirection(angle);
                    probe.setMaterial(mr);
                    std::vector<ProbeSample> sa = probe.sample(wo, 1.5f, 77, BsdfProbe::kWidth * 16);
                    probe.setMaterial(other);
                    std::vector<ProbeSample> sb = probe.sample(wo, 1.5f, 77, BsdfProbe::kWidth * 16);
                    int different = 0, ok = 0;
                    for (size_t k = 0; k < sa.size(); ++k) {
                        different += !sameBits(&sa[k].wi, &sb[k].wi, sizeof(glm::vec3)) ||
                                     !sameBits(&sa[k].pdf, &sb[k].pdf, 4) ||
                                     !sameBits(&sa[k].weight, &sb[k].weight, sizeof(glm::vec3)) ||
                                     sa[k].flag != sb[k].flag;
                        ok += sa[k].ok();
                    }
                    EXPECT_EQ(different, 0) << what << " theta_o " << angle << ": bsdfSample";
                    EXPECT_GT(ok, int(sa.size() / 2)) << what;
                }
            }
}

// Whole renders: a metallic-roughness material at metallic 1 (0) renders the same image, bit for bit,
// as the conductor (plastic) it equals, with every integrator. Plain, the packer packs it as that model
// (shaderMaterial: fewer shader lines); with a metallic-roughness map of white texels (factors times 1)
// it stays the blend, whose shader code then runs at its ends, compiled beside only what the scene
// has (MATERIAL_TYPES). What this catches: everything the probe test does, and an integrator that
// treats the new type differently (a delta test that misses a smooth metal, a bdpt vertex that loses
// its metallic factor, a lobe choice that uses a different random number), or a packed shortcut that
// is not the same model.
TEST(MetallicRoughness, EndpointsRenderTheSameImagesAsTheConductorAndThePlastic) {
    ensureGlContext();
    for (bool mapped : {false, true})
        for (float metallic : {1.0f, 0.0f})
            for (float roughness : {0.0f, 0.4f})
                for (const Material& mr : endpointMaterials(metallic, roughness)) {
                    Scene a = sphereOnAFloor(mr), b = sphereOnAFloor(endpointModel(mr));
                    if (mapped) {
                        a.materials[0].metallicRoughnessTexture = 0;
                        Texture white;
                        white.name = "white";
                        white.image.width = white.image.height = 1;
                        white.image.texels = {0, 255, 255, 255};
                        a.textures.push_back(white);
                    }
                    EXPECT_EQ(shaderMaterial(a.materials[0]).type,
                              mapped ? MaterialType::MetallicRoughness : b.materials[0].type);
                    Renderer ra(a, testShaders()), rb(b, testShaders());
                    for (Integrator integrator :
                         {Integrator::Nee, Integrator::Bsdf, Integrator::Bdpt, Integrator::Naive}) {
                        std::string what = std::string(integratorName(integrator)) + ", metallic " +
                                           std::to_string(metallic) + ", roughness " +
                                           std::to_string(roughness) + ", coat " +
                                           std::to_string(mr.specularColor.g) + (mapped ? ", mapped" : "");
                        Accumulation ia = renderScene(ra, sphereCamera(), integrator, 32, 8, 4, 3);
                        Accumulation ib = renderScene(rb, sphereCamera(), integrator, 32, 8, 4, 3);
                        expectBitIdentical(ia, ib, what.c_str());
                    }
                }
}

}  // namespace
}  // namespace fp::test
