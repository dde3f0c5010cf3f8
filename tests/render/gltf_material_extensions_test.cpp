// glTF's material extensions (README, the material table) rendered with the real shaders:
// - KHR_materials_unlit on the Khronos UnlitTest model: each object is its flat base colour, exactly,
//   in every integrator (no shading, no noise).
// - KHR_materials_volume: an absorbing glass cube of index 1 in a white furnace shows exactly the
//   attenuation colour where the path inside is attenuationDistance long (Beer-Lambert).
// - KHR_materials_specular: the blend with a tinted coat samples as its density says (chi-square).
// - KHR_materials_clearcoat and KHR_materials_sheen: the second GGX lobe and the Charlie sheen lobe on
//   top, tested as every lobe is (bsdf_*_test.cpp): chi-square of their sampling, the sampled density
//   is bsdfPdf, reciprocity, energy (a white furnace of directions: the albedo never exceeds 1), the
//   smooth coat's mirror weight, and whole renders in which nee, bsdf and bdpt agree.
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

// Clearcoated metallic-roughness materials: rough and smooth coats over rough and smooth bases.
Material clearcoated(float metallic, float roughness, float clearcoat, float clearcoatRoughness) {
    Material m = makeMetallicRoughness(metallic, roughness);
    m.clearcoat = clearcoat;
    m.clearcoatRoughness = clearcoatRoughness;
    return m;
}

Material sheened(Material m, glm::vec3 colour, float roughness) {
    m.sheenColor = colour;
    m.sheenRoughness = roughness;
    return m;
}

// The layered cases: clearcoats, sheens, and both.
std::vector<BsdfCase> layeredCases() {
    const glm::vec3 velvet(1.0f, 0.8f, 0.6f);
    return {{"sheen r=0.5 over m=0 r=0.6", sheened(makeMetallicRoughness(0.0f, 0.6f), velvet, 0.5f), 1.5f},
            {"sheen r=0.1 over smooth m=1", sheened(makeMetallicRoughness(1.0f, 0.0f), velvet, 0.1f), 1.5f},
            {"sheen r=1 under coat r=0.2", sheened(clearcoated(0.5f, 0.5f, 1.0f, 0.2f), velvet, 1.0f), 1.5f},
            {"coat 1 r=0.1 over m=0.5 r=0.4", clearcoated(0.5f, 0.4f, 1.0f, 0.1f), 1.5f},
            {"coat 0.7 r=0.3 over m=0 r=0.7", clearcoated(0.0f, 0.7f, 0.7f, 0.3f), 1.5f},
            {"smooth coat 1 over m=1 r=0.3", clearcoated(1.0f, 0.3f, 1.0f, 0.0f), 1.5f},
            {"coat 1 r=0.2 over smooth m=0", clearcoated(0.0f, 0.0f, 1.0f, 0.2f), 1.5f}};
}

// Chi-square of the sampled directions against bsdfPdf (Bonferroni over the cases and angles), the
// density's mass against the fraction of non-delta samples, and each sample's reported density against
// bsdfPdf at its direction. The break-checks: clearcoatedPdf without the coat's probability p, or
// sheenedPdf without the sheen's, fails it.
TEST(GltfMaterialExtensions, LayersSampleAsTheirDensitySays) {
    BsdfProbe& probe = bsdfProbe();
    const std::vector<BsdfCase> cases = layeredCases();
    const double significance = 0.01 / double(cases.size() * incidentAngles().size());
    for (size_t c = 0; c < cases.size(); ++c) {
        probe.setMaterial(cases[c].material);
        for (size_t a = 0; a < incidentAngles().size(); ++a) {
            const glm::vec3 wo = incidentDirection(incidentAngles()[a]);
            const std::string what = describe(cases[c], incidentAngles()[a]);
            std::vector<ProbeSample> samples =
                probe.sample(wo, 1.5f, uint32_t(5000 + 10 * c + a), kSampleCount);
            ChiSquareResult r = chiSquareTest(probe, samples, wo, 1.5f);
            std::printf("  %-42s chi2 %8.2f  dof %3d  p %.4f\n", what.c_str(), r.statistic, r.dof, r.pValue);
            EXPECT_GT(r.pValue, significance) << what;
            const double f = r.nonDeltaFraction;
            EXPECT_NEAR(r.pdfIntegral, f, 5.0 * std::sqrt(f * (1.0 - f) / kSampleCount) + 1e-4) << what;
            std::vector<EvalQuery> queries;
            for (const ProbeSample& s : samples)
                if (s.ok() && !s.delta() && queries.size() < 4096) queries.push_back({wo, 1.5f, s.wi});
            std::vector<ProbeEval> values = probe.eval(queries);
            int differ = 0;
            for (size_t k = 0, q = 0; k < samples.size() && q < queries.size(); ++k) {
                if (!samples[k].ok() || samples[k].delta()) continue;
                differ += std::abs(samples[k].pdf - values[q].pdf) > 1e-4f * values[q].pdf + 1e-7f;
                ++q;
            }
            EXPECT_EQ(differ, 0) << what << ": sampled density is not bsdfPdf";
        }
    }
}

// Helmholtz reciprocity, f(wo, wi) = f(wi, wo) (eval / cos(theta_i) both ways), on an even lattice of
// pairs away from the horizon; and the albedo of a white base under a white coat, the mean sample
// weight, is at most 1 (five standard errors) at every angle, grazing included.
TEST(GltfMaterialExtensions, LayersAreReciprocalAndConserveEnergy) {
    BsdfProbe& probe = bsdfProbe();
    const std::vector<glm::vec3> lattice = sphereLattice(1024);
    for (BsdfCase c : layeredCases()) {
        probe.setMaterial(c.material);
        std::vector<EvalQuery> forward, backward;
        for (size_t k = 0; k < lattice.size(); ++k) {
            glm::vec3 wo = lattice[k], wi = lattice[(k * 733 + 101) % lattice.size()];
            if (wo.z > 0.02f && wi.z > 0.02f) {
                forward.push_back({wo, 1.5f, wi});
                backward.push_back({wi, 1.5f, wo});
            }
        }
        std::vector<ProbeEval> f = probe.eval(forward), b = probe.eval(backward);
        int bad = 0, nonZero = 0;
        for (size_t k = 0; k < f.size(); ++k)
            for (int ch = 0; ch < 3; ++ch) {
                double fwd = double(f[k].value[ch]) / forward[k].wi.z,
                       bwd = double(b[k].value[ch]) / forward[k].wo.z;
                bad += std::abs(fwd - bwd) > 1e-3 * std::max(fwd, bwd) + 1e-6;
                nonZero += ch == 0 && fwd > 0.0;
            }
        EXPECT_EQ(bad, 0) << c.name << ": not reciprocal";
        EXPECT_GT(nonZero, int(f.size() / 4)) << c.name;

        c.material.diffuse = glm::vec3(1.0f);  // the worst case: white everywhere
        if (c.material.sheenColor != glm::vec3(0.0f)) c.material.sheenColor = glm::vec3(1.0f);
        probe.setMaterial(c.material);
        std::vector<float> angles = incidentAngles();
        angles.push_back(89.0f);
        for (float angle : angles) {
            std::vector<ProbeSample> samples =
                probe.sample(incidentDirection(angle), 1.5f, 6000, kSampleCount);
            glm::dvec3 sum(0.0), squares(0.0);
            for (const ProbeSample& s : samples) {
                glm::dvec3 w = s.ok() ? glm::dvec3(s.weight) : glm::dvec3(0.0);
                sum += w;
                squares += w * w;
            }
            const double n = double(samples.size());
            glm::dvec3 mean = sum / n,
                       se = glm::sqrt(glm::max(squares / n - mean * mean, glm::dvec3(0.0)) / n);
            std::printf("  %-42s theta %4.1f albedo %.4f +- %.1e\n", c.name.c_str(), angle, mean.x, se.x);
            for (int ch = 0; ch < 3; ++ch)
                EXPECT_LE(mean[ch], 1.0 + 5.0 * se[ch] + 1e-6) << c.name << " " << angle;
            EXPECT_GT(mean.x, 0.3) << c.name << " " << angle
                                   << ": a white material reflects most of the light";
        }
    }
}

// A smooth coat is a mirror of reflectance c F(cos_o; 1.5): its delta samples' mean weight is that, as
// the Fresnel equations give it here, within five standard errors.
TEST(GltfMaterialExtensions, SmoothClearcoatMirrorsWithItsFresnelReflectance) {
    BsdfProbe& probe = bsdfProbe();
    Material m = clearcoated(0.0f, 0.5f, 0.6f, 0.0f);
    probe.setMaterial(m);
    for (float angle : {0.0f, 60.0f, 85.0f}) {
        const glm::vec3 wo = incidentDirection(angle);
        std::vector<ProbeSample> samples = probe.sample(wo, 1.5f, 6100, kSampleCount);
        double sum = 0.0, squares = 0.0;
        for (const ProbeSample& s : samples) {
            double w = s.ok() && s.delta() ? double(s.weight.x) : 0.0;
            sum += w;
            squares += w * w;
        }
        const double n = double(samples.size()), mean = sum / n;
        const double se = std::sqrt(std::max(squares / n - mean * mean, 0.0) / n);
        const double expected = 0.6 * fresnelDielectricReference(double(wo.z), 1.5);
        EXPECT_NEAR(mean, expected, 5.0 * se + 1e-6) << "theta_o " << angle;
    }
}

// A clearcoated or sheened sphere on a floor under a lamp and a sky: nee (light and BSDF samples weighed
// by MIS), bsdf (BSDF samples alone) and bdpt (every join) agree block by block, for a rough and a smooth
// coat and a sheen. What this catches beyond the probe: an integrator that treats a layer differently (a
// delta test that misses the smooth coat, a bdpt vertex that loses the layer), and whole-image MIS bias.
TEST(GltfMaterialExtensions, LayersRenderTheSameWithEveryIntegrator) {
    ensureGlContext();
    const std::pair<const char*, Material> materials[] = {
        {"coat roughness 0.2", clearcoated(0.0f, 0.5f, 1.0f, 0.2f)},
        {"smooth coat", clearcoated(0.0f, 0.5f, 1.0f, 0.0f)},
        {"sheen", sheened(makeMetallicRoughness(0.0f, 0.5f), glm::vec3(0.2f, 0.3f, 0.9f), 0.4f)}};
    for (const auto& [name, material] : materials) {
        Material coated = material;
        coated.diffuse = glm::vec3(0.6f, 0.1f, 0.1f);
        Scene scene = sphereOnAFloor(coated);
        const Camera camera = sphereCamera();
        Renderer renderer(scene, testShaders());
        const std::string what = name;
        Accumulation nee = renderScene(renderer, camera, Integrator::Nee, 32, 256, 4, 11);
        Accumulation bsdf = renderScene(renderer, camera, Integrator::Bsdf, 32, 256, 4, 12);
        Accumulation bdpt = renderScene(renderer, camera, Integrator::Bdpt, 32, 256, 4, 13);
        expectSameImage(nee, bsdf, 4, 0.02f, "nee vs bsdf, " + what);
        expectSameImage(nee, bdpt, 4, 0.02f, "nee vs bdpt, " + what);
    }
}

}  // namespace
}  // namespace fp::test
