// Float precision of the GGX lobes of glsl/common/bsdf.glsl near the smooth limit, run in GLSL through
// OSMesa. The statistical tests cannot see these lobes (too narrow for any histogram) and a sample's
// weight does not depend on D (it cancels in eval / pdf), but bsdfEval and bsdfPdf do: next-event
// estimation multiplies light samples by bsdfEval, and MIS weighs by bsdfPdf. So they are compared,
// at the directions the sampler draws, with the same formulas evaluated here in double precision.
#include <gtest/gtest.h>

#include <cstdio>

#include "bsdf_test_util.h"

namespace fp::test {
namespace {

TEST(BsdfPrecision, NearSmoothGgxConductorMatchesDoublePrecision) {
    BsdfProbe& probe = bsdfProbe();
    const int count = BsdfProbe::kWidth * 32;
    for (float roughness : {0.011f, 0.02f, 0.05f, 0.1f, 0.2f}) {
        Material m = makeMaterial(MaterialType::Conductor, roughness);
        probe.setMaterial(m);
        const double alpha = std::max(double(roughness) * double(roughness), 1e-4);  // as ggxAlpha
        for (float angle : incidentAngles()) {
            const glm::vec3 wo = incidentDirection(angle);
            std::vector<EvalQuery> queries;
            for (const ProbeSample& s : probe.sample(wo, 1.0f, 71, count))
                if (s.ok()) queries.push_back({wo, 1.0f, s.wi});
            ASSERT_GT(queries.size(), size_t(count / 2));
            std::vector<ProbeEval> values = probe.eval(queries);
            double worstValue = 0.0, worstPdf = 0.0;
            for (size_t k = 0; k < values.size(); ++k) {
                ReferenceValue r = ggxConductorReference(glm::dvec3(wo), glm::dvec3(queries[k].wi), alpha,
                                                         double(m.specular.x));
                worstValue = std::max(worstValue, std::abs(double(values[k].value.x) - r.value) / r.value);
                worstPdf = std::max(worstPdf, std::abs(double(values[k].pdf) - r.pdf) / r.pdf);
            }
            std::printf(
                "  roughness %.3f theta_o %2.0f: largest relative error of bsdfEval %.1e, of bsdfPdf %.1e\n",
                double(roughness), double(angle), worstValue, worstPdf);
            // A float evaluation of these formulas is good to ~1e-6 here; the margin is for grazing
            // angles, where the half vector is a small difference of nearly opposite vectors.
            EXPECT_LT(worstValue, 1e-3) << "bsdfEval, roughness " << roughness << " theta_o " << angle;
            EXPECT_LT(worstPdf, 1e-3) << "bsdfPdf, roughness " << roughness << " theta_o " << angle;
        }
    }
}

}  // namespace
}  // namespace fp::test
