// Consistency of the three functions of every BSDF in glsl/common/bsdf.glsl, run in GLSL through OSMesa
// (issues 4 and 15), each checked against something computed independently of it:
//   - bsdfEval and bsdfPdf against the published formulas, evaluated here in double precision at fixed
//     directions (Walter et al. 2007 for GGX reflection and refraction, Heitz 2018 for the density of
//     visible normals, the Fresnel equations);
//   - the mean of bsdfSample's weights against the integral of bsdfEval over the sphere by quadrature:
//     weight = f |cos| / pdf, so E[weight] = integral of f |cos| whatever the sampler, if and only if the
//     weight, the sampled density and bsdfEval agree;
//   - bsdfEval's (generalised) reciprocity.
// The sampled directions' histogram against bsdfPdf, and bsdfPdf's integral against the fraction of
// samples it describes, are bsdf_chi_square_test.cpp's; the delta lobes, bsdf_delta_test.cpp's.
#include <gtest/gtest.h>

#include <cstdio>

#include "bsdf_test_util.h"

namespace fp::test {
namespace {

constexpr int kCount = BsdfProbe::kWidth * 64;  // samples per (case, angle) where samples are pairs to test

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

double alphaOf(const Material& m) {
    return std::max(double(m.roughness) * double(m.roughness), 1e-4);  // ggxAlpha
}

// ---------------------------------------------------------------------------------------------------
// bsdfEval and bsdfPdf against the formulas.

// The pairs of the formula tests: four incident directions and a lattice of 512 wi over the sphere,
// without the pairs where float rounding of the unit vectors alone moves the result by more than the
// tolerance: grazing wi, and (for glass) microfacets seen at grazing angles, where 1 - F is
// ill-conditioned, or near the edge of the support, where a value jumps to 0.
std::vector<EvalQuery> formulaPairs(float eta, bool dielectric) {
    std::vector<EvalQuery> out;
    for (float angle : {0.0f, 30.0f, 60.0f, 80.0f})
        for (const glm::vec3& wi : sphereLattice(512)) {
            const glm::vec3 wo = incidentDirection(angle);
            if (std::abs(wi.z) < 0.02f) continue;
            if (dielectric) {
                glm::dvec3 h = wi.z > 0.0f ? glm::dvec3(wo) + glm::dvec3(wi)
                                           : glm::dvec3(wi) * double(eta) + glm::dvec3(wo);
                if (glm::length(h) < 1e-3) continue;
                h = glm::normalize(h);
                if (std::min(std::abs(glm::dot(h, glm::dvec3(wo))), std::abs(glm::dot(h, glm::dvec3(wi)))) <
                        0.05 ||
                    std::abs(h.z) < 0.05)
                    continue;
            }
            out.push_back({wo, eta, wi});
        }
    return out;
}

// Every rough model's bsdfEval (each channel) and bsdfPdf equal the formulas to float precision. What
// this catches: a wrong or missing factor of f (D, G, F, the 1 / (4 cos_o) of reflection, the Jacobian
// and 1 / eta^2 of refraction, the (1 - F) attenuations of the plastic's base), a Fresnel evaluated at
// the wrong angle, a wrong density of visible normals or Jacobian in bsdfPdf. A bug common to bsdfEval
// and bsdfSample's weight cancels out of the sample-weight test below and can only be seen here.
TEST(BsdfFormulas, EvalAndPdfMatchThePublishedModels) {
    BsdfProbe& probe = bsdfProbe();
    const std::vector<BsdfCase> cases = samplingCases();
    for (size_t c = 0; c < cases.size(); ++c) {
        const Material& m = cases[c].material;
        const bool dielectric = m.type == MaterialType::Dielectric;
        probe.setMaterial(m);
        std::vector<EvalQuery> queries = formulaPairs(cases[c].eta, dielectric);
        std::vector<ProbeEval> values = probe.eval(queries);
        Mismatches bad;
        int nonZero = 0, transmitted = 0;
        // The plastic's density is a mixture of the coat's and the base's with a probability of choosing
        // the coat that is the sampler's own business (it may depend on wo, not on wi): it is fitted per
        // wo by least squares, and then every wi must fit the mixture. The metallic-roughness model's is
        // metallic times the conductor's (the same GGX density as the coat's) plus (1 - metallic) times
        // the plastic's: again a mixture of the two, whose share of GGX must be at least metallic.
        const bool mixture = m.type == MaterialType::Plastic || m.type == MaterialType::MetallicRoughness;
        std::vector<double> fitNumerator(4, 0.0), fitDenominator(4, 0.0), coatDensity(queries.size()),
            baseDensity(queries.size());
        for (size_t k = 0; k < queries.size(); ++k) {
            const glm::dvec3 wo(queries[k].wo), wi(queries[k].wi);
            const double alpha = alphaOf(m);
            const std::string at = " wo " + vectorText(queries[k].wo) + " wi " + vectorText(queries[k].wi);
            glm::dvec3 value(0.0);
            double pdf = 0.0;
            for (int ch = 0; ch < 3; ++ch) {
                switch (m.type) {
                    case MaterialType::Diffuse:
                        value[ch] = wi.z > 0.0 ? m.diffuse[ch] / kPi * wi.z : 0.0;
                        pdf = wi.z > 0.0 ? wi.z / kPi : 0.0;
                        break;
                    case MaterialType::Conductor: {
                        ReferenceValue r = ggxConductorReference(wo, wi, alpha, m.specular[ch]);
                        value[ch] = r.value;
                        pdf = r.pdf;
                        break;
                    }
                    case MaterialType::Plastic:
                        value[ch] = plasticReference(wo, wi, alpha, m.roughness >= 0.01f, m.ior,
                                                     m.diffuse[ch], m.specular[ch]);
                        break;
                    case MaterialType::MetallicRoughness:
                        value[ch] = metallicRoughnessReference(wo, wi, alpha, m.roughness >= 0.01f, m.ior,
                                                               m.diffuse[ch], m.metallic);
                        break;
                    case MaterialType::Dielectric: {
                        ReferenceValue r =
                            ggxDielectricReference(wo, wi, alpha, cases[c].eta, m.transmission[ch]);
                        value[ch] = r.value;
                        pdf = r.pdf;
                        break;
                    }
                    case MaterialType::Unlit:  // scatters nothing (gltf_material_extensions_test.cpp)
                        break;
                }
                if (!near(values[k].value[ch], value[ch], 1e-3, 1e-6))
                    bad.add("bsdfEval " + vectorText(values[k].value) + " but the formula gives " +
                            vectorText(glm::vec3(value)) + at);
            }
            nonZero += value.x > 1e-6;
            transmitted += value.x > 1e-6 && wi.z < 0.0;
            if (mixture) {
                size_t a = k / (queries.size() / 4);  // formulaPairs: the four wo, in order, equally many
                coatDensity[k] = m.roughness >= 0.01f ? ggxReflectionDensity(wo, wi, alpha) : 0.0;
                baseDensity[k] = wi.z > 0.0 ? wi.z / kPi : 0.0;
                // pdf = p coat + (1 - p) base, i.e. pdf - base = p (coat - base).
                fitNumerator[a] += (values[k].pdf - baseDensity[k]) * (coatDensity[k] - baseDensity[k]);
                fitDenominator[a] += (coatDensity[k] - baseDensity[k]) * (coatDensity[k] - baseDensity[k]);
            } else if (!near(values[k].pdf, pdf, 1e-3, 1e-6)) {
                bad.add("bsdfPdf " + std::to_string(values[k].pdf) + " but the formula gives " +
                        std::to_string(pdf) + at);
            }
        }
        if (mixture) {
            // A smooth metallic-roughness has no GGX density: its share is the conductor's delta lobe's.
            const double least =
                m.type == MaterialType::MetallicRoughness && m.roughness >= 0.01f ? m.metallic : 0.0;
            for (size_t k = 0; k < queries.size(); ++k) {
                size_t a = k / (queries.size() / 4);
                double p = fitDenominator[a] > 0.0 ? fitNumerator[a] / fitDenominator[a] : 0.0;
                double expected = p * coatDensity[k] + (1.0 - p) * baseDensity[k];
                if (!(p >= least - 1e-4 && p <= 1.0) || !near(values[k].pdf, expected, 1e-3, 1e-6))
                    bad.add("bsdfPdf " + std::to_string(values[k].pdf) + " but the best mixture (coat " +
                            std::to_string(p) + ") gives " + std::to_string(expected) + " wo " +
                            vectorText(queries[k].wo) + " wi " + vectorText(queries[k].wi));
            }
        }
        EXPECT_EQ(bad.count, 0) << cases[c].name << ", " << queries.size() << " pairs; first: " << bad.first;
        EXPECT_GT(nonZero, int(queries.size() / 8)) << cases[c].name << ": too few pairs where f > 0 to tell";
        if (dielectric) {
            EXPECT_GT(transmitted, 20) << cases[c].name << ": too few refracted pairs to tell";
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// The sample weights against the integral of bsdfEval.

// The integral of bsdfEval(wo, wi) over the whole sphere of wi, evaluated by the shader at the nodes of a
// quadrature written here. The narrow lobes of GGX are narrow in the microfacet normal h, around +z,
// whatever wo: so the integral is taken over h, each h standing for the wi it reflects wo into (every
// wi above the surface comes from exactly one h, h = normalize(wo + wi)) and, for glass, the wi it
// refracts wo into (h = -normalize(eta wi + wo), Walter et al. 2007, eq. 16), with the Jacobians
// d(omega_i) / d(omega_h) of the two maps: 4 |wo.h| for reflection (eq. 14) and
// (eta wi.h + wo.h)^2 / (eta^2 |wi.h|) for refraction (the inverse of eq. 17). The midpoint rule runs in
// (s, phi_h) with theta_h = a tan(s atan(theta_max / a)), a = alpha: half the nodes inside the lobe's
// width, the rest spread out to the tails, where the plastic's base also lives. For reflection,
// theta_max is where wi meets the horizon, 1/2 atan2(cos_o, -sin_o cos(phi_h - phi_o)) (from
// wi.z = 2 (wo.h) h.z - wo.z = 0), so that the horizon, beyond which f drops to 0 within a few alpha
// (Smith's shadowing), is a boundary of the rule rather than a jump inside it. Two rules, n and 2n
// nodes per dimension: the difference is the size of the coarser's error and bounds the finer's
// (refraction's support has edges inside the rule, where the convergence is only O(h)).
struct SphereIntegral {
    glm::dvec3 value{0.0};
    double error = 0.0;  // |fine - coarse|, over channels
};

glm::dvec3 integrateEvalOverNormals(BsdfProbe& probe, glm::vec3 wo, float eta, double alpha, bool refraction,
                                    int n) {
    std::vector<EvalQuery> queries;
    std::vector<double> weights;
    const glm::dvec3 o(wo);
    const double sinO = std::sqrt(std::max(0.0, 1.0 - o.z * o.z)), phiO = std::atan2(o.y, o.x);
    const double e = eta, dphi = 2.0 * kPi / (2 * n);
    for (int j = 0; j < 2 * n; ++j) {
        const double phi = (j + 0.5) * dphi;
        for (bool reflect : {true, false}) {
            if (!reflect && !refraction) continue;
            const double top = reflect ? 0.5 * std::atan2(o.z, -sinO * std::cos(phi - phiO)) : 0.5 * kPi;
            const double range = std::atan(top / alpha);
            for (int i = 0; i < n; ++i) {
                const double s = (i + 0.5) / n, theta = alpha * std::tan(s * range);
                const double dtheta = alpha * range / (std::cos(s * range) * std::cos(s * range)) / n;
                const glm::dvec3 h(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                   std::cos(theta));
                const double area = std::sin(theta) * dtheta * dphi, c = glm::dot(o, h);
                if (c <= 0.0) continue;
                glm::dvec3 wi;
                double jacobian;
                if (reflect) {
                    wi = 2.0 * c * h - o;
                    if (wi.z <= 0.0) continue;
                    jacobian = 4.0 * c;
                } else {
                    const double cos2T = 1.0 - (1.0 - c * c) / (e * e);
                    if (cos2T <= 0.0) continue;  // total internal reflection
                    wi = -o / e + (c / e - std::sqrt(cos2T)) * h;
                    if (wi.z >= 0.0) continue;
                    const double d = e * glm::dot(wi, h) + c;
                    jacobian = d * d / (e * e * std::abs(glm::dot(wi, h)));
                }
                queries.push_back({wo, eta, glm::vec3(wi)});
                weights.push_back(jacobian * area);
            }
        }
    }
    std::vector<ProbeEval> values = probe.eval(queries);
    glm::dvec3 sum(0.0);
    for (size_t k = 0; k < values.size(); ++k) sum += glm::dvec3(values[k].value) * weights[k];
    return sum;
}

// The same integral over wi directly, for the broad lobes of the Lambertian surfaces and the plastic's
// base, which the rule above spreads too thin: the midpoint rule on n x 4n points per hemisphere in
// (t, phi) with |cos(theta_i)| = 1 - t^2, the horizon a boundary of both hemispheres' rules.
glm::dvec3 integrateEvalOverDirections(BsdfProbe& probe, glm::vec3 wo, float eta, int n) {
    std::vector<EvalQuery> queries;
    std::vector<double> weights;
    const double dphi = 2.0 * kPi / (4 * n);
    for (double side : {1.0, -1.0})
        for (int a = 0; a < n; ++a) {
            const double t = (a + 0.5) / n, z = side * (1.0 - t * t),
                         r = std::sqrt(std::max(0.0, 1.0 - z * z));
            for (int b = 0; b < 4 * n; ++b) {
                const double phi = (b + 0.5) * dphi;
                queries.push_back(
                    {wo, eta, glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z))});
                weights.push_back(2.0 * t / n * dphi);
            }
        }
    std::vector<ProbeEval> values = probe.eval(queries);
    glm::dvec3 sum(0.0);
    for (size_t k = 0; k < values.size(); ++k) sum += glm::dvec3(values[k].value) * weights[k];
    return sum;
}

// The integral of bsdfEval over the sphere by the rule that suits the model, at n and 2n nodes.
SphereIntegral integrateEval(BsdfProbe& probe, glm::vec3 wo, float eta, const Material& m, int n) {
    const bool microfacet = m.type == MaterialType::Conductor || m.type == MaterialType::Dielectric;
    const bool refraction = m.type == MaterialType::Dielectric;
    auto rule = [&](int nodes) {
        return microfacet ? integrateEvalOverNormals(probe, wo, eta, alphaOf(m), refraction, nodes)
                          : integrateEvalOverDirections(probe, wo, eta, nodes);
    };
    glm::dvec3 coarse = rule(n), fine = rule(2 * n);
    glm::dvec3 difference = glm::abs(fine - coarse);
    return {fine, std::max({difference.x, difference.y, difference.z})};
}

// The mean sample weight, with a failed sample counting 0, is an unbiased estimate of the directional
// albedo, the integral of f |cos| over the sphere: the shader's samples are compared with bsdfEval
// integrated by quadrature (plus, for a smooth coat, the mirror's albedo Ks F(cos_o), the Fresnel
// equations computed here), within five standard errors and the quadrature's error. What this catches:
// a weight that is not eval / pdf (a factor dropped or added in bsdfSample, a lobe-selection
// probability not divided out, a wrong eta passed along), and a sampled density that is not bsdfPdf
// (a wrong Jacobian or lobe probability in bsdfPdf makes the weight wrong by that factor). It does not
// see a bug in bsdfEval that the weight shares: that is the formula test's.
TEST(BsdfSampleWeights, MeanWeightIsTheIntegralOfEval) {
    BsdfProbe& probe = bsdfProbe();
    const std::vector<BsdfCase> cases = samplingCases();
    for (size_t c = 0; c < cases.size(); ++c) {
        const Material& m = cases[c].material;
        probe.setMaterial(m);
        for (size_t a = 0; a < incidentAngles().size(); ++a) {
            const glm::vec3 wo = incidentDirection(incidentAngles()[a]);
            const float eta = cases[c].eta;
            const std::string what = describe(cases[c], incidentAngles()[a]);
            std::vector<ProbeSample> samples = probe.sample(wo, eta, caseSeed(c, a) + 500, kSampleCount);
            glm::dvec3 sum(0.0), sumSquares(0.0);
            int invalid = 0;  // a weight must be finite and non-negative
            for (const ProbeSample& s : samples) {
                glm::dvec3 w = s.ok() ? glm::dvec3(s.weight) : glm::dvec3(0.0);
                invalid += s.ok() && !(glm::all(glm::greaterThanEqual(s.weight, glm::vec3(0.0f))) &&
                                       glm::all(glm::lessThan(s.weight, glm::vec3(1e30f))));
                sum += w;
                sumSquares += w * w;
            }
            const double count = double(samples.size());
            const glm::dvec3 mean = sum / count;
            const glm::dvec3 standardError =
                glm::sqrt(glm::max(sumSquares / count - mean * mean, glm::dvec3(0.0)) / count);
            SphereIntegral integral = integrateEval(probe, wo, eta, m, 128);
            if (m.type == MaterialType::MetallicRoughness) {
                // The blend's narrow conductor lobe and broad base need different rules: each part is
                // integrated as the model it is (their sum is the blend's eval: the formula test above),
                // and the material under test is set back for the next angle.
                Material conductor = makeMaterial(MaterialType::Conductor, m.roughness);
                conductor.specular = m.diffuse;
                Material plastic = makeMaterial(MaterialType::Plastic, m.roughness);
                plastic.diffuse = m.diffuse;
                plastic.specular = glm::vec3(1.0f);
                plastic.ior = m.ior;
                probe.setMaterial(conductor);
                SphereIntegral metal = integrateEval(probe, wo, eta, conductor, 128);
                probe.setMaterial(plastic);
                SphereIntegral b = integrateEval(probe, wo, eta, plastic, 128);
                probe.setMaterial(m);
                const double metallic = double(m.metallic);
                integral.value = metallic * metal.value + (1.0 - metallic) * b.value;
                integral.error = metallic * metal.error + (1.0 - metallic) * b.error;
            }
            glm::dvec3 expected = integral.value;
            if (m.type == MaterialType::Plastic && m.roughness < 0.01f)
                expected += glm::dvec3(m.specular) * fresnelDielectricReference(double(wo.z), double(m.ior));
            if (m.type == MaterialType::MetallicRoughness && m.roughness < 0.01f)
                for (int ch = 0; ch < 3;
                     ++ch)  // the two mirrors: the metal's Schlick, the white coat's Fresnel
                    expected[ch] +=
                        double(m.metallic) * fresnelSchlickReference(m.diffuse[ch], double(wo.z)) +
                        (1.0 - double(m.metallic)) * fresnelDielectricReference(double(wo.z), double(m.ior));
            std::printf(
                "  %-38s mean weight (%.5f, %.5f, %.5f) +- %.1e  integral (%.5f, %.5f, %.5f) +- %.1e\n",
                what.c_str(), mean.x, mean.y, mean.z, standardError.x, expected.x, expected.y, expected.z,
                integral.error);
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_NEAR(mean[ch], expected[ch], 5.0 * standardError[ch] + integral.error + 1e-5)
                    << what << ", channel " << ch;
            // The comparison is sharp: the quadrature is good to the noise or better.
            EXPECT_LT(integral.error, 3.0 * standardError.x + 1e-4) << what;
            EXPECT_GT(expected.x, 0.01) << what << ": nothing to compare";
            EXPECT_EQ(invalid, 0) << what << ": weights negative, infinite or NaN";
        }
    }
}

// The density bsdfSample reports with each non-delta sample is bsdfPdf of the direction it returns: MIS
// weighs a BSDF sample by the first and a light sample by the second, and the two weights of one path
// sum to 1 only if they agree. What this catches: a sampler that reports the density of the lobe it
// chose rather than of the whole mixture (the plastic's coat and base, the metallic-roughness model's
// two lobes), or a density computed at a different direction. Within float rounding.
TEST(BsdfSampleDensity, SampledDensityIsBsdfPdf) {
    BsdfProbe& probe = bsdfProbe();
    const std::vector<BsdfCase> cases = samplingCases();
    for (size_t c = 0; c < cases.size(); ++c) {
        probe.setMaterial(cases[c].material);
        for (size_t a = 0; a < incidentAngles().size(); ++a) {
            const glm::vec3 wo = incidentDirection(incidentAngles()[a]);
            std::vector<ProbeSample> samples = probe.sample(wo, cases[c].eta, caseSeed(c, a) + 700, kCount);
            std::vector<EvalQuery> queries;
            for (const ProbeSample& s : samples)
                if (s.ok() && !s.delta()) queries.push_back({wo, cases[c].eta, s.wi});
            std::vector<ProbeEval> values = probe.eval(queries);
            Mismatches bad;
            size_t k = 0;
            for (const ProbeSample& s : samples) {
                if (!s.ok() || s.delta()) continue;
                if (!near(s.pdf, values[k].pdf, 1e-4, 1e-7))
                    bad.add("sampled pdf " + std::to_string(s.pdf) + " but bsdfPdf " +
                            std::to_string(values[k].pdf) + " wi " + vectorText(s.wi));
                ++k;
            }
            const std::string what = describe(cases[c], incidentAngles()[a]);
            EXPECT_EQ(bad.count, 0) << what << ", " << queries.size() << " samples; first: " << bad.first;
            EXPECT_GT(queries.size(), samples.size() / 5) << what;
        }
    }
}

// A shading normal interpolated across a triangle can leave the view direction below it (wo.z < 0) on
// a surface whose geometric normal faces the viewer. bsdfEval and bsdfPdf must then give finite,
// non-negative values (0 is the intended answer): a negative f or pdf would subtract light and break
// MIS, a NaN would poison the pixel. What this catches: the GGX terms divided by wo.z or dot(wo, wm)
// and the Fresnel factors evaluated at a negative cosine, without a guard. (Written for issue 15
// while the guards were being added to bsdf.glsl: it fails on the code from before them.)
TEST(BsdfBelowTheShadingNormal, EvalAndPdfAreFiniteAndNonNegative) {
    BsdfProbe& probe = bsdfProbe();
    std::vector<BsdfCase> cases = samplingCases();
    cases.push_back({"conductor r=0", makeMaterial(MaterialType::Conductor, 0.0f), 1.0f});
    cases.push_back({"dielectric r=0 eta=1.5", makeMaterial(MaterialType::Dielectric, 0.0f), 1.5f});
    std::vector<glm::vec3> below;
    for (const glm::vec3& w : sphereLattice(64))
        if (w.z < 0.0f) below.push_back(w);
    below.push_back(glm::vec3(0.0f, 0.6f, -0.8f));
    below.push_back(glm::vec3(std::sqrt(1.0f - 1e-6f), 0.0f, -1e-3f));  // just below the horizon
    for (const BsdfCase& c : cases) {
        probe.setMaterial(c.material);
        std::vector<EvalQuery> queries;
        for (const glm::vec3& wo : below)
            for (const glm::vec3& wi : sphereLattice(256)) queries.push_back({wo, c.eta, wi});
        std::vector<ProbeEval> values = probe.eval(queries);
        Mismatches bad;
        for (size_t k = 0; k < values.size(); ++k) {
            const ProbeEval& e = values[k];
            const bool valid = glm::all(glm::greaterThanEqual(e.value, glm::vec3(0.0f))) &&
                               glm::all(glm::lessThan(e.value, glm::vec3(1e30f))) && e.pdf >= 0.0f &&
                               e.pdf < 1e30f;  // false for NaN too
            if (!valid)
                bad.add("bsdfEval " + vectorText(e.value) + " bsdfPdf " + std::to_string(e.pdf) + " wo " +
                        vectorText(queries[k].wo) + " wi " + vectorText(queries[k].wi));
        }
        EXPECT_EQ(bad.count, 0) << c.name << ", " << values.size() << " pairs; first: " << bad.first;
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
