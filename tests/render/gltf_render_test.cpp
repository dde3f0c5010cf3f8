// glTF 2.0 scenes the tests write themselves (scene/gltf_test_util.h), loaded by fp::loadScene as a
// user's file is and rendered with the real shaders: the glTF path from file to pixels, against analytic
// values and between integrators.
// - A smooth glass sphere (KHR_materials_transmission, KHR_materials_ior) in a white furnace shows
//   exactly the environment with nee; bdpt agrees with nee at its depth limit.
// - A grid of metallic-roughness spheres (metallic 0, 0.5, 1 by roughness 0.2, 0.5, 1) under an
//   emissive quad (KHR_materials_emissive_strength) and a dim sky: nee, bsdf and bdpt agree sphere by
//   sphere and block by block.
// - A normal map on a flat plane, in glTF's texture coordinates (v = 0 at the image's top) and its
//   green-up convention, shows what the plane geometrically tilted to the mapped normal shows under a
//   KHR_lights_punctual directional light; the map with green reversed shows the other tilt.
// - An alpha MASK from the baseColorTexture's alpha shows the sky exactly where alpha is 0 and a smooth
//   black coat's Fresnel reflection of it where alpha is 1.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "render_test_util.h"
#include "scene/gltf_test_util.h"
#include "scene/instancing.h"
#include "scene/load.h"
#include "scene/procedural.h"
#include "scene/scene_test_util.h"
#include "scene/texture_test_util.h"

namespace fp::test {
namespace {

using json = nlohmann::json;

// Writes the builder's glTF (its buffer as a data URI) to a temporary directory and loads it.
Scene loadBuilt(const GltfBuilder& b, const std::string& name) {
    TempDir dir;
    return loadScene(dir.write(name, b.gltf()));
}

void declareExtensions(GltfBuilder& b, const std::vector<std::string>& extensions) {
    b.doc["extensionsUsed"] = extensions;
}

// glTF's metallic-roughness factors.
json pbr(glm::vec3 base, double metallic, double roughness) {
    return {{"baseColorFactor", {base.r, base.g, base.b, 1.0}},
            {"metallicFactor", metallic},
            {"roughnessFactor", roughness}};
}

// The triangles as a non-indexed primitive's attributes: POSITION, and NORMAL (their shading normals)
// when `normals`.
json triangleAttributes(GltfBuilder& b, const std::vector<Triangle>& triangles, bool normals) {
    std::vector<glm::vec3> p, n;
    for (const Triangle& t : triangles)
        for (int k = 0; k < 3; ++k) {
            p.push_back(t.p[size_t(k)]);
            n.push_back(t.n[size_t(k)]);
        }
    json attributes = {{"POSITION", b.vec3(p)}};
    if (normals) attributes["NORMAL"] = b.vec3(n);
    return attributes;
}

// The quad a b c d (counter-clockwise seen from its front) as an indexed primitive, with TEXCOORD_0
// (glTF's, v = 0 at the image's top) at its corners when `uv` is given.
json quadPrimitive(GltfBuilder& b, const std::array<glm::vec3, 4>& p, int material,
                   const std::vector<glm::vec2>& uv = {}) {
    json attributes = {{"POSITION", b.vec3({p[0], p[1], p[2], p[3]})}};
    if (!uv.empty()) attributes["TEXCOORD_0"] = b.vec2(uv);
    return {{"attributes", attributes}, {"indices", b.indices16({0, 1, 2, 0, 2, 3})}, {"material", material}};
}

// A texture from RGBA bytes (top row first), in a PNG data URI: images[i] and textures[i].
int addTexture(GltfBuilder& b, int width, int height, const std::vector<uint8_t>& rgba) {
    int image = b.push("images", {{"uri", "data:image/png;base64," + base64(pngBytes(width, height, rgba))}});
    return b.push("textures", {{"source", image}});
}

// The pixel (column, row from the top, as Accumulation stores them; continuous) where `camera` images p.
glm::dvec2 projectToPixel(const Camera& camera, int size, glm::vec3 p) {
    CameraFrame f = cameraFrame(camera, 1.0f);
    glm::dvec3 local = glm::dvec3(p) - glm::dvec3(f.eye);
    double depth = glm::dot(local, glm::dvec3(f.forward));
    double x = glm::dot(local, glm::dvec3(f.right)) / (depth * glm::dot(f.right, f.right));
    double y = glm::dot(local, glm::dvec3(f.up)) / (depth * glm::dot(f.up, f.up));
    return {0.5 * (x + 1.0) * size, 0.5 * (1.0 - y) * size};
}

// The depth view of a size x size image of `camera` (one sample a pixel): 0 where no surface is seen.
Image depthView(Renderer& renderer, const Camera& camera, int size) {
    RenderSettings s;
    s.width = s.height = size;
    s.view = View::Depth;
    renderer.configure(s, camera);
    renderer.render(1);
    return renderer.readback().mean();
}

// ---------------------------------------------------------------------------------------------------
// A glass sphere in a white furnace.

// The sphere of WhiteFurnace.SmoothGlassSphereShowsExactlyTheEnvironment (environment_test.cpp), written
// as a glTF mesh with a white, smooth material that transmits everything at index 1.5 (glass: its
// transmission times 1 - metallic is above 1/2). In a uniform environment of radiance 1 every pixel must
// show exactly 1: reflection and refraction split the light without loss, and the radiance scaling
// 1 / eta^2 on entering is undone on leaving; nee, block by block and for the whole image. Depth 1000:
// total internal reflection between the flat facets traps some light for long (nee measured 0.9979 over
// the whole image at depth 100, 0.9999 at 300, 1.0000 at 1000, 4096 samples). bdpt stops at 12 bounces
// whatever --max-depth says (BDPT_MAX_DEPTH, bdpt.glsl), where the sphere still holds 1 % of the image's
// light, so it is compared with nee at depth 12 instead, block by block.
// What this catches: a glTF glass loaded as anything but a clear dielectric (the transmission threshold's
// comparison reversed in gltf_material.cpp: besides the type check, the white coat over white that the
// sphere became showed less than 1, a block at z 13 and the whole image at z -58 under nee), a
// transmission tint other than the white base colour, and a radiance scaling that is not undone (1 / eta^2
// applied on entering only, max(eta^2, 1) in dielectricSample: the whole image at z -472). The furnace
// cannot see the index itself: any eta gives 1.
TEST(GltfRender, GlassSphereInAWhiteFurnaceShowsExactlyTheEnvironment) {
    ensureGlContext();
    const Scene shape = sphereInFurnace(Material{}, false);
    GltfBuilder b;
    declareExtensions(b, {"KHR_materials_transmission", "KHR_materials_ior"});
    int glass = b.material({{"name", "glass"},
                            {"pbrMetallicRoughness", pbr(glm::vec3(1.0f), 0.0, 0.0)},
                            {"extensions",
                             {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                              {"KHR_materials_ior", {{"ior", 1.5}}}}}});
    b.mesh(
        json::array({{{"attributes", triangleAttributes(b, shape.triangles, false)}, {"material", glass}}}));
    b.node({{"mesh", 0}});
    b.scene({0});
    Scene scene = loadBuilt(b, "glass.gltf");
    ASSERT_EQ(scene.triangles.size(), shape.triangles.size());
    const Material& m = scene.materials[scene.triangles[0].material];
    EXPECT_EQ(m.type, MaterialType::Dielectric);
    EXPECT_EQ(m.ior, 1.5f);
    EXPECT_EQ(m.roughness, 0.0f);
    EXPECT_EQ(m.transmission, glm::vec3(1.0f));
    scene.environment.color = glm::vec3(1.0f);

    constexpr int kSize = 32;
    const Camera camera = outsideCamera();
    Renderer renderer(scene, testShaders());
    int onSphere = 0;
    for (const glm::vec3& p : depthView(renderer, camera, kSize).pixels) onSphere += p.x > 0.0f;
    EXPECT_GT(onSphere, 250) << "the sphere must fill half the image";
    const std::vector<glm::dvec3> white(size_t(kSize) * kSize, glm::dvec3(1.0));
    expectImage(renderScene(renderer, camera, Integrator::Nee, kSize, 64, 1000, 1), white, 4,
                "nee, glTF glass sphere in a white furnace");
    Accumulation bdpt = renderScene(renderer, camera, Integrator::Bdpt, kSize, 64, 12, 2);
    Accumulation nee = renderScene(renderer, camera, Integrator::Nee, kSize, 64, 12, 3);
    expectSameImage(bdpt, nee, 4, 0.01f, "glTF glass sphere in a white furnace, depth 12: bdpt against nee");
}

// ---------------------------------------------------------------------------------------------------
// A grid of metallic-roughness spheres.

constexpr double kGridMetallic[3] = {0.0, 0.5, 1.0};  // rows, top to bottom
constexpr double kGridRoughness[3] = {0.2, 0.5, 1.0};
const glm::vec3 kGridBase[3] = {{0.2f, 0.5f, 0.8f}, {0.8f, 0.4f, 0.3f}, {1.0f, 0.8f, 0.4f}};
constexpr float kGridRadius = 0.4f;
constexpr float kLampStrength = 5.0f;

glm::vec3 gridCentre(int row, int column) {
    return glm::vec3(float(column - 1), float(1 - row), 0.0f);
}

Camera gridCamera() {
    Camera c;
    c.eye = glm::vec3(0.0f, 0.0f, 6.0f);
    c.target = glm::vec3(0.0f);
    c.fovY = 32.0f;
    return c;
}

// Nine spheres: one smooth unit sphere's accessors shared by nine meshes, one per material, each placed
// (scaled to kGridRadius and moved) by its node; over them a 4 x 3 emissive quad facing down (emissive
// strength kLampStrength, out of the camera's view). The sky is set after loading.
GltfBuilder sphereGrid() {
    const Scene shape = sphereInFurnace(Material{}, true);
    GltfBuilder b;
    declareExtensions(b, {"KHR_materials_emissive_strength"});
    const json sphere = triangleAttributes(b, shape.triangles, true);
    std::vector<int> roots;
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column) {
            int material = b.material(
                {{"pbrMetallicRoughness", pbr(kGridBase[row], kGridMetallic[row], kGridRoughness[column])}});
            int mesh = b.mesh(json::array({{{"attributes", sphere}, {"material", material}}}));
            glm::vec3 c = gridCentre(row, column);
            roots.push_back(b.node({{"mesh", mesh},
                                    {"translation", {c.x, c.y, c.z}},
                                    {"scale", {kGridRadius, kGridRadius, kGridRadius}}}));
        }
    int lamp = b.material(
        {{"name", "lamp"},
         {"pbrMetallicRoughness", pbr(glm::vec3(0.0f), 0.0, 1.0)},
         {"emissiveFactor", {1.0, 1.0, 1.0}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", kLampStrength}}}}}});
    // Counter-clockwise seen from below: it faces -y.
    int mesh = b.mesh(json::array({quadPrimitive(b,
                                                 {glm::vec3(-2.0f, 3.0f, 0.0f), glm::vec3(2.0f, 3.0f, 0.0f),
                                                  glm::vec3(2.0f, 3.0f, 3.0f), glm::vec3(-2.0f, 3.0f, 3.0f)},
                                                 lamp)}));
    roots.push_back(b.node({{"mesh", mesh}}));
    b.scene(roots);
    return b;
}

// Each sphere's triangles carry the metallic-roughness material of its row and column; the lamp's its
// emission. Then nee (512 samples), bsdf (2048) and bdpt (512) agree: on the 6 x 6 pixels at the centre
// of each sphere's image (each bright enough, and sharp enough to tell, within 5 standard errors of the
// difference), and block by block over the whole image. The rows are the model's two packed forms
// (metallic 0 a plastic, 1 a conductor) and the mixture (0.5), which nee evaluates, bsdf samples and
// bdpt joins through different functions.
// What this catches: a glTF factor mapped to the wrong field (the load checks: roughnessFactor read
// from metallicFactor failed them, while the integrators, fed the same wrong material, still agreed), and
// an evaluation, density or sampling routine of the model that disagrees with the others: the plastic's
// density without its lobe probability ((1 - p) dropped in plasticPdf) put nee against bsdf at whole-image
// z 8 to 15 (a block at 5.9, the metallic 0.5, roughness 1 sphere at 5.7 standard errors) and bdpt
// against nee at z 9.
TEST(GltfRender, MetallicRoughnessSphereGridAgreesBetweenIntegrators) {
    ensureGlContext();
    Scene scene = loadBuilt(sphereGrid(), "grid.gltf");
    ASSERT_EQ(scene.triangles.size(), 9 * sphereInFurnace(Material{}, true).triangles.size() + 2);
    // The materials of the triangles near each sphere's centre, and of the lamp (above them).
    std::array<std::set<uint32_t>, 9> sphereMaterials;
    std::set<uint32_t> lampMaterials;
    for (const Triangle& t : scene.triangles) {
        glm::vec3 centroid = (t.p[0] + t.p[1] + t.p[2]) / 3.0f;
        if (centroid.y > 2.0f) lampMaterials.insert(t.material);
        for (int k = 0; k < 9; ++k)
            if (glm::length(centroid - gridCentre(k / 3, k % 3)) <= kGridRadius)
                sphereMaterials[size_t(k)].insert(t.material);
    }
    ASSERT_EQ(lampMaterials.size(), 1u);
    EXPECT_EQ(scene.materials[*lampMaterials.begin()].emission, glm::vec3(kLampStrength));
    for (int k = 0; k < 9; ++k) {
        const int row = k / 3, column = k % 3;
        ASSERT_EQ(sphereMaterials[size_t(k)].size(), 1u) << "one material per sphere, sphere " << k;
        const Material& m = scene.materials[*sphereMaterials[size_t(k)].begin()];
        EXPECT_EQ(m.type, MaterialType::MetallicRoughness) << "sphere " << k;
        EXPECT_FLOAT_EQ(m.metallic, float(kGridMetallic[row])) << "sphere " << k;
        EXPECT_FLOAT_EQ(m.roughness, float(kGridRoughness[column])) << "sphere " << k;
        EXPECT_EQ(m.diffuse, kGridBase[row]) << "sphere " << k;
        EXPECT_FALSE(m.isEmissive()) << "sphere " << k;
    }
    scene.environment.color = glm::vec3(0.1f);

    constexpr int kSize = 40;
    const Camera camera = gridCamera();
    Renderer renderer(scene, testShaders());
    const Image depth = depthView(renderer, camera, kSize);
    Accumulation nee = renderScene(renderer, camera, Integrator::Nee, kSize, 512, 4, 1);
    Accumulation bsdf = renderScene(renderer, camera, Integrator::Bsdf, kSize, 2048, 4, 2);
    Accumulation bdpt = renderScene(renderer, camera, Integrator::Bdpt, kSize, 512, 4, 3);
    struct Pair {
        const Accumulation *a, *b;
        const char* what;
    };
    for (const Pair& pair : {Pair{&nee, &bsdf, "nee against bsdf"}, Pair{&bdpt, &nee, "bdpt against nee"}}) {
        for (int row = 0; row < 3; ++row)
            for (int column = 0; column < 3; ++column) {
                glm::dvec2 centre = projectToPixel(camera, kSize, gridCentre(row, column));
                int x0 = int(std::lround(centre.x)) - 3, y0 = int(std::lround(centre.y)) - 3;
                // On the sphere's image (about 4.7 pixels in radius), but perhaps for the corners.
                int onSphere = 0;
                for (int y = y0; y < y0 + 6; ++y)
                    for (int x = x0; x < x0 + 6; ++x) onSphere += depth.at(x, y).x > 0.0f;
                ASSERT_GE(onSphere, 32) << "sphere " << row << ", " << column;
                ImageEstimate ea = estimate(*pair.a, x0, y0, 6, 6), eb = estimate(*pair.b, x0, y0, 6, 6);
                char where[160];
                std::snprintf(where, sizeof where, "%s, metallic %.1f roughness %.2f", pair.what,
                              kGridMetallic[row], kGridRoughness[column]);
                std::printf("  %s: %.4f +- %.4f against %.4f +- %.4f (green)\n", where, double(ea.mean.g),
                            double(ea.standardError.g), double(eb.mean.g), double(eb.standardError.g));
                for (int ch = 0; ch < 3; ++ch) {
                    double se = std::hypot(double(ea.standardError[ch]), double(eb.standardError[ch]));
                    EXPECT_LT(std::abs(ea.mean[ch] - eb.mean[ch]), 5.0 * se) << where << ", channel " << ch;
                    EXPECT_LT(se, 0.05 * eb.mean[ch]) << where << ": too noisy to mean anything";
                    EXPECT_GT(ea.mean[ch], 0.02f) << where << ": not black";
                }
            }
        expectSameImage(*pair.a, *pair.b, 4, 0.02f, std::string("glTF sphere grid, ") + pair.what);
    }
}

// ---------------------------------------------------------------------------------------------------
// A normal-mapped plane under a directional light.

// The light travels along kSunTravel (from above, the -z side and a little +x): the normal map's two
// tilts, toward -z and toward +z, face it differently.
const glm::vec3 kSunTravel = -glm::normalize(glm::vec3(0.4f, 1.0f, -0.6f));
constexpr float kPlaneHalf = 3.0f;
const glm::vec3 kPlaneBase(0.8f, 0.6f, 0.4f);

// A square of side 2 kPlaneHalf about the origin with unit normal n, its front toward n (e1: +x made
// orthogonal to n, e2 = n x e1); metallic 0, roughness 1, its base colour kPlaneBase. With
// `normalTexel`, the plane is flat (n = +y) and carries a one-texel normal map of that RGB code, its
// glTF texture coordinates u = (x + h) / 2h along +x and v along -z (the image's top at -z) or, with
// `mirrored`, along +z. Lit by a KHR_lights_punctual directional light of 3 lux turned (its node's -Z)
// to kSunTravel; the environment is black.
Scene sunlitPlane(glm::vec3 n, const uint8_t* normalTexel = nullptr, bool mirrored = false) {
    GltfBuilder b;
    declareExtensions(b, {"KHR_lights_punctual"});
    json material = {{"pbrMetallicRoughness", pbr(kPlaneBase, 0.0, 1.0)}};
    glm::vec3 e1 = glm::normalize(glm::vec3(1.0f, 0.0f, 0.0f) - n * n.x), e2 = glm::cross(n, e1);
    const float h = kPlaneHalf;
    std::array<glm::vec3, 4> p = {h * (-e1 - e2), h * (e1 - e2), h * (e1 + e2), h * (-e1 + e2)};
    std::vector<glm::vec2> uv;
    if (normalTexel) {
        material["normalTexture"] = {
            {"index", addTexture(b, 1, 1, {normalTexel[0], normalTexel[1], normalTexel[2], 255})}};
        for (const glm::vec3& q : p) {
            float v = (q.z + h) / (2.0f * h);  // 0 at z = -h: the image's top is at -z
            uv.emplace_back((q.x + h) / (2.0f * h), mirrored ? 1.0f - v : v);
        }
    }
    int m = b.material(material);
    int mesh = b.mesh(json::array({quadPrimitive(b, p, m, uv)}));
    b.doc["extensions"] = {
        {"KHR_lights_punctual", {{"lights", {{{"type", "directional"}, {"intensity", 3.0}}}}}}};
    // The rotation taking -Z to kSunTravel: the quaternion (cross(a, b), 1 + a.b), normalised.
    const glm::vec3 a(0.0f, 0.0f, -1.0f);
    glm::vec4 q(glm::cross(a, kSunTravel), 1.0f + glm::dot(a, kSunTravel));
    q = glm::normalize(q);
    b.node({{"mesh", mesh}});
    b.node({{"rotation", {q.x, q.y, q.z, q.w}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.scene({0, 1});
    Scene scene = loadBuilt(b, "plane.gltf");
    EXPECT_EQ(scene.punctualLights.size(), 1u);
    if (!scene.punctualLights.empty()) {
        const PunctualLight& sun = scene.punctualLights[0];
        EXPECT_EQ(sun.type, PunctualLightType::Directional);
        EXPECT_LT(glm::length(sun.direction - kSunTravel), 1e-5f);
    }
    EXPECT_EQ(scene.materials.at(scene.triangles.at(0).material).normalTexture, normalTexel ? 0 : -1);
    return scene;
}

// Looks straight down at the plane from 8 above; the plane fills the image, flat or tilted. From this
// high every view's mirror image about the mapped normals stays above the plane, so the normal map's
// normal is used as it is (surface.glsl tilts it back where the reflection would fall below the plane:
// valid_reflection.glsl; from 4 above, with the far edge seen 14 degrees off the vertical, it did).
Camera lookingDownAtThePlane() {
    Camera c;
    c.eye = glm::vec3(0.0f, 8.0f, 0.0f);
    c.target = glm::vec3(0.0f);
    c.up = glm::vec3(0.0f, 0.0f, 1.0f);
    c.fovY = 9.0f;
    return c;
}

// A flat plane whose normal map holds one tangent-space normal shows, pixel by pixel, what the plane
// geometrically tilted to the mapped normal shows: under a directional light, with the same camera ray,
// the same light direction and the same shading normal, the model (a rough coat over the base colour:
// not Lambertian, so an analytic value would have to repeat the model) gives the same radiance. glTF's
// normal map convention: red along the tangent (+u), green toward the image's top (decreasing glTF v,
// increasing v once the loader has flipped it), blue along the normal. Texel (160, 200, 220) decodes to
// (0.255, 0.569, 0.725): tilted toward +x and, green up, toward the image's top, which lies at -z with
// the plain texture coordinates and at +z with the mirrored ones (the bitangent's sign then -1); texel
// (160, 55, 220) is its reflection, green down. Each of the four renders must match its tilted plane
// (nee at depth 1, whose only noise is the pixel's jitter), and the two tilts must differ by over 10 %.
// What this catches: v not flipped on loading (gltf_mesh.cpp: every map then tilts the wrong way, each
// mapped plane 0.38 or 2.6 times its tilted plane, whole-image z about 3e5), the bitangent's sign
// ignored in textures.glsl (the two mirrored cases, the same figures), a green channel read reversed
// (DirectX's convention: all four), and the tangent and bitangent swapped (mean ratio 0.95, z 2e4).
TEST(GltfRender, NormalMapShowsThePlaneTiltedTowardTheTexturesTop) {
    ensureGlContext();
    const uint8_t up[3] = {160, 200, 220}, down[3] = {160, 55, 220};
    auto decode = [](const uint8_t* t) {
        return glm::dvec3(t[0] / 255.0 * 2.0 - 1.0, t[1] / 255.0 * 2.0 - 1.0, t[2] / 255.0 * 2.0 - 1.0);
    };
    // The world normal of a texel's code on the flat plane: tangent +x, normal +y, the image's top at
    // `top` (-z or +z).
    auto mapped = [&](const uint8_t* texel, double top) {
        glm::dvec3 c = decode(texel);
        return glm::vec3(glm::normalize(glm::dvec3(c.x, c.z, top * c.y)));
    };
    const Camera camera = lookingDownAtThePlane();
    constexpr int kSize = 24;
    // The two tilts: toward -z (green up on plain coordinates) and toward +z.
    const glm::vec3 towardMinusZ = mapped(up, -1.0), towardPlusZ = mapped(up, 1.0);
    Scene minusScene = sunlitPlane(towardMinusZ), plusScene = sunlitPlane(towardPlusZ);
    Renderer minusRenderer(minusScene, testShaders()), plusRenderer(plusScene, testShaders());
    Accumulation tiltedMinus = renderScene(minusRenderer, camera, Integrator::Nee, kSize, 64, 1, 1);
    Accumulation tiltedPlus = renderScene(plusRenderer, camera, Integrator::Nee, kSize, 64, 1, 2);
    ImageEstimate em = estimate(tiltedMinus), ep = estimate(tiltedPlus);
    std::printf("  plane tilted toward -z %.5f +- %.5f, toward +z %.5f +- %.5f\n", double(em.mean.g),
                double(em.standardError.g), double(ep.mean.g), double(ep.standardError.g));
    ASSERT_GT(em.mean.g, 1.1f * ep.mean.g) << "the two tilts must look different";
    ASSERT_GT(ep.mean.g, 0.01f) << "both lit";

    struct Case {
        const uint8_t* texel;
        bool mirrored;
        const Accumulation* expected;
        const char* what;
    };
    const Case cases[] = {{up, false, &tiltedMinus, "green up, plain uv: toward -z"},
                          {down, false, &tiltedPlus, "green down, plain uv: toward +z"},
                          {up, true, &tiltedPlus, "green up, mirrored uv: toward +z"},
                          {down, true, &tiltedMinus, "green down, mirrored uv: toward -z"}};
    uint32_t seed = 3;
    for (const Case& c : cases) {
        Scene flat = sunlitPlane(glm::vec3(0.0f, 1.0f, 0.0f), c.texel, c.mirrored);
        Renderer renderer(flat, testShaders());
        Accumulation acc = renderScene(renderer, camera, Integrator::Nee, kSize, 64, 1, seed++);
        expectSameImage(acc, *c.expected, 4, 0.02f, std::string("normal map, ") + c.what);
    }
}

// ---------------------------------------------------------------------------------------------------
// Alpha MASK from the base colour texture.

// The unpolarised Fresnel reflectance of a smooth dielectric of index eta seen from air at cos(theta)
// (Born & Wolf, the s and p amplitudes), written out in double.
double fresnelDielectric(double cosI, double eta) {
    double cosT = std::sqrt(1.0 - (1.0 - cosI * cosI) / (eta * eta));
    double rs = (cosI - eta * cosT) / (cosI + eta * cosT), rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return 0.5 * (rs * rs + rp * rp);
}

// A 4 x 4 quad in z = 0 facing +z, the camera 3 in front of it looking at its centre (it fills the
// image), under a white sky. Its material: base colour factor white, a baseColorTexture of 16 x 1 texels,
// black, alpha 0 in the left eight texels and 255 in the right eight (u = (x + 2) / 4), alphaMode MASK
// (cutoff 0.5, glTF's default), metallic 0 and roughness 0: where alpha passes the cutoff, a smooth
// white coat over a black base, which reflects exactly F(cos theta; 1.5) of the sky toward the camera;
// elsewhere no surface, the sky exactly. (The bilinear alpha crosses 1/2 at u = 1/2, x = 0, exactly:
// llvmpipe's filtering puts it there to well under a thousandth of a pixel, as the 1536 samples of the
// column left of it, all the sky, show. The camera sees u in 0.23 to 0.77 only, far from where the
// repeating texture wraps.) The expected
// image averages, over each pixel's area, 1 where the camera ray meets x < 0 and F where x > 0; nee,
// bsdf and bdpt must match it block by block and for the whole image, and every pixel left of the
// middle must be exactly 1.
// What this catches: the texture's alpha not used as coverage (gltf_material.cpp no longer pointing
// alphaTexture at the base colour texture: the left half showed F, whole-image z -9868 under nee), the
// cutoff compared the wrong way or the alpha map read at 1 - uv (opacity.glsl: the halves swapped, blocks
// at z 2e6, while the whole image's mean hardly moved, z -1.1, the halves mirroring each other: only the
// blocks see it), and the texture's rgb not multiplying the white factor (surface.glsl: a white base,
// whole-image z 468).
TEST(GltfRender, AlphaMaskShowsTheSkyWhereTheBaseColourAlphaIsZero) {
    ensureGlContext();
    constexpr float kHalf = 2.0f;
    GltfBuilder b;
    std::vector<uint8_t> texels(16 * 4, 0);
    for (int x = 8; x < 16; ++x) texels[size_t(4 * x + 3)] = 255;
    json mr = pbr(glm::vec3(1.0f), 0.0, 0.0);
    mr["baseColorTexture"] = {{"index", addTexture(b, 16, 1, texels)}};
    int material = b.material({{"pbrMetallicRoughness", mr}, {"alphaMode", "MASK"}});
    std::array<glm::vec3, 4> p = {glm::vec3(-kHalf, -kHalf, 0.0f), glm::vec3(kHalf, -kHalf, 0.0f),
                                  glm::vec3(kHalf, kHalf, 0.0f), glm::vec3(-kHalf, kHalf, 0.0f)};
    std::vector<glm::vec2> uv;
    for (const glm::vec3& q : p)
        uv.emplace_back((q.x + kHalf) / (2.0f * kHalf), (kHalf - q.y) / (2.0f * kHalf));
    b.mesh(json::array({quadPrimitive(b, p, material, uv)}));
    b.node({{"mesh", 0}});
    b.scene({0});
    Scene scene = loadBuilt(b, "mask.gltf");
    const Material& m = scene.materials.at(scene.triangles.at(0).material);
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(m.alphaCutoff, 0.5f);
    EXPECT_GE(m.alphaTexture, 0);
    EXPECT_EQ(m.alphaTexture, m.diffuseTexture);
    scene.environment.color = glm::vec3(1.0f);

    Camera camera;
    camera.eye = glm::vec3(0.0f, 0.0f, 3.0f);
    camera.target = glm::vec3(0.0f);
    camera.fovY = 40.0f;
    constexpr int kSize = 24;
    // The expected image, rows top first: the midpoint rule on 16 x 16 points of each pixel.
    const CameraFrame f = cameraFrame(camera, 1.0f);
    std::vector<glm::dvec3> expected(size_t(kSize) * kSize);
    constexpr int n = 16;
    for (int row = 0; row < kSize; ++row)
        for (int x = 0; x < kSize; ++x) {
            double sum = 0.0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    double nx = 2.0 * (x + (i + 0.5) / n) / kSize - 1.0,
                           ny = 2.0 * (kSize - 1 - row + (j + 0.5) / n) / kSize - 1.0;
                    glm::dvec3 d = glm::normalize(glm::dvec3(f.forward) + nx * glm::dvec3(f.right) +
                                                  ny * glm::dvec3(f.up));
                    double hitX = double(camera.eye.x) + d.x * (-double(camera.eye.z) / d.z);
                    sum += hitX < 0.0 ? 1.0 : fresnelDielectric(-d.z, 1.5);
                }
            expected[size_t(row) * kSize + size_t(x)] = glm::dvec3(sum / (n * n));
        }

    Renderer renderer(scene, testShaders());
    uint32_t seed = 1;
    for (Integrator integrator : {Integrator::Nee, Integrator::Bsdf, Integrator::Bdpt}) {
        Accumulation acc = renderScene(renderer, camera, integrator, kSize, 64, 3, seed++);
        const std::string what = std::string(integratorName(integrator)) + ", glTF alpha mask";
        expectImage(acc, expected, 4, what);
        const Image mean = acc.mean();
        for (int row = 0; row < kSize; ++row)
            for (int x = 0; x < kSize / 2; ++x)
                EXPECT_EQ(mean.at(x, row), glm::vec3(1.0f)) << what << ": the sky at " << x << ", " << row;
        ImageEstimate right = estimate(acc, kSize / 2, 0, kSize / 2, kSize);
        EXPECT_LT(right.mean.g, 0.06f) << what << ": the right half is the surface";
        EXPECT_LT(right.standardError.g, 0.02f * right.mean.g) << what << ": too noisy to mean anything";
    }
}

// ---------------------------------------------------------------------------------------------------
// An instanced grid.

// One sphere mesh placed by nine nodes (turned and scaled differently), on a floor under an emissive
// quad: the loader stores the sphere once (scene/instancing.h) and the renderer traces two levels; the
// image must be the flattened scene's (--flatten-instances), block by block, with nee and bdpt. What
// this catches: anything in the glTF path to instances (node transforms taken as object-to-world, the
// mesh kept in its own space) or in their tracing that differs from the flattened world triangles.
TEST(GltfRender, InstancedGridRendersAsItsFlattenedCopy) {
    GltfBuilder b;
    Scene sphere;
    appendSphere(sphere, glm::vec3(0.0f), 1.0f, 8, 16, 0, true);
    int grey = b.material({{"pbrMetallicRoughness", pbr(glm::vec3(0.7f, 0.5f, 0.3f), 0.0, 0.6)}});
    int floor = b.material({{"pbrMetallicRoughness", pbr(glm::vec3(0.5f), 0.0, 1.0)}});
    int lamp =
        b.material({{"pbrMetallicRoughness", pbr(glm::vec3(0.0f), 0.0, 1.0)},
                    {"emissiveFactor", {1.0, 1.0, 1.0}},
                    {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 6.0}}}}}});
    declareExtensions(b, {"KHR_materials_emissive_strength"});
    int mesh = b.mesh(
        json::array({{{"attributes", triangleAttributes(b, sphere.triangles, true)}, {"material", grey}}}));
    std::vector<int> nodes;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double angle = 0.4 * (3 * i + j), s = 0.25 + 0.05 * (i + j);
            nodes.push_back(b.node({{"mesh", mesh},
                                    {"translation", {-1.0 + i, s, -1.0 + j}},
                                    {"rotation", {0.0, std::sin(angle / 2), 0.0, std::cos(angle / 2)}},
                                    {"scale", {s, 1.4 * s, s}}}));
        }
    nodes.push_back(b.node(
        {{"mesh", b.mesh(json::array({quadPrimitive(
                      b, {glm::vec3(-2, 0, 2), glm::vec3(2, 0, 2), glm::vec3(2, 0, -2), glm::vec3(-2, 0, -2)},
                      floor)}))}}));
    nodes.push_back(b.node({{"mesh", b.mesh(json::array({quadPrimitive(
                                         b,
                                         {glm::vec3(-0.5f, 2.5f, 0.5f), glm::vec3(0.5f, 2.5f, 0.5f),
                                          glm::vec3(0.5f, 2.5f, -0.5f), glm::vec3(-0.5f, 2.5f, -0.5f)},
                                         lamp)}))}}));
    b.scene(nodes);
    Scene scene = loadBuilt(b, "grid.gltf");
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 9u);
    scene.environment.color = glm::vec3(0.05f);
    Scene flat = flattenInstances(scene);
    Camera camera;
    camera.eye = glm::vec3(0.0f, 2.0f, 3.0f);
    camera.target = glm::vec3(0.0f, 0.3f, 0.0f);
    camera.fovY = 50.0f;
    ensureGlContext();
    Renderer instanced(scene, testShaders()), flattened(flat, testShaders());
    for (Integrator integrator : {Integrator::Nee, Integrator::Bdpt}) {
        Accumulation a = renderScene(instanced, camera, integrator, 48, 64, 4, 5);
        Accumulation f = renderScene(flattened, camera, integrator, 48, 64, 4, 6);
        expectSameImage(a, f, 8, 0.03f,
                        std::string("glTF instanced grid vs flattened, ") + integratorName(integrator));
    }
}

}  // namespace
}  // namespace fp::test
