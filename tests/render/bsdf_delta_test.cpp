// The delta lobes of glsl/common/bsdf.glsl (roughness below kSmooth), run in GLSL through OSMesa: no
// density can describe them, so the chi-square tests skip them; instead every sample is checked
// against the law of reflection, Snell's law and the Fresnel equations, computed here in double.
#include <gtest/gtest.h>

#include "bsdf_test_util.h"

namespace fp::test {
namespace {

constexpr int kCount = BsdfProbe::kWidth * 64;
const std::vector<float> kAngles = {0.0f, 30.0f, 45.0f, 60.0f, 80.0f, 89.0f};

// The direction of specular reflection: wo mirrored about the normal.
glm::vec3 specularReflection(glm::vec3 wo) {
    return glm::vec3(-wo.x, -wo.y, wo.z);
}

bool near(glm::vec3 a, glm::vec3 b, float tolerance) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(tolerance)));
}

// A delta lobe is invisible to bsdfEval and bsdfPdf: light sampling must never find it.
void expectNothingOutsideTheDelta(BsdfProbe& probe, glm::vec3 wo, float eta, const std::string& what) {
    std::vector<EvalQuery> queries;
    for (const glm::vec3& wi : sphereLattice(4096)) queries.push_back({wo, eta, wi});
    queries.push_back({wo, eta, specularReflection(wo)});  // even exactly at the delta direction
    int nonZero = 0;
    for (const ProbeEval& e : probe.eval(queries)) nonZero += e.value != glm::vec3(0.0f) || e.pdf != 0.0f;
    EXPECT_EQ(nonZero, 0) << what;
}

// A smooth conductor is a mirror whose reflectance is Schlick's Fresnel from F0 = Ks.
TEST(BsdfDeltaLobes, SmoothConductorIsASchlickMirror) {
    BsdfProbe& probe = bsdfProbe();
    Material m = makeMaterial(MaterialType::Conductor, 0.0f);
    probe.setMaterial(m);
    for (float angle : kAngles) {
        const glm::vec3 wo = incidentDirection(angle);
        const std::string what = "theta_o " + std::to_string(angle);
        glm::vec3 expected;
        for (int ch = 0; ch < 3; ++ch) expected[ch] = float(fresnelSchlickReference(m.specular[ch], wo.z));
        int bad = 0;
        for (const ProbeSample& s : probe.sample(wo, 1.0f, 31, kCount))
            bad += !s.ok() || !s.delta() || s.pdf != 0.0f || !near(s.wi, specularReflection(wo), 1e-6f) ||
                   !near(s.weight, expected, 1e-5f);
        EXPECT_EQ(bad, 0) << what;
        expectNothingOutsideTheDelta(probe, wo, 1.0f, what);
    }
}

// Glass: each sample reflects with probability F and refracts with probability 1 - F (Fresnel, exact),
// the reflection with weight 1 and the refraction with weight Tf / eta^2 (the radiance scaling of
// pbrt-v4 section 9.5.2). So without the scaling and with Tf = 1, reflection + transmission = 1 exactly:
// every single sample carries weight 1, and no energy is lost or made.
TEST(BsdfDeltaLobes, SmoothDielectricSplitsEnergyByFresnelWithoutLoss) {
    BsdfProbe& probe = bsdfProbe();
    for (glm::vec3 tint : {glm::vec3(1.0f), glm::vec3(0.9f, 0.5f, 0.2f)}) {
        Material m = makeMaterial(MaterialType::Dielectric, 0.0f);
        m.transmission = tint;
        probe.setMaterial(m);
        for (float eta : {1.5f, 1.0f / 1.5f}) {
            for (float angle : kAngles) {
                const glm::vec3 wo = incidentDirection(angle);
                const std::string what = "eta " + std::to_string(eta) + " theta_o " + std::to_string(angle);
                // Snell's law: the tangential component scales by 1 / eta and the direction turns over.
                glm::dvec3 t = -glm::dvec3(wo.x, wo.y, 0.0) / double(eta);
                double sin2 = glm::dot(t, t);
                glm::vec3 refracted(glm::dvec3(t.x, t.y, -std::sqrt(std::max(0.0, 1.0 - sin2))));
                int reflected = 0, bad = 0;
                for (const ProbeSample& s : probe.sample(wo, eta, 47, kCount)) {
                    bad += !s.ok() || !s.delta() || s.pdf != 0.0f;
                    if (s.wi.z > 0.0f) {
                        ++reflected;
                        bad += !near(s.wi, specularReflection(wo), 1e-6f) || s.weight != glm::vec3(1.0f);
                    } else {
                        bad += !near(s.wi, refracted, 2e-6f) || !near(s.weight * eta * eta, tint, 1e-6f);
                    }
                }
                EXPECT_EQ(bad, 0) << what;
                // The fraction reflected is F, within 5 binomial standard errors (exactly 1 under total
                // internal reflection, sin2 >= 1, and then the test has no noise).
                double F = fresnelDielectricReference(wo.z, eta);
                double error = std::sqrt(F * (1.0 - F) / kCount);
                EXPECT_NEAR(double(reflected) / kCount, F, 5.0 * error + 1e-7) << what;
                if (sin2 >= 1.0) {
                    EXPECT_EQ(reflected, kCount) << what << ": total internal reflection";
                }
                expectNothingOutsideTheDelta(probe, wo, eta, what);
            }
        }
    }
}

// Smooth plastic: the coat's delta reflection carries Ks F(cos theta_o) on average (whatever the
// probability of choosing it), and the Lambertian base is not a delta lobe.
TEST(BsdfDeltaLobes, SmoothPlasticCoatReflectsKsTimesFresnel) {
    BsdfProbe& probe = bsdfProbe();
    Material m = makeMaterial(MaterialType::Plastic, 0.0f);
    m.specular = glm::vec3(1.0f, 0.8f, 0.6f);
    probe.setMaterial(m);
    for (float angle : kAngles) {
        const glm::vec3 wo = incidentDirection(angle);
        const std::string what = "theta_o " + std::to_string(angle);
        std::vector<ProbeSample> samples = probe.sample(wo, m.ior, 53, kCount);
        glm::dvec3 sum(0.0), sumSquares(0.0);
        int bad = 0, deltas = 0;
        for (const ProbeSample& s : samples) {
            bad += !s.ok();
            if (s.delta()) {
                ++deltas;
                bad += s.pdf != 0.0f || !near(s.wi, specularReflection(wo), 1e-6f);
                sum += glm::dvec3(s.weight);
                sumSquares += glm::dvec3(s.weight) * glm::dvec3(s.weight);
            }
        }
        EXPECT_EQ(bad, 0) << what;
        EXPECT_GT(deltas, 0) << what;
        EXPECT_LT(deltas, kCount) << what;
        const double F = fresnelDielectricReference(wo.z, m.ior);
        for (int ch = 0; ch < 3; ++ch) {
            double mean = sum[ch] / kCount, variance = sumSquares[ch] / kCount - mean * mean;
            EXPECT_NEAR(mean, m.specular[ch] * F, 5.0 * std::sqrt(variance / kCount) + 1e-6)
                << what << " channel " << ch;
        }
    }
}

}  // namespace
}  // namespace fp::test
