// The texture maps and coverage of the material model (Material's *Texture fields, alpha, doubleSided;
// glsl/common/textures.glsl, surface.glsl, opacity.glsl), rendered through the real shaders against
// analytic answers and against each other:
// - a normal map turns a flat plane's shading into that of the plane tilted to the mapped normal;
// - BLEND coverage a lets a fraction 1 - a of the light through (camera, bounce and shadow rays), MASK
//   cuts at its cutoff, single-sided surfaces vanish from behind;
// - emission maps and emitters with coverage are seen the same by light sampling and by BSDF sampling;
// - with every map at once, nee, bsdf and bdpt agree.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "render_test_util.h"
#include "surface_maps_scene.h"

namespace fp::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------------
// Normal maps.

// A sky that is black but for one texel, a small sun of radiance kSun: light from (almost) one
// direction, the same at every point of the scene, so that a plane's shading depends only on its
// normal. Texel (40, 9) of 64 x 32 lies at theta = 53.4 degrees from +y, between +x and -z.
constexpr int kSkyWidth = 64, kSkyHeight = 32, kSunX = 40, kSunY = 9;
constexpr float kSun = 200.0f;

Image sunSky() {
    Image sky(kSkyWidth, kSkyHeight);
    sky.at(kSunX, kSunY) = glm::vec3(kSun);
    return sky;
}

// The radiance a Lambertian surface of albedo kd and normal n shows under sunSky(): kd / pi times the
// integral over the sun's texel of L cos(n, w) dw, with dw = 2 pi^2 sin(theta) du dv for the
// equirectangular map (lights.glsl: u = 0.5 + atan2(x, -z) / 2 pi, v = theta / pi), by the midpoint rule.
double sunlitRadiance(glm::dvec3 n, double kd) {
    const int steps = 200;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            double u = (kSunX + (i + 0.5) / steps) / kSkyWidth, v = (kSunY + (j + 0.5) / steps) / kSkyHeight;
            double phi = (u - 0.5) * 2.0 * kPi, theta = v * kPi;
            glm::dvec3 w(std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi));
            double area =
                2.0 * kPi * kPi * std::sin(theta) / (double(kSkyWidth) * kSkyHeight * steps * steps);
            sum += std::max(0.0, glm::dot(n, w)) * area;
        }
    return kd / kPi * kSun * sum;
}

// A 2 x 2 square about the origin with unit normal n, its front face toward n, and the camera that
// sees nothing but it: looking down at it from 4 above.
Scene planeUnderTheSun(glm::vec3 n, const Material& material) {
    Scene scene;
    scene.source = "plane under a sun";
    scene.materials.push_back(material);
    // e1: +x made orthogonal to n; e2 = n x e1, so that (b - a) x (c - a) = 4 e1 x e2 = 4 n.
    glm::vec3 e1 = glm::normalize(glm::vec3(1.0f, 0.0f, 0.0f) - n * n.x), e2 = glm::cross(n, e1);
    appendMappedQuad(scene, -e1 - e2, e1 - e2, e1 + e2, -e1 + e2, 0);
    scene.environment.map = sunSky();
    return scene;
}

Camera lookingDown() {
    Camera c;
    c.eye = glm::vec3(0.0f, 4.0f, -0.3f);
    c.target = glm::vec3(0.0f);
    c.up = glm::vec3(0.0f, 0.0f, 1.0f);
    c.fovY = 18.0f;  // the plane fills the image, tilted or not
    return c;
}

// A flat plane (normal +y) whose normal map holds one tangent-space normal shows what the plane
// geometrically tilted to the mapped normal shows, and both what the integral of the sun's texel gives
// (a Lambertian surface lit from one direction is a function of its shading normal alone; the sun is
// at infinity). The map's frame on the flat plane: tangent +x (u grows along +x), bitangent -z (v grows
// along -z: dp/dv), normal +y. Texel (191, 160, 230) decodes to (0.498, 0.255, 0.804): the normal
// tilted toward +x and -z, toward the sun. With normal scale 0.5 the x and y components halve (glTF's
// normalTexture.scale). What this catches: a map not applied, applied in the wrong frame (tangent or
// bitangent swapped or reversed, the sign of the bitangent ignored), not decoded as 2 c - 1, the scale
// applied to z, or an sRGB decode of a linear map.
TEST(SurfaceMaps, NormalMappedPlaneShowsTheTiltedPlane) {
    ensureGlContext();
    const uint8_t code[3] = {191, 160, 230};
    for (float scale : {1.0f, 0.5f}) {
        glm::dvec3 c(code[0] / 255.0 * 2.0 - 1.0, code[1] / 255.0 * 2.0 - 1.0, code[2] / 255.0 * 2.0 - 1.0);
        c.x *= scale;
        c.y *= scale;
        // Tangent +x, bitangent -z, normal +y.
        const glm::dvec3 mapped = glm::normalize(glm::dvec3(c.x, c.z, -c.y));
        Material lambert = diffuseMaterial(0.8f);
        Material mappedMaterial = lambert;
        mappedMaterial.normalTexture = 0;
        mappedMaterial.normalScale = scale;
        Scene flat = planeUnderTheSun(glm::vec3(0.0f, 1.0f, 0.0f), mappedMaterial);
        flat.textures.push_back(makeTexture("normal", 1, 1, {code[0], code[1], code[2], 255}));
        Scene tilted = planeUnderTheSun(glm::vec3(mapped), lambert);
        Renderer rf(flat, testShaders()), rt(tilted, testShaders());
        Accumulation a = renderScene(rf, lookingDown(), Integrator::Nee, 24, 64, 1, 1);
        Accumulation b = renderScene(rt, lookingDown(), Integrator::Nee, 24, 64, 1, 2);
        const double expected = sunlitRadiance(mapped, 0.8),
                     unmapped = sunlitRadiance(glm::dvec3(0, 1, 0), 0.8);
        ImageEstimate ea = estimate(a), eb = estimate(b);
        std::printf(
            "  scale %.1f: normal-mapped %.5f +- %.5f, tilted %.5f +- %.5f, analytic %.5f (flat %.5f)\n",
            double(scale), double(ea.mean.x), double(ea.standardError.x), double(eb.mean.x),
            double(eb.standardError.x), expected, unmapped);
        ASSERT_GT(std::abs(expected / unmapped - 1.0), 0.1) << "the tilt must matter";
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_NEAR(ea.mean[ch], expected, 5.0 * ea.standardError[ch] + 1e-4 * expected)
                << "scale " << scale;
            EXPECT_NEAR(eb.mean[ch], expected, 5.0 * eb.standardError[ch] + 1e-4 * expected)
                << "scale " << scale;
        }
        EXPECT_LT(ea.standardError.x, 0.01 * expected);
        expectSameImage(a, b, 4, 0.02f, "normal-mapped against tilted, scale " + std::to_string(scale));
    }
}

// ---------------------------------------------------------------------------------------------------
// Coverage and single-sided surfaces.

// A black shell (the box [-2, 2]^3, faces outward) around the camera and a Lambertian sphere of albedo
// 0.5 (radius 0.5, 2 in front of the camera), under a white sky. The shell lets a fraction t of the sky
// through, so the background shows t and the sphere, convex and lit through the shell from every side,
// 0.5 t. shell's material is the shell's; `inward` turns its faces to face the inside.
Scene sphereInAShell(const Material& shell, bool inward = false) {
    Scene scene;
    scene.source = "sphere in a shell";
    scene.materials = {shell, diffuseMaterial(0.5f)};
    appendBox(scene, glm::vec3(-2.0f), glm::vec3(2.0f), 0);
    if (inward)
        for (Triangle& t : scene.triangles) {
            std::swap(t.p[1], t.p[2]);
            glm::vec3 n = glm::normalize(t.geometricNormal());
            t.n = {n, n, n};
        }
    appendSphere(scene, glm::vec3(0.0f, 0.0f, 1.0f), 0.5f, 16, 32, 1, true);
    scene.environment.color = glm::vec3(1.0f);
    return scene;
}

// A pinhole, or with `aperture` a thin lens focused on the sphere.
Camera shellCamera(float aperture = 0.0f) {
    Camera c;
    c.aperture = aperture;
    c.eye = glm::vec3(0.0f, 0.0f, -1.0f);
    c.target = glm::vec3(0.0f, 0.0f, 1.0f);
    c.fovY = 60.0f;
    return c;
}

// In a 32 x 32 image of shellCamera(): the 8 x 8 block at the centre sees only the sphere (its image
// has a radius of about 7 pixels), the four 6 x 6 corner blocks only the shell.
struct ShellImage {
    ImageEstimate sphere, background;
    float backgroundMin = 0.0f, backgroundMax = 0.0f;
};

ShellImage shellImage(Renderer& renderer, Integrator integrator, int spp, float aperture) {
    Accumulation acc = renderScene(renderer, shellCamera(aperture), integrator, 32, spp, 6, 5);
    EXPECT_EQ(acc.droppedSamples(), 0u);
    ShellImage out;
    out.sphere = estimate(acc, 12, 12, 8, 8);
    glm::dvec3 sum(0.0), var(0.0);
    Image mean = acc.mean(), variance = acc.varianceOfMean();
    out.backgroundMin = 1e30f;
    out.backgroundMax = -1e30f;
    for (int y : {0, 26})
        for (int x : {0, 26}) {
            ImageEstimate e = estimate(acc, x, y, 6, 6);
            sum += glm::dvec3(e.mean);
            var += glm::dvec3(e.standardError) * glm::dvec3(e.standardError);
            for (int j = y; j < y + 6; ++j)
                for (int i = x; i < x + 6; ++i) {
                    out.backgroundMin =
                        std::min({out.backgroundMin, mean.at(i, j).x, mean.at(i, j).y, mean.at(i, j).z});
                    out.backgroundMax =
                        std::max({out.backgroundMax, mean.at(i, j).x, mean.at(i, j).y, mean.at(i, j).z});
                }
        }
    out.background.mean = glm::vec3(sum / 4.0);
    out.background.standardError = glm::vec3(glm::sqrt(var) / 4.0);
    return out;
}

void expectShell(const Scene& scene, double transmitted, const std::string& what, double sphere = -1.0,
                 float aperture = 0.0f) {
    if (sphere < 0.0) sphere = 0.5 * transmitted;
    ensureGlContext();
    Renderer renderer(scene, testShaders());
    for (Integrator integrator : {Integrator::Nee, Integrator::Bsdf, Integrator::Naive, Integrator::Bdpt}) {
        ShellImage s = shellImage(renderer, integrator, 64, aperture);
        const std::string where = what + ", " + integratorName(integrator);
        std::printf("  %-40s background %.4f +- %.4f, sphere %.4f +- %.4f (expected %.4f, %.4f)\n",
                    where.c_str(), double(s.background.mean.x), double(s.background.standardError.x),
                    double(s.sphere.mean.x), double(s.sphere.standardError.x), transmitted, sphere);
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_NEAR(s.background.mean[ch], transmitted, 5.0 * s.background.standardError[ch] + 1e-6)
                << where;
            EXPECT_NEAR(s.sphere.mean[ch], sphere, 5.0 * s.sphere.standardError[ch] + 1e-6) << where;
        }
        if (transmitted == 0.0 || transmitted == 1.0) {
            // Deterministic: every camera ray passes, or none does.
            EXPECT_EQ(s.backgroundMin, float(transmitted)) << where;
            EXPECT_EQ(s.backgroundMax, float(transmitted)) << where;
        } else {
            EXPECT_LT(s.background.standardError.x, 0.01) << where << ": too noisy to mean anything";
            EXPECT_LT(s.sphere.standardError.x, 0.01) << where << ": too noisy to mean anything";
        }
    }
}

Material blackShell() {
    Material m;
    m.name = "shell";
    m.diffuse = glm::vec3(0.0f);
    return m;
}

// BLEND coverage 0.5 halves the light through the shell: the background shows 0.5 and the sphere 0.25,
// found by camera rays (closest hit), bounce rays and shadow rays (any hit) alike, with every
// integrator. What this catches: coverage ignored (0, 0), applied to closest hits only (nee's shadow
// rays would see the shell opaque: the sphere 0 under nee), a coin that is not fair (another fraction),
// or one correlated between the rays of a path.
TEST(SurfaceMaps, BlendCoverageHalvesTheLightThroughIt) {
    Material shell = blackShell();
    shell.alphaMode = AlphaMode::Blend;
    shell.alpha = 0.5f;
    expectShell(sphereInAShell(shell), 0.5, "blend 0.5");
}

// The coverage of an alpha map's A channel (linear: not sRGB-decoded) times the alpha factor: A = 128
// and factor 0.8 give 0.8 * 128 / 255 = 0.4016, so 0.5984 of the light gets through.
TEST(SurfaceMaps, AlphaMapMultipliesTheAlphaFactor) {
    Material shell = blackShell();
    shell.alphaMode = AlphaMode::Blend;
    shell.alpha = 0.8f;
    shell.alphaTexture = 0;
    Scene scene = sphereInAShell(shell);
    scene.textures.push_back(makeTexture("coverage", 1, 1, {255, 255, 255, 128}));
    expectShell(scene, 1.0 - 0.8 * 128.0 / 255.0, "alpha map 128 x 0.8");
}

// MASK is deterministic: alpha 0.5 under a cutoff of 0.6 is no surface at all (the sky exactly), over a
// cutoff of 0.4 an opaque one (black exactly).
TEST(SurfaceMaps, MaskCoverageCutsAtTheCutoff) {
    Material shell = blackShell();
    shell.alphaMode = AlphaMode::Mask;
    shell.alpha = 0.5f;
    shell.alphaCutoff = 0.6f;
    expectShell(sphereInAShell(shell), 1.0, "mask 0.5 below a cutoff of 0.6");
    shell.alphaCutoff = 0.4f;
    expectShell(sphereInAShell(shell), 0.0, "mask 0.5 above a cutoff of 0.4");
}

// A single-sided surface (glTF doubleSided false) is not there for the camera from behind, and only for
// the camera (opacity.glsl): the shell's faces turned outward vanish from the camera inside it (the sky
// exactly) but still keep the sky's light from the sphere (black exactly); turned inward they block
// everything; a double-sided shell blocks either way. What this catches: culling the wrong side, or
// culling for rays other than the camera's (the sphere would be lit).
TEST(SurfaceMaps, SingleSidedSurfacesVanishFromBehindForTheCamera) {
    Material shell = blackShell();
    shell.doubleSided = false;
    expectShell(sphereInAShell(shell, false), 1.0, "single-sided, facing out", 0.0);
    expectShell(sphereInAShell(shell, true), 0.0, "single-sided, facing in");
    shell.doubleSided = true;
    expectShell(sphereInAShell(shell, false), 0.0, "double-sided");
}

// The same through a thin lens: camera rays start on the lens, not at the eye, and are still the
// camera's (a test that recognised them by the eye alone would let the shell block the sky).
TEST(SurfaceMaps, SingleSidedSurfacesVanishFromBehindThroughALensToo) {
    Material shell = blackShell();
    shell.doubleSided = false;
    expectShell(sphereInAShell(shell, false), 1.0, "single-sided, through a lens", 0.0, 0.1f);
}

// ---------------------------------------------------------------------------------------------------
// Emission maps and emitters with coverage.

// A grey floor under two lamps facing down: one with Ke 4 times a 2 x 2 emission map of four colours,
// one with Ke 6 and BLEND coverage 0.5. Light sampling must see each lamp's point as a ray hitting it
// does (the map at that point's uv, the coverage as its expectation), or nee and bsdf differ; bdpt's
// light subpaths start on the lamps with the same radiance.
Scene floorUnderMappedLamps() {
    Scene scene;
    scene.source = "floor under mapped lamps";
    Material floor = diffuseMaterial(0.5f);
    Material mapped = lampMaterial(glm::vec3(4.0f));
    mapped.emissionTexture = 0;
    Material covered = lampMaterial(glm::vec3(6.0f));
    covered.alphaMode = AlphaMode::Blend;
    covered.alpha = 0.5f;
    scene.materials = {floor, mapped, covered};
    appendQuad(scene, glm::vec3(-3.0f, 0.0f, -3.0f), glm::vec3(-3.0f, 0.0f, 3.0f),
               glm::vec3(3.0f, 0.0f, 3.0f), glm::vec3(3.0f, 0.0f, -3.0f), 0);
    // Facing down: counter-clockwise seen from below.
    appendMappedQuad(scene, glm::vec3(-1.5f, 1.2f, -0.5f), glm::vec3(-0.5f, 1.2f, -0.5f),
                     glm::vec3(-0.5f, 1.2f, 0.5f), glm::vec3(-1.5f, 1.2f, 0.5f), 1);
    appendQuad(scene, glm::vec3(0.5f, 1.0f, -0.5f), glm::vec3(1.5f, 1.0f, -0.5f), glm::vec3(1.5f, 1.0f, 0.5f),
               glm::vec3(0.5f, 1.0f, 0.5f), 2);
    scene.textures.push_back(makeTexture(
        "emission", 2, 2, {255, 40, 40, 255, 40, 255, 40, 255, 40, 40, 255, 255, 255, 255, 255, 255}));
    return scene;
}

Camera floorCamera() {
    Camera c;
    c.eye = glm::vec3(0.0f, 0.7f, -3.5f);
    c.target = glm::vec3(0.0f, 0.0f, 0.3f);
    c.fovY = 50.0f;
    return c;
}

TEST(SurfaceMaps, EmissionMapsAndCoverageOfEmittersAgreeBetweenEstimators) {
    ensureGlContext();
    Scene scene = floorUnderMappedLamps();
    Renderer renderer(scene, testShaders());
    Accumulation nee = renderScene(renderer, floorCamera(), Integrator::Nee, 24, 256, 3, 1);
    Accumulation bsdf = renderScene(renderer, floorCamera(), Integrator::Bsdf, 24, 1024, 3, 2);
    Accumulation bdpt = renderScene(renderer, floorCamera(), Integrator::Bdpt, 24, 256, 3, 3);
    expectSameImage(nee, bsdf, 4, 0.03f, "mapped lamps: nee against bsdf");
    expectSameImage(bdpt, nee, 4, 0.03f, "mapped lamps: bdpt against nee");
}

// Seen directly, the mapped lamp shows Ke times its map (sRGB-decoded, bilinear) and the covered lamp
// half its Ke. The camera looks up at the lamps from below; the mapped lamp's texture is uniform here.
TEST(SurfaceMaps, LampsSeenDirectlyShowTheirMapAndCoverage) {
    ensureGlContext();
    Scene scene = floorUnderMappedLamps();
    scene.textures[0] = makeTexture("emission", 1, 1, {200, 100, 50, 255});
    Renderer renderer(scene, testShaders());
    Camera up;
    up.eye = glm::vec3(-1.0f, 0.2f, 0.0f);
    up.target = glm::vec3(-1.0f, 1.2f, 0.0f);
    up.up = glm::vec3(0.0f, 0.0f, 1.0f);
    up.fovY = 20.0f;  // the mapped lamp fills the view
    Accumulation mapped = renderScene(renderer, up, Integrator::Nee, 8, 16, 0, 1);
    auto decode = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
    glm::vec3 expected =
        4.0f * glm::vec3(float(decode(200 / 255.0)), float(decode(100 / 255.0)), float(decode(50 / 255.0)));
    for (const glm::vec3& p : mapped.mean().pixels)
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(p[ch], expected[ch], 1e-4f * expected[ch]);
    up.eye = glm::vec3(1.0f, 0.2f, 0.0f);
    up.target = glm::vec3(1.0f, 1.0f, 0.0f);
    Accumulation covered = renderScene(renderer, up, Integrator::Nee, 8, 256, 0, 2);
    ImageEstimate e = estimate(covered);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(e.mean[ch], 3.0f, 5.0f * e.standardError[ch]);
    EXPECT_LT(e.standardError.x, 0.1f);
}

// ---------------------------------------------------------------------------------------------------
// Metallic-roughness maps, and everything at once.

// A metallic-roughness map of one texel (G = 102, B = 204: roughness 0.4, metallic 0.8, linear) with
// factors 1 shows what factors 0.4 and 0.8 without a map show.
TEST(SurfaceMaps, MetallicRoughnessMapIsItsFactors) {
    ensureGlContext();
    auto scene = [](bool mapped) {
        Scene s;
        s.source = "metallic-roughness sphere";
        Material m;
        m.type = MaterialType::MetallicRoughness;
        m.diffuse = glm::vec3(0.9f, 0.6f, 0.3f);
        m.metallic = mapped ? 1.0f : 0.8f;
        m.roughness = mapped ? 1.0f : 0.4f;
        if (mapped) m.metallicRoughnessTexture = 0;
        s.materials = {m, lampMaterial(glm::vec3(20.0f))};
        s.textures.push_back(makeTexture("mr", 1, 1, {0, 102, 204, 255}));
        appendSphere(s, glm::vec3(0.0f), 1.0f, 16, 32, 0, true);
        appendQuad(s, glm::vec3(-1.0f, 3.0f, -1.0f), glm::vec3(1.0f, 3.0f, -1.0f),
                   glm::vec3(1.0f, 3.0f, 1.0f), glm::vec3(-1.0f, 3.0f, 1.0f), 1);
        s.environment.color = glm::vec3(0.2f);
        return s;
    };
    Scene a = scene(true), b = scene(false);
    Renderer ra(a, testShaders()), rb(b, testShaders());
    Camera c;
    c.eye = glm::vec3(0.0f, 1.5f, -3.5f);
    c.target = glm::vec3(0.0f);
    c.fovY = 40.0f;
    expectSameImage(renderScene(ra, c, Integrator::Nee, 24, 256, 3, 1),
                    renderScene(rb, c, Integrator::Nee, 24, 256, 3, 2), 4, 0.02f,
                    "metallic-roughness map against its factors");
}

// Every map at once (surface_maps_scene.h: base colour, metallic-roughness and normal maps on a floor,
// specular and roughness maps on a plastic box, an alpha-mapped BLEND quad and a single-sided one),
// under a lamp and a dim sky: nee, bsdf and bdpt must agree. bdpt keeps the textured values of every
// stored vertex (bdpt_subpaths.glsl keepDiffuse); the estimators meet the maps through different
// functions (light samples, BSDF samples, joins).
TEST(SurfaceMaps, EveryMapAtOnceNeeBsdfAndBdptAgree) {
    ensureGlContext();
    Scene scene = everyMapScene();
    Renderer renderer(scene, testShaders());
    const Camera c = everyMapCamera();
    Accumulation nee = renderScene(renderer, c, Integrator::Nee, 24, 256, 4, 1);
    Accumulation bsdf = renderScene(renderer, c, Integrator::Bsdf, 24, 1024, 4, 2);
    Accumulation bdpt = renderScene(renderer, c, Integrator::Bdpt, 24, 256, 4, 3);
    expectSameImage(nee, bsdf, 4, 0.03f, "every map: nee against bsdf");
    expectSameImage(bdpt, nee, 4, 0.03f, "every map: bdpt against nee");
}

}  // namespace
}  // namespace fp::test
