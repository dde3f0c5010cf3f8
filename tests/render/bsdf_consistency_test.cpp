// Consistency of the three functions of every BSDF in glsl/common/bsdf.glsl, run in GLSL through OSMesa
// (issue 4): a sample's weight and pdf must be what bsdfEval and bsdfPdf say at the sampled direction,
// and bsdfEval must obey (generalised) reciprocity.
#include <gtest/gtest.h>

#include <cstdio>

#include "bsdf_test_util.h"

namespace fp::test {
namespace {

constexpr int kCount = BsdfProbe::kWidth * 64;  // samples per (case, angle): every lobe is well visited

bool near(double a, double b, double relative, double absolute) {
    return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b)) + absolute;
}

// Counts failures without flooding the log: the first one is described.
struct Mismatches {
    int count = 0;
    std::string first;
    void add(const std::string& what) {
        if (count++ == 0) first = what;
    }
};

std::string vectorText(glm::vec3 v) {
    char text[96];
    std::snprintf(text, sizeof(text), "(%.7g, %.7g, %.7g)", double(v.x), double(v.y), double(v.z));
    return text;
}

// The weight bsdfSample returns is f |cos| / pdf, the estimators' multiplier: it must be bsdfEval /
// bsdfPdf at the same direction, and its pdf bsdfPdf, or MIS (which uses bsdfPdf) and the path weight
// (which uses the sample's weight) describe different estimators.
TEST(BsdfSampleWeights, EqualEvalOverPdfAtTheSampledDirection) {
    BsdfProbe& probe = bsdfProbe();
    const std::vector<BsdfCase> cases = samplingCases();
    for (size_t c = 0; c < cases.size(); ++c) {
        probe.setMaterial(cases[c].material);
        for (size_t a = 0; a < incidentAngles().size(); ++a) {
            const glm::vec3 wo = incidentDirection(incidentAngles()[a]);
            const float eta = cases[c].eta;
            const std::string what = describe(cases[c], incidentAngles()[a]);
            std::vector<ProbeSample> samples = probe.sample(wo, eta, caseSeed(c, a) + 500, kCount);
            std::vector<EvalQuery> queries;
            std::vector<const ProbeSample*> sampled;
            for (const ProbeSample& s : samples)
                if (s.ok() && !s.delta()) {
                    queries.push_back({wo, eta, s.wi});
                    sampled.push_back(&s);
                }
            ASSERT_GT(queries.size(), size_t(kCount / 3)) << what;
            std::vector<ProbeEval> values = probe.eval(queries);
            Mismatches bad;
            for (size_t k = 0; k < values.size(); ++k) {
                const ProbeSample& s = *sampled[k];
                const ProbeEval& e = values[k];
                std::string at = " at wi " + vectorText(s.wi);
                if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf))
                    bad.add("sample pdf " + std::to_string(s.pdf) + at);
                if (!near(s.pdf, e.pdf, 1e-3, 1e-7)) {
                    bad.add("sample pdf " + std::to_string(s.pdf) + " but bsdfPdf " + std::to_string(e.pdf) +
                            at);
                }
                for (int ch = 0; ch < 3; ++ch) {
                    double expected = double(e.value[ch]) / double(e.pdf);
                    if (!std::isfinite(s.weight[ch]) || s.weight[ch] < 0.0f ||
                        !near(s.weight[ch], expected, 1e-3, 1e-7))
                        bad.add("weight " + vectorText(s.weight) + " but eval / pdf " +
                                vectorText(e.value / e.pdf) + at);
                }
            }
            EXPECT_EQ(bad.count, 0) << what << ", " << values.size() << " samples; first: " << bad.first;
        }
    }
}

// Pairs (wo, wi) on which reciprocity is checked: the three incident directions with the sampled
// directions (where the lobes are) and an even lattice over the sphere (where the tails are), and the
// lattice against itself, with cos(theta) away from 0 on both sides so that f = eval / |cos| is
// well conditioned in float.
std::vector<EvalQuery> reciprocityPairs(BsdfProbe& probe, const BsdfCase& c, size_t caseIndex) {
    std::vector<EvalQuery> pairs;
    const std::vector<glm::vec3> lattice = sphereLattice(2048);
    for (size_t a = 0; a < incidentAngles().size(); ++a) {
        const glm::vec3 wo = incidentDirection(incidentAngles()[a]);
        for (const ProbeSample& s : probe.sample(wo, c.eta, caseSeed(caseIndex, a) + 900, kCount / 4))
            if (s.ok() && !s.delta()) pairs.push_back({wo, c.eta, s.wi});
        for (const glm::vec3& wi : lattice) pairs.push_back({wo, c.eta, wi});
    }
    for (size_t k = 0; k < lattice.size(); ++k)  // with a partner far along the lattice: a scrambled pairing
        if (lattice[k].z > 0.0f)
            pairs.push_back({lattice[k], c.eta, lattice[(k * 733 + 101) % lattice.size()]});
    std::vector<EvalQuery> kept;
    for (const EvalQuery& q : pairs)
        if (q.wo.z > 0.02f && std::abs(q.wi.z) > 0.02f) kept.push_back(q);
    return kept;
}

// Reflection is reciprocal (Helmholtz): f(wo, wi) = f(wi, wo), i.e. with bsdfEval's cosine,
// eval(wo, wi) / cos(theta_i) = eval(wi, wo) / cos(theta_o). Every model, every reflected pair.
TEST(BsdfReciprocity, ReflectionIsSymmetric) {
    BsdfProbe& probe = bsdfProbe();
    const std::vector<BsdfCase> cases = samplingCases();
    for (size_t c = 0; c < cases.size(); ++c) {
        probe.setMaterial(cases[c].material);
        std::vector<EvalQuery> forward, backward;
        for (const EvalQuery& q : reciprocityPairs(probe, cases[c], c))
            if (q.wi.z > 0.0f) {
                forward.push_back(q);
                backward.push_back({q.wi, q.eta, q.wo});
            }
        std::vector<ProbeEval> f = probe.eval(forward), b = probe.eval(backward);
        Mismatches bad;
        int nonZero = 0;
        for (size_t k = 0; k < f.size(); ++k) {
            for (int ch = 0; ch < 3; ++ch) {
                double fwd = double(f[k].value[ch]) / forward[k].wi.z,
                       bwd = double(b[k].value[ch]) / forward[k].wo.z;
                nonZero += ch == 0 && fwd > 0.0;
                if (!near(fwd, bwd, 1e-3, 1e-6))
                    bad.add("f(wo, wi) " + std::to_string(fwd) + " f(wi, wo) " + std::to_string(bwd) +
                            " wo " + vectorText(forward[k].wo) + " wi " + vectorText(forward[k].wi));
            }
        }
        EXPECT_EQ(bad.count, 0) << cases[c].name << ", " << f.size() << " pairs; first: " << bad.first;
        EXPECT_GT(nonZero, int(f.size() / 4)) << cases[c].name << ": too few pairs where f > 0 to tell";
    }
}

// Refraction is not symmetric but obeys generalised reciprocity (Veach 1997, chapter 5; pbrt-v4 section
// 9.5.2): for light flowing from wi to wo, f(wi -> wo) / n_o^2 = f(wo -> wi) / n_i^2, where n_o and n_i
// are the refractive indices on wo's and wi's sides. bsdf.glsl's f(wo, wi; eta) is f(wi -> wo) with
// eta = n_i / n_o, already including the 1 / eta^2 radiance scaling (Walter et al. 2007, eq. 21, has
// n_o^2 / (n_i (wi.wm) + n_o (wo.wm))^2, and the code writes it as 1 / (eta^2 (wi.wm + wo.wm / eta)^2)).
// The reversed flow is the same interface seen from wi's side: its shading frame is mirrored
// (surface.glsl builds the frame on the side the path arrives from; an isotropic BSDF does not care
// which mirror), its wo is flipSide(wi), its wi is flipSide(wo), and its eta is 1 / eta. So the
// relation tested is
//     f(wo, wi; eta) eta^2 = f(flipSide(wi), flipSide(wo); 1 / eta),
// with f = eval / |cos(theta_i)|. Both sides are D G (1 - F) |wi.wm| |wo.wm| / (|cos_o cos_i|
// (wi.wm + wo.wm / eta)^2), since the Fresnel transmittance of an interface is the same from both sides.
TEST(BsdfReciprocity, DielectricTransmissionIsReciprocalUpToEtaSquared) {
    BsdfProbe& probe = bsdfProbe();
    const std::vector<BsdfCase> cases = samplingCases();
    for (size_t c = 0; c < cases.size(); ++c) {
        if (cases[c].material.type != MaterialType::Dielectric) continue;
        probe.setMaterial(cases[c].material);
        const float eta = cases[c].eta;
        std::vector<EvalQuery> forward, backward;
        for (const EvalQuery& q : reciprocityPairs(probe, cases[c], c)) {
            // Where either direction grazes the microfacet, 1 - F is ill-conditioned: float rounding of
            // the unit vectors (1e-7) alone moves it by 0.1%. Such pairs carry almost no light anyway.
            glm::dvec3 wm = glm::normalize(glm::dvec3(q.wi) * double(eta) + glm::dvec3(q.wo));
            if (std::min(std::abs(glm::dot(wm, glm::dvec3(q.wo))), std::abs(glm::dot(wm, glm::dvec3(q.wi)))) <
                0.05)
                continue;
            if (q.wi.z < 0.0f) {
                forward.push_back(q);
                backward.push_back({flipSide(q.wi), 1.0f / eta, flipSide(q.wo)});
            }
        }
        std::vector<ProbeEval> f = probe.eval(forward), b = probe.eval(backward);
        Mismatches bad;
        int nonZero = 0;
        for (size_t k = 0; k < f.size(); ++k) {
            for (int ch = 0; ch < 3; ++ch) {
                double fwd = double(f[k].value[ch]) / std::abs(forward[k].wi.z) * double(eta) * double(eta);
                double bwd = double(b[k].value[ch]) / std::abs(forward[k].wo.z);
                nonZero += ch == 0 && fwd > 0.0;
                if (!near(fwd, bwd, 1e-3, 1e-6))
                    bad.add("f(wo, wi) eta^2 " + std::to_string(fwd) + " reversed " + std::to_string(bwd) +
                            " wo " + vectorText(forward[k].wo) + " wi " + vectorText(forward[k].wi));
            }
        }
        EXPECT_EQ(bad.count, 0) << cases[c].name << ", " << f.size() << " pairs; first: " << bad.first;
        EXPECT_GT(nonZero, int(f.size() / 4)) << cases[c].name << ": too few pairs where f > 0 to tell";
    }
}

}  // namespace
}  // namespace fp::test
