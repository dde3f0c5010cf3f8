#pragma once
// Shared pieces of the BSDF tests (bsdf_*_test.cpp): a probe that runs the functions of
// glsl/common/bsdf.glsl fragment by fragment through glsl/tests/bsdf_probe.frag.glsl, the materials
// under test, the chi-square goodness-of-fit machinery and double-precision GGX formulas for reference
// values. The statistical design follows Mitsuba's BSDF tests (Jakob et al., Mitsuba 3,
// src/python/python/chi2.py): histogram sampled directions, integrate the density over the same bins,
// pool sparse bins, and compare with Pearson's chi-square at a significance corrected for the number of
// tests (Bonferroni here; Mitsuba uses the nearly identical Sidak correction).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/error.h"
#include "gl/gl.h"
#include "gl/program.h"
#include "gl/shader_source.h"
#include "gpu/layout_defines.h"
#include "pack/layout.h"
#include "pack/pack.h"
#include "render_test_util.h"
#include "scene/scene.h"

namespace fp::test {

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------------
// Directions in the local shading frame (normal +z), as bsdf.glsl uses them.

// The incident direction wo at polar angle thetaDeg. Its azimuth is not 0 so that nothing the tests
// see lines up with the histogram's bin edges by accident.
inline glm::vec3 incidentDirection(float thetaDeg) {
    const double theta = double(thetaDeg) * kPi / 180.0, phi = 0.3;
    return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                     float(std::cos(theta)));
}

// The angles every sampling test runs at: normal incidence (the special case of the visible-normal
// sampler's frame), an oblique one, and a grazing one where shadowing and Fresnel matter most.
inline const std::vector<float>& incidentAngles() {
    static const std::vector<float> angles = {0.0f, 45.0f, 80.0f};
    return angles;
}

// The same direction seen from the other side of the surface: the mirror image in the tangent plane.
// An isotropic BSDF is unchanged by this reflection, so it maps the frame of one side onto the frame
// surface.glsl builds on the other.
inline glm::vec3 flipSide(glm::vec3 w) {
    return glm::vec3(w.x, w.y, -w.z);
}

// n directions spread evenly over the whole sphere: the spherical Fibonacci lattice (Swinbank & Purser
// 2006), z uniform in (-1, 1) and the azimuth advancing by the golden angle. They reach the tails and
// grazing angles that sampled directions rarely visit.
inline std::vector<glm::vec3> sphereLattice(int n) {
    const double goldenAngle = kPi * (3.0 - std::sqrt(5.0));
    std::vector<glm::vec3> out;
    out.reserve(size_t(n));
    for (int k = 0; k < n; ++k) {
        double z = 1.0 - (2.0 * k + 1.0) / n, r = std::sqrt(1.0 - z * z), phi = goldenAngle * k;
        out.emplace_back(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
    }
    return out;
}

// ---------------------------------------------------------------------------------------------------
// The GLSL probe.

struct ProbeSample {
    glm::vec3 wi{0.0f};
    float pdf = 0.0f;
    glm::vec3 weight{0.0f};
    int flag = 0;  // 0: bsdfSample returned false; 1: a non-delta sample; 2: a delta sample
    bool ok() const { return flag != 0; }
    bool delta() const { return flag == 2; }
};

struct EvalQuery {
    glm::vec3 wo{0.0f, 0.0f, 1.0f};
    float eta = 1.0f;
    glm::vec3 wi{0.0f, 0.0f, 1.0f};
};

struct ProbeEval {
    glm::vec3 value{0.0f};  // bsdfEval: f(wo, wi) |cos(theta_i)|
    float pdf = 0.0f;       // bsdfPdf
};

class BsdfProbe {
  public:
    static constexpr int kWidth = 256;  // fragments per row of every pass

    // The layout's defines, and the sampler rng.glsl needs to compile (the probe draws its own numbers).
    static ShaderDefines probeDefines() {
        ShaderDefines defines = layout::layoutDefines();
        defines.emplace_back("SAMPLER", "0");
        return defines;
    }

    explicit BsdfProbe(const ShaderLibrary& shaders)
        : program_(shaders, "passes/fullscreen.vert.glsl", "tests/bsdf_probe.frag.glsl", probeDefines()) {
        // Units of our own at the top of the range, so that no test's renderer loses a binding.
        firstUnit_ = glInteger(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS) -
                     4;  // materials, wo and eta, wi, and a spare one for creating textures
        glActiveTexture(GLenum(GL_TEXTURE0 + firstUnit_));
        glGenBuffers(1, &materialBuffer_);
        glBindBuffer(GL_TEXTURE_BUFFER, materialBuffer_);
        glBufferData(GL_TEXTURE_BUFFER, sizeof(glm::vec4) * layout::kMaterialTexels, nullptr,
                     GL_DYNAMIC_DRAW);
        glGenTextures(1, &materialTexture_);
        glBindTexture(GL_TEXTURE_BUFFER, materialTexture_);
        glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, materialBuffer_);
        glGenTextures(2, inputs_);
        glGenTextures(2, outputs_);
        glGenFramebuffers(1, &framebuffer_);
        glGenVertexArrays(1, &vertexArray_);
        program_.use();
        // Every sampler the included files declare gets a unit of its own: a draw fails when two active
        // samplers of different types share a unit, and which samplers stay active is the compiler's
        // choice.
        const char* sceneSamplers[] = {"uTriangles", "uNormals", "uNodes", "uLights"};
        for (int i = 0; i < 4; ++i) program_.set(sceneSamplers[i], firstUnit_ - 1 - i);
        program_.set("uMaterials", firstUnit_);
        program_.set("uWoEta", firstUnit_ + 1);
        program_.set("uWi", firstUnit_ + 2);
    }
    ~BsdfProbe() {
        glDeleteVertexArrays(1, &vertexArray_);
        glDeleteFramebuffers(1, &framebuffer_);
        glDeleteTextures(2, outputs_);
        glDeleteTextures(2, inputs_);
        glDeleteTextures(1, &materialTexture_);
        glDeleteBuffers(1, &materialBuffer_);
    }
    BsdfProbe(const BsdfProbe&) = delete;
    BsdfProbe& operator=(const BsdfProbe&) = delete;

    // The material under test, packed as src/pack/pack.cpp packs it; the fourth texel's w, the Cauchy
    // coefficient of a dispersive glass, is 0: one index for all wavelengths.
    void setMaterial(const Material& m) {
        Material packed = m;
        packed.abbeNumber = 0.0f;
        const std::array<glm::vec4, layout::kMaterialTexels> texels = packMaterial(packed);
        glBindBuffer(GL_TEXTURE_BUFFER, materialBuffer_);
        glBufferSubData(GL_TEXTURE_BUFFER, 0, sizeof(texels), texels.data());
    }

    // `count` samples of bsdfSample(material, wo, u, eta), sample k from fragment (k % kWidth, k / kWidth).
    std::vector<ProbeSample> sample(glm::vec3 wo, float eta, uint32_t seed, int count) {
        program_.use();
        program_.set("uMode", 0);
        program_.set("uSeed", seed);
        program_.set("uWo", wo);
        program_.set("uEta", eta);
        std::vector<glm::vec4> a, b;
        draw(count, a, b);
        std::vector<ProbeSample> out(static_cast<size_t>(count));
        for (size_t k = 0; k < out.size(); ++k)
            out[k] = {glm::vec3(a[k]), a[k].w, glm::vec3(b[k]), int(b[k].w)};
        return out;
    }

    // bsdfEval and bsdfPdf for each query, in draws of at most kMaxRows rows.
    std::vector<ProbeEval> eval(const std::vector<EvalQuery>& queries) {
        const size_t chunk = size_t(kWidth) * kMaxRows;
        if (queries.size() <= chunk) return evalChunk(queries);
        std::vector<ProbeEval> out;
        out.reserve(queries.size());
        for (size_t first = 0; first < queries.size(); first += chunk) {
            std::vector<EvalQuery> part(queries.begin() + long(first),
                                        queries.begin() + long(std::min(queries.size(), first + chunk)));
            std::vector<ProbeEval> values = evalChunk(part);
            out.insert(out.end(), values.begin(), values.end());
        }
        return out;
    }

  private:
    static constexpr int kMaxRows = 4096;  // within every GL 4.1 implementation's GL_MAX_TEXTURE_SIZE

    std::vector<ProbeEval> evalChunk(const std::vector<EvalQuery>& queries) {
        int count = int(queries.size());
        int rows = (count + kWidth - 1) / kWidth;
        std::vector<glm::vec4> woEta(size_t(rows) * kWidth, glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));
        std::vector<glm::vec4> wi(woEta.size(), glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
        for (size_t k = 0; k < queries.size(); ++k) {
            woEta[k] = glm::vec4(queries[k].wo, queries[k].eta);
            wi[k] = glm::vec4(queries[k].wi, 0.0f);
        }
        for (int i = 0; i < 2; ++i) {
            glActiveTexture(GLenum(GL_TEXTURE0 + firstUnit_ + 1 + i));
            glBindTexture(GL_TEXTURE_2D, inputs_[i]);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kWidth, rows, 0, GL_RGBA, GL_FLOAT,
                         (i == 0 ? woEta : wi).data());
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // complete without mipmaps
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        program_.use();
        program_.set("uMode", 1);
        std::vector<glm::vec4> a, b;
        draw(count, a, b);
        std::vector<ProbeEval> out(queries.size());
        for (size_t k = 0; k < out.size(); ++k) out[k] = {glm::vec3(a[k]), a[k].w};
        return out;
    }

    // One full-viewport draw of ceil(count / kWidth) rows; returns both attachments, row by row.
    void draw(int count, std::vector<glm::vec4>& out0, std::vector<glm::vec4>& out1) {
        int rows = (count + kWidth - 1) / kWidth;
        glActiveTexture(GLenum(GL_TEXTURE0 + firstUnit_ + 3));  // a unit nobody samples
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        for (int i = 0; i < 2; ++i) {
            glBindTexture(GL_TEXTURE_2D, outputs_[i]);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kWidth, rows, 0, GL_RGBA, GL_FLOAT, nullptr);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D,
                                   outputs_[i], 0);
        }
        const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glDrawBuffers(2, buffers);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Error("BSDF probe: incomplete framebuffer");
        glActiveTexture(GLenum(GL_TEXTURE0 + firstUnit_));
        glBindTexture(GL_TEXTURE_BUFFER, materialTexture_);
        for (int i = 0; i < 2; ++i) {
            glActiveTexture(GLenum(GL_TEXTURE0 + firstUnit_ + 1 + i));
            glBindTexture(GL_TEXTURE_2D, inputs_[i]);
        }
        glActiveTexture(GLenum(GL_TEXTURE0 + firstUnit_ + 3));
        glDisable(GL_BLEND);
        glDisable(GL_SCISSOR_TEST);
        glViewport(0, 0, kWidth, rows);
        glBindVertexArray(vertexArray_);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        out0.assign(size_t(rows) * kWidth, glm::vec4(0.0f));
        out1.assign(out0.size(), glm::vec4(0.0f));
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glReadPixels(0, 0, kWidth, rows, GL_RGBA, GL_FLOAT, out0.data());
        glReadBuffer(GL_COLOR_ATTACHMENT1);
        glReadPixels(0, 0, kWidth, rows, GL_RGBA, GL_FLOAT, out1.data());
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        if (GLenum e = glGetError(); e != GL_NO_ERROR)
            throw Error("BSDF probe: GL error " + std::to_string(e));
    }

    Program program_;
    int firstUnit_ = 0;
    GLuint materialBuffer_ = 0, materialTexture_ = 0, framebuffer_ = 0, vertexArray_ = 0;
    GLuint inputs_[2] = {0, 0}, outputs_[2] = {0, 0};
};

// One probe per test binary, created after (and so destroyed before) the GL context, from the test
// shaders (FP_RENDER_TEST_SHADERS: a candidate change to bsdf.glsl can be tested without rebuilding).
inline BsdfProbe& bsdfProbe() {
    ensureGlContext();
    static BsdfProbe probe(testShaders());
    return probe;
}

// ---------------------------------------------------------------------------------------------------
// The materials under test: every model with a non-delta lobe, at the roughness values the issue asks
// for. `eta` is n_transmitted / n_incident as seen from wo's side (surface.glsl): ior entering glass,
// 1 / ior leaving it.

struct BsdfCase {
    std::string name;
    Material material;
    float eta = 1.0f;
};

inline Material makeMaterial(MaterialType type, float roughness) {
    Material m;
    m.type = type;
    m.roughness = roughness;
    m.ior = 1.5f;
    switch (type) {
        case MaterialType::Diffuse:
            m.diffuse = glm::vec3(0.8f, 0.5f, 0.2f);
            break;
        case MaterialType::Conductor:
            m.specular = glm::vec3(0.9f, 0.6f, 0.3f);
            break;
        case MaterialType::Plastic:
            m.diffuse = glm::vec3(0.5f);
            m.specular = glm::vec3(1.0f);
            break;
        case MaterialType::Dielectric:
            m.transmission = glm::vec3(1.0f, 0.8f, 0.6f);
            break;
        case MaterialType::MetallicRoughness:
            m.diffuse = glm::vec3(0.9f, 0.6f, 0.3f);  // the base colour: the metal's F0, the base's albedo
            m.metallic = 0.5f;
            break;
        case MaterialType::Unlit:
            m.diffuse = glm::vec3(0.9f, 0.6f, 0.3f);  // what it shows; it scatters nothing
            break;
    }
    return m;
}

// glTF's metallic-roughness model at (metallic, roughness).
inline Material makeMetallicRoughness(float metallic, float roughness) {
    Material m = makeMaterial(MaterialType::MetallicRoughness, roughness);
    m.metallic = metallic;
    return m;
}

inline std::vector<BsdfCase> samplingCases() {
    auto name = [](const char* model, float roughness, const char* extra = "") {
        std::ostringstream s;
        s << model << " r=" << roughness << extra;
        return s.str();
    };
    std::vector<BsdfCase> cases;
    cases.push_back({"diffuse", makeMaterial(MaterialType::Diffuse, 0.0f), 1.0f});
    for (float r : {0.2f, 0.5f, 0.9f})
        cases.push_back({name("conductor", r), makeMaterial(MaterialType::Conductor, r), 1.0f});
    for (float r : {0.0f, 0.3f})
        cases.push_back({name("plastic", r), makeMaterial(MaterialType::Plastic, r), 1.5f});
    for (float r : {0.3f, 0.7f}) {
        cases.push_back({name("dielectric", r, " eta=1.5"), makeMaterial(MaterialType::Dielectric, r), 1.5f});
        cases.push_back(
            {name("dielectric", r, " eta=1/1.5"), makeMaterial(MaterialType::Dielectric, r), 1.0f / 1.5f});
    }
    // The blend at several (metallic, roughness); metallic 0 and 1 are the plastic and the conductor
    // (bsdf_metallic_roughness_test.cpp), metallic 0.5 with roughness 0 mixes two delta lobes with the base.
    for (auto [metallic, r] : {std::pair{0.5f, 0.3f}, {0.2f, 0.6f}, {0.8f, 0.2f}, {0.5f, 0.0f}}) {
        std::ostringstream what;
        what << "metallic-roughness m=" << metallic << " r=" << r;
        cases.push_back({what.str(), makeMetallicRoughness(metallic, r), 1.5f});
    }
    return cases;
}

inline std::string describe(const BsdfCase& c, float thetaDeg) {
    std::ostringstream s;
    s << c.name << ", theta_o=" << thetaDeg;
    return s.str();
}

// Samples per sampling test, and a seed per (case, angle) so that the tests are repeatable.
constexpr int kSampleCount = BsdfProbe::kWidth * 512;
inline uint32_t caseSeed(size_t caseIndex, size_t angleIndex) {
    return uint32_t(1000 + 17 * caseIndex + angleIndex);
}

// ---------------------------------------------------------------------------------------------------
// The chi-square distribution.

// The regularized upper incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a): its power series
// for x < a + 1 and Legendre's continued fraction, evaluated with the modified Lentz method, above
// (Abramowitz & Stegun, section 6.5; Press et al., Numerical Recipes, 3rd ed., section 6.2).
inline double regularizedGammaQ(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double logPrefactor = -x + a * std::log(x) - std::lgamma(a);
    const double eps = 1e-15;
    if (x < a + 1.0) {
        // P(a, x) = e^-x x^a / Gamma(a) * sum_n x^n / (a (a + 1) ... (a + n)).
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 10000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::abs(term) < std::abs(sum) * eps) break;
        }
        return std::max(0.0, 1.0 - sum * std::exp(logPrefactor));
    }
    // Q(a, x) = e^-x x^a / Gamma(a) * 1 / (x + 1 - a - 1 (1 - a) / (x + 3 - a - 2 (2 - a) / (x + 5 - a -
    // ...))).
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < eps) break;
    }
    return std::exp(logPrefactor) * h;
}

// P(X >= statistic) for X chi-square distributed with `dof` degrees of freedom.
inline double chiSquarePValue(double statistic, int dof) {
    return regularizedGammaQ(0.5 * dof, 0.5 * statistic);
}

// ---------------------------------------------------------------------------------------------------
// The goodness-of-fit test of one (material, wo).

// Bins over the whole sphere, uniform in (cos(theta), phi): the map (cos(theta), phi) -> direction
// preserves area (Archimedes' hat-box theorem, which uniform sphere sampling rests on: pbrt-v4 A.5.2),
// so every bin has the same solid angle.
constexpr int kCosBins = 20, kPhiBins = 40;
constexpr int kBins = kCosBins * kPhiBins;

inline int binOf(glm::vec3 w) {
    double z = std::clamp(double(w.z), -1.0, 1.0);
    int i = std::min(int((z + 1.0) * 0.5 * kCosBins), kCosBins - 1);
    double phi = std::atan2(double(w.y), double(w.x));
    if (phi < 0.0) phi += 2.0 * kPi;
    int j = std::min(int(phi / (2.0 * kPi) * kPhiBins), kPhiBins - 1);
    return i * kPhiBins + j;
}

struct BinIntegral {
    double value = 0.0;
    bool straddlesZero = false;  // the pdf is 0 at some of the bin's points and not at others
};

// The integral of bsdfPdf over each bin listed, by the midpoint rule on n x n points per bin, uniform in
// (theta, phi) with the weight sin(theta) dtheta dphi. Uniform in theta rather than in cos(theta), so
// that the points do not thin out toward the poles, where the narrow lobes of near-normal reflection
// and refraction live.
inline std::vector<BinIntegral> integratePdf(BsdfProbe& probe, glm::vec3 wo, float eta,
                                             const std::vector<int>& bins, int n) {
    std::vector<EvalQuery> queries;
    std::vector<double> weights;
    queries.reserve(bins.size() * size_t(n * n));
    weights.reserve(queries.capacity());
    const double dphi = 2.0 * kPi / (kPhiBins * n);
    for (int bin : bins) {
        int i = bin / kPhiBins, j = bin % kPhiBins;
        double theta0 = std::acos(-1.0 + 2.0 * (i + 1) / kCosBins),
               theta1 = std::acos(-1.0 + 2.0 * i / kCosBins);
        double dtheta = (theta1 - theta0) / n;
        for (int a = 0; a < n; ++a) {
            double theta = theta0 + (a + 0.5) * dtheta;
            double st = std::sin(theta), ct = std::cos(theta);
            for (int b = 0; b < n; ++b) {
                double phi = (j * n + b + 0.5) * dphi;
                queries.push_back(
                    {wo, eta, glm::vec3(float(st * std::cos(phi)), float(st * std::sin(phi)), float(ct))});
                weights.push_back(st * dtheta * dphi);
            }
        }
    }
    std::vector<ProbeEval> values = probe.eval(queries);
    std::vector<BinIntegral> integrals(bins.size());
    const size_t perBin = size_t(n * n);
    for (size_t k = 0; k < bins.size(); ++k) {
        int zeros = 0;
        for (size_t p = k * perBin; p < (k + 1) * perBin; ++p) {
            integrals[k].value += double(values[p].pdf) * weights[p];
            zeros += values[p].pdf == 0.0f;
        }
        integrals[k].straddlesZero = zeros > 0 && zeros < int(perBin);
    }
    return integrals;
}

// The integral of bsdfPdf over every bin, to an accuracy that cannot sway a test of `sampleCount`
// samples. On a smooth integrand the midpoint rule's error falls as h^2, so (I_2n - I_n) / 3 estimates
// the error of I_2n and (4 I_2n - I_n) / 3 is better still (Richardson extrapolation, the first step of
// Romberg's method). Each bin's rule is refined (16, 32, ... 512 points per dimension) until that error
// estimate is below a twentieth of the bin's sampling noise, sqrt(expected count) / N. The densities
// also jump to 0 along curves that cut through bins (refraction would need a microfacet normal below
// the horizon beyond them), where the rule converges only as h and erratically and extrapolation does
// not apply: bins that straddle such a jump and expect a sample or more get the finest plain rule.
inline std::vector<double> integratePdfOverBins(BsdfProbe& probe, glm::vec3 wo, float eta, int sampleCount) {
    constexpr int kCoarsest = 16, kJumpMinimum = 128, kFinest = 512;
    std::vector<int> pending(kBins);
    for (int b = 0; b < kBins; ++b) pending[size_t(b)] = b;
    std::vector<BinIntegral> previous = integratePdf(probe, wo, eta, pending, kCoarsest);
    std::vector<double> out(previous.size());
    for (int n = 2 * kCoarsest; n <= kFinest && !pending.empty(); n *= 2) {
        std::vector<BinIntegral> fine = integratePdf(probe, wo, eta, pending, n);
        std::vector<int> next;
        for (size_t k = 0; k < pending.size(); ++k) {
            size_t b = size_t(pending[k]);
            double error = (fine[k].value - previous[b].value) / 3.0;
            double noise = std::sqrt(std::max(fine[k].value, 1.0 / sampleCount) / sampleCount);
            bool jump =
                (previous[b].straddlesZero || fine[k].straddlesZero) && fine[k].value * sampleCount >= 1.0;
            if (jump) error = fine[k].value - previous[b].value;  // O(h): the difference is the error's size
            out[b] = jump ? fine[k].value : fine[k].value + error;
            if ((jump && n < kJumpMinimum) || std::abs(error) > 0.05 * noise) next.push_back(pending[k]);
            previous[b] = fine[k];
        }
        pending = std::move(next);
    }
    return out;
}

struct PearsonResult {
    double statistic = 0.0;
    int dof = 0;
    double pValue = 1.0;
};

// Pearson's statistic of (expected, observed) cells whose counts sum to the same total. As Mitsuba
// does, the cells expected to hold fewer than 5 samples are pooled (smallest first, until the pool
// expects 5), which keeps the statistic close to its chi-square limit (Cochran 1952). Unlike Mitsuba, a
// sample in a cell of expectation 0 is not an outright failure: the expectations come from a finite
// set of points, which can miss a sliver of support at a cell's edge; pooled, such a cell still counts.
inline PearsonResult pearsonChiSquare(std::vector<std::pair<double, double>> cells) {
    std::sort(cells.begin(), cells.end());
    std::vector<std::pair<double, double>> pooled;
    std::pair<double, double> pool{0.0, 0.0};
    for (const auto& cell : cells) {
        if (pool.first < 5.0) {
            pool.first += cell.first;
            pool.second += cell.second;
        } else {
            pooled.push_back(cell);
        }
    }
    pooled.push_back(pool);
    PearsonResult r;
    for (const auto& [expected, observed] : pooled) {
        double d = observed - expected;
        r.statistic += expected > 0.0 ? d * d / expected : (observed > 0.0 ? HUGE_VAL : 0.0);
    }
    r.dof = int(pooled.size()) - 1;                                  // one constraint: the totals agree
    if (!std::isfinite(r.statistic)) return {HUGE_VAL, r.dof, 0.0};  // NaN densities fail too
    r.pValue = r.dof > 0 ? chiSquarePValue(r.statistic, r.dof) : 1.0;
    return r;
}

struct ChiSquareResult : PearsonResult {
    double pdfIntegral = 0.0;       // of bsdfPdf over the sphere
    double nonDeltaFraction = 0.0;  // of the samples: successful and not delta
};

// The goodness-of-fit test of the non-delta sampled directions against bsdfPdf. A bin's expected count
// is the number of non-delta samples times the bin's share of the pdf's integral, so this tests the
// shape of the density; its total mass, which must equal the fraction of successful non-delta samples
// (failed and delta samples have no density), is returned for a separate check.
inline ChiSquareResult chiSquareTest(BsdfProbe& probe, const std::vector<ProbeSample>& samples, glm::vec3 wo,
                                     float eta) {
    ChiSquareResult result;
    std::vector<double> pdfMass = integratePdfOverBins(probe, wo, eta, int(samples.size()));
    std::vector<double> observed(pdfMass.size(), 0.0);
    int nonDelta = 0;
    for (const ProbeSample& s : samples)
        if (s.ok() && !s.delta()) {
            observed[size_t(binOf(s.wi))] += 1.0;
            ++nonDelta;
        }
    for (double m : pdfMass) result.pdfIntegral += m;
    result.nonDeltaFraction = double(nonDelta) / double(samples.size());
    if (nonDelta == 0 || result.pdfIntegral <= 0.0) return result;
    std::vector<std::pair<double, double>> cells;
    for (size_t b = 0; b < pdfMass.size(); ++b)
        cells.emplace_back(pdfMass[b] / result.pdfIntegral * nonDelta, observed[b]);
    static_cast<PearsonResult&>(result) = pearsonChiSquare(std::move(cells));
    return result;
}

// ---------------------------------------------------------------------------------------------------
// GGX in double precision, written from the published formulas (not from bsdf.glsl), for reference
// values. Isotropic Trowbridge-Reitz with alpha = roughness^2, Smith height-correlated masking-shadowing
// (pbrt-v4 section 9.6; Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based
// BRDFs", JCGT 3(2)).

inline double ggxDistribution(double cosThetaM, double alpha) {
    double c2 = cosThetaM * cosThetaM, s2 = std::max(0.0, 1.0 - c2), a2 = alpha * alpha;
    double d = s2 + a2 * c2;  // = cos^2 (tan^2 + alpha^2)
    return a2 / (kPi * d * d);
}

inline double ggxLambda(double cosTheta, double alpha) {
    double c2 = cosTheta * cosTheta;
    double tan2 = std::max(0.0, 1.0 - c2) / c2;
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
}

inline double ggxG2(double cosO, double cosI, double alpha) {
    return 1.0 / (1.0 + ggxLambda(cosO, alpha) + ggxLambda(cosI, alpha));
}

// The integral over the directions wi with cos(theta_i) >= zMin of a function that is even in wi.y
// (wo lies in the xz plane), by the midpoint rule on n x n points per hemisphere: in phi over [0, pi]
// (then doubled), and in the upper hemisphere in t with cos(theta) = 1 - t^2, t in [0, 1], which crowds
// points toward the pole where narrow lobes at near-normal incidence live; below the horizon, uniform
// in cos(theta) from zMin, so that a cut at zMin is a boundary of the rule rather than a jump inside it.
// Two rules, n and 2n, are combined by Richardson extrapolation (the midpoint rule's error is O(h^2) on
// smooth integrands).
template <class Function>
double integrateOverSphere(const Function& f, int n, double zMin = 0.0) {
    auto rule = [&f, zMin](int m) {
        const double dphi = kPi / m;
        double sum = 0.0;
        auto ring = [&](double z, double dz) {
            double r = std::sqrt(std::max(0.0, 1.0 - z * z));
            for (int b = 0; b < m; ++b) {
                double phi = (b + 0.5) * dphi;
                sum += f(glm::dvec3(r * std::cos(phi), r * std::sin(phi), z)) * dz * dphi;
            }
        };
        for (int a = 0; a < m; ++a) {
            double t = (a + 0.5) / m;
            ring(1.0 - t * t, 2.0 * t / m);
            if (zMin < 0.0) ring(zMin * (1.0 - t), -zMin / m);
        }
        return 2.0 * sum;
    };
    double coarse = rule(n), fine = rule(2 * n);
    return fine + (fine - coarse) / 3.0;
}

// The incident direction of the albedo tables: polar angle acos(cosThetaO) in the xz plane.
inline glm::dvec3 incidentInXzPlane(double cosThetaO) {
    return glm::dvec3(std::sqrt(std::max(0.0, 1.0 - cosThetaO * cosThetaO)), 0.0, cosThetaO);
}

// Directional albedo E(mu_o) of a GGX conductor with Fresnel 1: the integral over the hemisphere of
// f(wo, wi) cos(theta_i) with f = D(wm) G2(wo, wi) / (4 cos_o cos_i) (Walter et al. 2007, eq. 20).
inline double ggxConductorAlbedo(double cosThetaO, double alpha, int n = 500) {
    const glm::dvec3 wo = incidentInXzPlane(cosThetaO);
    return integrateOverSphere(
        [&](const glm::dvec3& wi) {
            if (wi.z <= 0.0) return 0.0;
            glm::dvec3 wm = glm::normalize(wo + wi);
            return ggxDistribution(wm.z, alpha) * ggxG2(wo.z, wi.z, alpha) / (4.0 * wo.z);
        },
        n);
}

// The "weak white furnace test" of Heitz 2014 (as above): with the masking term G1 alone, the
// microfacet reflection integrates to exactly 1 over the whole sphere of wi, for any roughness and
// wo. It checks D and Lambda (and the quadrature) independently of any BSDF.
inline double ggxWeakWhiteFurnace(double cosThetaO, double alpha, int n = 500) {
    const glm::dvec3 wo = incidentInXzPlane(cosThetaO);
    const double g1 = 1.0 / (1.0 + ggxLambda(wo.z, alpha));
    return integrateOverSphere(
        [&](const glm::dvec3& wi) {
            glm::dvec3 h = wo + wi;
            if (h.z <= 0.0) return 0.0;  // the half vector of a back-facing microfacet: D = 0
            return ggxDistribution(glm::normalize(h).z, alpha) * g1 / (4.0 * wo.z);
        },
        n, -wo.z);  // below cos(theta_i) = -cos(theta_o) the half vector points down
}

// Unpolarised Fresnel reflectance of a dielectric interface, eta = n_transmitted / n_incident: the mean
// of the s and p reflectances of the Fresnel equations (Born & Wolf, Principles of Optics, chapter 1);
// 1 under total internal reflection.
inline double fresnelDielectricReference(double cosI, double eta) {
    double sin2T = (1.0 - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0) return 1.0;
    double cosT = std::sqrt(1.0 - sin2T);
    double rs = (cosI - eta * cosT) / (cosI + eta * cosT), rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return 0.5 * (rs * rs + rp * rp);
}

// Schlick's approximation (Schlick 1994): F = F0 + (1 - F0) (1 - cos)^5.
inline double fresnelSchlickReference(double f0, double cosI) {
    return f0 + (1.0 - f0) * std::pow(1.0 - cosI, 5.0);
}

struct ReferenceValue {
    double value = 0.0;  // f(wo, wi) cos(theta_i), as bsdfEval returns it
    double pdf = 0.0;    // of sampling a visible normal (Heitz 2018) and reflecting: / (4 wo.wm)
};

// The GGX conductor of bsdf.glsl in double precision, for one channel of F0.
inline ReferenceValue ggxConductorReference(glm::dvec3 wo, glm::dvec3 wi, double alpha, double f0) {
    if (wi.z <= 0.0) return {};
    glm::dvec3 wm = glm::normalize(wo + wi);
    double cosOm = glm::dot(wo, wm), d = ggxDistribution(wm.z, alpha);
    double f = d * ggxG2(wo.z, wi.z, alpha) * fresnelSchlickReference(f0, cosOm) / (4.0 * wo.z);
    double g1 = 1.0 / (1.0 + ggxLambda(wo.z, alpha));
    return {f, g1 * d / (4.0 * wo.z)};  // G1 (wo.wm) D / wo.z, times the Jacobian 1 / (4 wo.wm)
}

// Heitz 2018, eq. 3: the density of the visible normals seen from wo, D_wo(wm) = G1(wo) <wo.wm> D(wm) /
// cos(theta_o), with the masking G1 = 1 / (1 + Lambda) of the Smith model.
inline double ggxVisibleNormalDensity(glm::dvec3 wo, glm::dvec3 wm, double alpha) {
    double g1 = 1.0 / (1.0 + ggxLambda(wo.z, alpha));
    return g1 * std::max(0.0, glm::dot(wo, wm)) * ggxDistribution(wm.z, alpha) / wo.z;
}

// A rough dielectric interface in double precision, from Walter et al. 2007 ("Microfacet Models for
// Refraction through Rough Surfaces", EGSR), for one channel of the transmission tint `tint`. wo is on
// the side of index n_o = 1, wi reflected (wi.z > 0) or refracted into the side of index n_i = eta.
// Reflection (eq. 20) f_r = F D G / (4 |cos_o| |cos_i|) with the half vector h_r = wo + wi (eq. 13);
// refraction (eq. 21) f_t = |wi.h| |wo.h| / (|cos_i| |cos_o|) n_o^2 (1 - F) D G / (n_i wi.h + n_o wo.h)^2
// with h_t = -(n_i wi + n_o wo) (eq. 16). Both half vectors are taken on the +z side; a microfacet that
// faces away from either direction contributes nothing (the chi+ factors of eq. 23). F is the exact
// Fresnel reflectance at wo.h, G the height-correlated Smith term. The density is that of sampling a
// visible normal (Heitz 2018), choosing reflection with probability F, and mapping the normal to wi:
// the Jacobians are 1 / (4 |wo.h|) (eq. 14) and n_i^2 |wi.h| / (n_i wi.h + n_o wo.h)^2 (eq. 17).
inline ReferenceValue ggxDielectricReference(glm::dvec3 wo, glm::dvec3 wi, double alpha, double eta,
                                             double tint) {
    if (wi.z == 0.0) return {};
    const bool reflection = wi.z > 0.0;
    glm::dvec3 h = reflection ? wo + wi : -(eta * wi + wo);
    if (glm::dot(h, h) == 0.0) return {};
    h = glm::normalize(h);
    if (h.z < 0.0) h = -h;
    const double cosOh = glm::dot(wo, h), cosIh = glm::dot(wi, h);
    if (cosOh * wo.z <= 0.0 || cosIh * wi.z <= 0.0) return {};
    const double F = fresnelDielectricReference(cosOh, eta);
    const double DG = ggxDistribution(h.z, alpha) * ggxG2(wo.z, wi.z, alpha);
    const double visible = ggxVisibleNormalDensity(wo, h, alpha);
    if (reflection) return {F * DG / (4.0 * wo.z), visible * F / (4.0 * cosOh)};
    const double denominator = eta * cosIh + cosOh;
    const double ft = std::abs(cosIh) * std::abs(cosOh) / (std::abs(wi.z) * wo.z) * (1.0 - F) * DG /
                      (denominator * denominator);
    return {tint * ft * std::abs(wi.z),
            visible * (1.0 - F) * eta * eta * std::abs(cosIh) / (denominator * denominator)};
}

// The plastic of bsdf.glsl, as its header describes it, in double precision and one channel: a GGX
// dielectric coat of index ior reflecting Ks D G F(wo.h) / (4 cos_o cos_i) (Walter et al. 2007, eq. 20),
// over a Lambertian base Kd / pi seen through the coat on the way in and out, attenuated by the Fresnel
// transmittance at both (1 - F(cos_o)) (1 - F(cos_i)). A smooth coat (roughness below kSmooth) has no
// rough lobe: its mirror reflection is a delta that bsdfEval does not see.
inline double plasticReference(glm::dvec3 wo, glm::dvec3 wi, double alpha, bool roughCoat, double ior,
                               double kd, double ks) {
    if (wi.z <= 0.0) return 0.0;
    double f = kd / kPi * (1.0 - fresnelDielectricReference(wo.z, ior)) *
               (1.0 - fresnelDielectricReference(wi.z, ior));
    if (roughCoat) {
        glm::dvec3 h = glm::normalize(wo + wi);
        f += ks * ggxDistribution(h.z, alpha) * ggxG2(wo.z, wi.z, alpha) *
             fresnelDielectricReference(glm::dot(wo, h), ior) / (4.0 * wo.z * wi.z);
    }
    return f * wi.z;
}

// glTF's metallic-roughness model as bsdf.glsl's header describes it, in double precision and one
// channel: metallic times the GGX conductor with F0 = base, plus (1 - metallic) times the plastic with a
// white coat of index ior over the Lambertian base.
inline double metallicRoughnessReference(glm::dvec3 wo, glm::dvec3 wi, double alpha, bool rough, double ior,
                                         double base, double metallic) {
    double conductor = rough ? ggxConductorReference(wo, wi, alpha, base).value : 0.0;
    return metallic * conductor + (1.0 - metallic) * plasticReference(wo, wi, alpha, rough, ior, base, 1.0);
}

// The density of choosing GGX reflection from wo: a visible normal, then the Jacobian 1 / (4 wo.h).
inline double ggxReflectionDensity(glm::dvec3 wo, glm::dvec3 wi, double alpha) {
    if (wi.z <= 0.0) return 0.0;
    glm::dvec3 h = glm::normalize(wo + wi);
    return ggxVisibleNormalDensity(wo, h, alpha) / (4.0 * glm::dot(wo, h));
}

}  // namespace fp::test
