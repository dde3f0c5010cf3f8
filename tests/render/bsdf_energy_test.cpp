// Energy conservation of the BSDFs of glsl/common/bsdf.glsl, run in GLSL through OSMesa (issue 4). The
// directional albedo, the integral over wi of f(wo, wi) |cos(theta_i)|, is estimated by the mean of the
// sampled weights (a failed sample counts 0): an unbiased estimate, since weight = f |cos| / pdf.
#include <gtest/gtest.h>

#include <cstdio>

#include "bsdf_test_util.h"

namespace fp::test {
namespace {

struct Albedo {
    glm::dvec3 mean{0.0}, standardError{0.0};
    double maxWeight = 0.0;  // the largest single-sample weight, over channels
};

// Transmitted weights are multiplied back by eta^2: the 1 / eta^2 of radiance transport (pbrt-v4 section
// 9.5.2) makes light entering a denser medium brighter per solid angle without making energy, so the
// conserved quantity is the albedo without it. (By generalised reciprocity, that albedo over wi is the
// fraction of the power arriving along wo that leaves: see bsdf_consistency_test.cpp.)
Albedo albedo(const std::vector<ProbeSample>& samples, float eta) {
    glm::dvec3 sum(0.0), sumSquares(0.0);
    Albedo a;
    for (const ProbeSample& s : samples) {
        if (!s.ok()) continue;
        glm::dvec3 w(s.weight);
        if (s.wi.z < 0.0f) w *= double(eta) * double(eta);
        sum += w;
        sumSquares += w * w;
        a.maxWeight = std::max({a.maxWeight, w.x, w.y, w.z});
    }
    const double n = double(samples.size());
    a.mean = sum / n;
    glm::dvec3 variance = glm::max(sumSquares / n - a.mean * a.mean, glm::dvec3(0.0));
    a.standardError = glm::sqrt(variance / n);
    return a;
}

// Every model, every incident angle, and the grazing limit: the albedo never exceeds 1 beyond five
// standard errors. Microfacet models with Fresnel <= 1 and Tf <= 1 conserve energy sample by sample:
// with visible-normal sampling the weight is F G2 / G1 <= F (Heitz & d'Eon 2014, "Importance Sampling
// Microfacet-Based BSDFs using the Distribution of Visible Normals"), since the height-correlated
// G2 = 1 / (1 + Lambda_o + Lambda_i) <= 1 / (1 + Lambda_o) = G1.
TEST(BsdfEnergy, AlbedoIsAtMostOne) {
    BsdfProbe& probe = bsdfProbe();
    std::vector<BsdfCase> cases = samplingCases();
    cases.push_back({"conductor r=0", makeMaterial(MaterialType::Conductor, 0.0f), 1.0f});
    cases.push_back({"dielectric r=0 eta=1.5", makeMaterial(MaterialType::Dielectric, 0.0f), 1.5f});
    cases.push_back({"dielectric r=0 eta=1/1.5", makeMaterial(MaterialType::Dielectric, 0.0f), 1.0f / 1.5f});
    Material whitePlastic = makeMaterial(MaterialType::Plastic, 0.6f);
    whitePlastic.diffuse = glm::vec3(1.0f);  // the worst case: a white base under a white coat
    cases.push_back({"plastic r=0.6 Kd=1", whitePlastic, 1.5f});
    for (float metallic : {0.0f, 0.5f, 1.0f}) {  // white metallic-roughness: the worst case again
        Material white = makeMetallicRoughness(metallic, 0.5f);
        white.diffuse = glm::vec3(1.0f);
        cases.push_back({"metallic-roughness m=" + std::to_string(metallic) + " r=0.5 base=1", white, 1.5f});
    }
    std::vector<float> angles = incidentAngles();
    angles.push_back(89.0f);
    for (size_t c = 0; c < cases.size(); ++c) {
        probe.setMaterial(cases[c].material);
        for (size_t a = 0; a < angles.size(); ++a) {
            const std::string what = describe(cases[c], angles[a]);
            std::vector<ProbeSample> samples =
                probe.sample(incidentDirection(angles[a]), cases[c].eta, caseSeed(c, a) + 2000, kSampleCount);
            Albedo e = albedo(samples, cases[c].eta);
            std::printf("  %-38s albedo (%.4f, %.4f, %.4f) +- %.1e  max weight %.4f\n", what.c_str(),
                        e.mean.x, e.mean.y, e.mean.z, e.standardError.x, e.maxWeight);
            for (int ch = 0; ch < 3; ++ch) {
                EXPECT_LE(e.mean[ch], 1.0 + 5.0 * e.standardError[ch] + 1e-6) << what << " channel " << ch;
            }
            MaterialType type = cases[c].material.type;
            if (type == MaterialType::Conductor || type == MaterialType::Dielectric) {
                EXPECT_LE(e.maxWeight, 1.0 + 1e-5) << what;
            }
            if (type == MaterialType::Diffuse) {  // Lambertian: exactly Kd, every sample
                EXPECT_NEAR(e.mean.x, cases[c].material.diffuse.x, 1e-6) << what;
                EXPECT_EQ(e.maxWeight, double(cases[c].material.diffuse.x)) << what;
            }
        }
    }
}

// The GGX conductor with F0 = 1 loses to single scattering only what its masking-shadowing removes,
// more at higher roughness (Kulla & Conty 2017, "Revisiting Physically Based Shading at Imageworks").
// Its albedo E(mu_o) from the shader's samples must match the integral of the same formulas computed
// here in double, within five standard errors of the Monte Carlo estimate.
TEST(BsdfEnergy, GgxConductorAlbedoMatchesNumericalIntegration) {
    BsdfProbe& probe = bsdfProbe();
    const std::vector<float> roughnesses = {0.2f, 0.4f, 0.6f, 0.8f, 1.0f};
    const std::vector<float> angles = {0.0f, 45.0f, 80.0f};
    std::vector<std::vector<double>> reference(roughnesses.size(), std::vector<double>(angles.size()));
    std::printf("  roughness  theta_o  shader E            integrated E\n");
    for (size_t r = 0; r < roughnesses.size(); ++r) {
        Material m = makeMaterial(MaterialType::Conductor, roughnesses[r]);
        m.specular = glm::vec3(1.0f);
        probe.setMaterial(m);
        const double alpha = double(roughnesses[r]) * double(roughnesses[r]);
        for (size_t a = 0; a < angles.size(); ++a) {
            const glm::vec3 wo = incidentDirection(angles[a]);
            Albedo e = albedo(probe.sample(wo, 1.0f, uint32_t(3000 + 10 * r + a), 4 * kSampleCount), 1.0f);
            reference[r][a] = ggxConductorAlbedo(double(wo.z), alpha);
            std::printf("  %9.1f  %7.0f  %.6f +- %.1e  %.6f\n", double(roughnesses[r]), double(angles[a]),
                        e.mean.x, e.standardError.x, reference[r][a]);
            // Float rounding of the shader's weights adds ~1e-6.
            EXPECT_NEAR(e.mean.x, reference[r][a], 5.0 * e.standardError.x + 1e-5)
                << "roughness " << roughnesses[r] << " theta_o " << angles[a];
            EXPECT_LT(reference[r][a], 1.0);
            if (r > 0) {
                EXPECT_LT(reference[r][a], reference[r - 1][a]) << "energy lost grows with roughness";
            }
        }
    }
    // The quadrature is converged: on a grid twice as fine, the narrowest lobes' integrals agree to far
    // less than the shader estimate's standard errors (5e-5 and more).
    EXPECT_NEAR(ggxConductorAlbedo(1.0, 0.04, 1000), reference[0][0], 1e-5);
    EXPECT_NEAR(ggxConductorAlbedo(double(incidentDirection(80.0f).z), 0.04, 1000), reference[0][2], 1e-5);
}

// What is analytic about the metallic-roughness model's albedo E(mu_o) with a white base colour (1):
// - metal (metallic 1), smooth: Schlick's Fresnel from F0 = 1 is 1 at every angle, so every sample
//   reflects with weight exactly 1: E = 1, a white non-absorbing mirror;
// - metal, rough: the GGX conductor's single-scattering albedo, below 1 by what masking-shadowing
//   removes (numerical integration of the formulas here: ggxConductorAlbedo);
// - dielectric (metallic 0), smooth: the coat reflects F(mu_o) (exact Fresnel, index 1.5), and the base
//   (albedo 1) returns (1 - F(mu_o)) times the cosine-weighted mean of 1 - F(mu_i) over the hemisphere,
//   1 - 2 int_0^1 F(mu) mu dmu, a one-dimensional integral: E = F(mu_o) + (1 - F(mu_o))(1 - 2 int F mu);
//   below 1 (light the coat reflects back inside is lost: the model has no internal reflection);
// - in between, the blend of the two: E = metallic E_metal + (1 - metallic) E_dielectric.
// The shader's mean weights must match these within five standard errors (the mirror case exactly).
TEST(BsdfEnergy, MetallicRoughnessAlbedoWhereItIsAnalytic) {
    BsdfProbe& probe = bsdfProbe();
    const double ior = 1.5;
    // 2 int_0^1 F(mu) mu dmu by the midpoint rule (F is smooth; 20000 points are exact to ~1e-9).
    double internal = 0.0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
        double mu = (k + 0.5) / n;
        internal += 2.0 * fresnelDielectricReference(mu, ior) * mu / n;
    }
    auto dielectric = [&](double mu) {
        double f = fresnelDielectricReference(mu, ior);
        return f + (1.0 - f) * (1.0 - internal);
    };
    for (size_t a = 0; a < incidentAngles().size(); ++a) {
        const glm::vec3 wo = incidentDirection(incidentAngles()[a]);
        const double mu = double(wo.z);
        struct Case {
            float metallic, roughness;
            double expected;
        };
        const Case cases[] = {{1.0f, 0.0f, 1.0},
                              {1.0f, 0.5f, ggxConductorAlbedo(mu, 0.25)},
                              {0.0f, 0.0f, dielectric(mu)},
                              {0.5f, 0.0f, 0.5 * 1.0 + 0.5 * dielectric(mu)}};
        for (const Case& c : cases) {
            Material m = makeMetallicRoughness(c.metallic, c.roughness);
            m.diffuse = glm::vec3(1.0f);
            probe.setMaterial(m);
            Albedo e = albedo(
                probe.sample(wo, 1.5f, uint32_t(5000 + 10 * a) + uint32_t(c.metallic * 7), kSampleCount),
                1.5f);
            char what[128];
            std::snprintf(what, sizeof what, "metallic %.1f roughness %.1f theta_o %.0f", double(c.metallic),
                          double(c.roughness), double(incidentAngles()[a]));
            std::printf("  %-42s albedo %.6f +- %.1e  analytic %.6f\n", what, e.mean.x, e.standardError.x,
                        c.expected);
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_NEAR(e.mean[ch], c.expected, 5.0 * e.standardError[ch] + 1e-5)
                    << what << " channel " << ch;
            if (c.metallic == 1.0f && c.roughness == 0.0f) {
                EXPECT_EQ(e.maxWeight, 1.0) << what;
                EXPECT_EQ(e.standardError.x, 0.0) << what << ": every sample weighs exactly 1";
            }
        }
    }
}

// The double-precision D and Lambda above pass Heitz's weak white furnace test: with G1 in place of G2
// the microfacet reflection integrates to 1 over the sphere, for any roughness and incident angle.
TEST(BsdfEnergy, ReferenceGgxPassesTheWeakWhiteFurnace) {
    for (double alpha : {0.04, 0.25, 0.64, 1.0})
        for (double theta : {0.0, 45.0, 80.0}) {
            EXPECT_NEAR(ggxWeakWhiteFurnace(std::cos(theta * kPi / 180.0), alpha), 1.0, 1e-5)
                << "alpha " << alpha << " theta_o " << theta;
        }
}

}  // namespace
}  // namespace fp::test
