// map_Kd through the whole pipeline: OBJ + MTL + PNG written here, loaded, packed, uploaded and looked
// up by the real shaders. A screen-filling quad carries the texture: the albedo view must reproduce the
// texels (bilinear, repeat, sRGB decoded), every integrator must see the textured Kd, and a mesh without
// vt falls back to the texture's mean colour.
#include <gtest/gtest.h>

#include "core/error.h"
#include "gpu/scene_textures.h"
#include "image/tone_map.h"
#include "render_test_util.h"
#include "scene/load.h"
#include "scene/scene_test_util.h"
#include "scene/texture_test_util.h"

namespace fp::test {
namespace {

constexpr int kTexSize = 4;

// A 4x4 texture whose every texel differs (red grows to the right, green downward, blue along both).
std::vector<uint8_t> gradientTexels() {
    std::vector<uint8_t> rgba;
    for (int y = 0; y < kTexSize; ++y)
        for (int x = 0; x < kTexSize; ++x)
            rgba.insert(rgba.end(),
                        {uint8_t(20 + 70 * x), uint8_t(30 + 60 * y), uint8_t(200 - 12 * (x + 3 * y)), 255});
    return rgba;
}

glm::vec3 decodedTexel(const std::vector<uint8_t>& rgba, int x, int y) {
    const uint8_t* t = &rgba[size_t(4 * (y * kTexSize + x))];
    return glm::vec3(srgbDecode(t[0] / 255.0f), srgbDecode(t[1] / 255.0f), srgbDecode(t[2] / 255.0f));
}

// Bilinear filtering with repeat wrapping, written independently of the GLSL: texel centres at
// half-integers, row 0 at the top (v = 1).
glm::vec3 bilinear(const std::vector<uint8_t>& rgba, glm::vec2 uv) {
    float x = uv.x * kTexSize - 0.5f, y = (1.0f - uv.y) * kTexSize - 0.5f;
    int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    float fx = x - float(x0), fy = y - float(y0);
    auto at = [&](int i, int j) {
        return decodedTexel(rgba, ((i % kTexSize) + kTexSize) % kTexSize,
                            ((j % kTexSize) + kTexSize) % kTexSize);
    };
    return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
           fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

// The square [-1, 1]^2 in z = 0, facing +z, with vt (x + 1) / 2, (y + 1) / 2 (or none), textured
// with `rgba` through an MTL library in a subdirectory.
Scene texturedQuad(const std::vector<uint8_t>& rgba, bool withTexcoords,
                   const std::string& material = "Kd 1\n") {
    TempDir dir;
    dir.write("lib/quad.mtl", "newmtl tex\n" + material + "map_Kd checker.png\n");
    dir.write("lib/checker.png", pngBytes(kTexSize, kTexSize, rgba));
    std::string faces = withTexcoords ? "f 1/1 2/2 3/3 4/4\n" : "f 1 2 3 4\n";
    return loadObj(dir.write("quad.obj",
                             "mtllib lib/quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                             "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl tex\n" +
                                 faces));
}

// At distance 1 with a 90 degree field of view the quad fills the image exactly: the pixel centre
// (x + 0.5, y + 0.5) (y from the top) sees uv ((x + 0.5) / W, 1 - (y + 0.5) / H).
Camera quadCamera() {
    Camera c;
    c.eye = glm::vec3(0.0f, 0.0f, 1.0f);
    c.target = glm::vec3(0.0f);
    c.fovY = 90.0f;
    return c;
}

Image albedoView(Renderer& renderer, int size) {
    RenderSettings s;
    s.width = s.height = size;
    s.view = View::Albedo;
    renderer.configure(s, quadCamera());
    renderer.render(1);
    return renderer.readback().mean();
}

TEST(Textures, AlbedoViewReproducesTheTexture) {
    ensureGlContext();
    std::vector<uint8_t> rgba = gradientTexels();
    Scene scene = texturedQuad(rgba, true);
    Renderer renderer(scene, testShaders());
    EXPECT_EQ(renderer.stats().gpuTextureBytes, 2 * 3 * 8 + 16 * 4 + 16u) << "uvs, texels and the table";
    // One pixel per texel: pixel centres are texel centres, so each pixel is one decoded texel. The
    // only error is the hit point's (a few float ulps of the quad's size of 2), times the largest
    // change between neighbouring texels per texel (at most 1): far below 1e-4.
    Image exact = albedoView(renderer, kTexSize);
    for (int y = 0; y < kTexSize; ++y)
        for (int x = 0; x < kTexSize; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(exact.at(x, y)[c], decodedTexel(rgba, x, y)[c], 1e-4f)
                    << x << "," << y << " channel " << c;
    // Four pixels per texel in each direction: the filter blends neighbours, across the wrap at the edges.
    const int size = 4 * kTexSize;
    Image filtered = albedoView(renderer, size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            glm::vec3 expected = bilinear(rgba, glm::vec2((x + 0.5f) / size, 1.0f - (y + 0.5f) / size));
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(filtered.at(x, y)[c], expected[c], 1e-4f) << x << "," << y << " channel " << c;
        }
}

// A sampler's wrap modes and nearest filtering (glTF's wrapS, wrapT, magFilter; Texture's fields): the
// quad's uvs stretched over [-1, 2]^2, clamped along u, mirrored along v, nearest. Each pixel centre
// (half a texel across, never on a texel's edge) must show exactly the texel that the OpenGL rules pick,
// written independently of the GLSL.
TEST(Textures, SamplersClampMirrorAndPickTheNearestTexel) {
    ensureGlContext();
    std::vector<uint8_t> rgba = gradientTexels();
    Scene scene = texturedQuad(rgba, true);
    for (Triangle& t : scene.triangles)
        for (glm::vec2& uv : t.uv) uv = 3.0f * uv - 1.0f;
    scene.textures[0].wrapS = TextureWrap::ClampToEdge;
    scene.textures[0].wrapT = TextureWrap::MirroredRepeat;
    scene.textures[0].nearest = true;
    Renderer renderer(scene, testShaders());
    const int size = 6 * kTexSize;
    Image image = albedoView(renderer, size);
    auto mirrored = [](int i) {
        int m = ((i % (2 * kTexSize)) + 2 * kTexSize) % (2 * kTexSize);
        return m < kTexSize ? m : 2 * kTexSize - 1 - m;
    };
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            glm::vec2 uv = 3.0f * glm::vec2((x + 0.5f) / size, 1.0f - (y + 0.5f) / size) - 1.0f;
            int tx = std::clamp(int(std::floor(uv.x * kTexSize)), 0, kTexSize - 1);
            int ty = mirrored(int(std::floor((1.0f - uv.y) * kTexSize)));
            glm::vec3 expected = decodedTexel(rgba, tx, ty);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(image.at(x, y)[c], expected[c], 1e-4f) << x << "," << y << " channel " << c;
        }
}

TEST(Textures, KdMultipliesTheTextureAndPlasticBasesAreTextured) {
    ensureGlContext();
    std::vector<uint8_t> rgba = gradientTexels();
    for (const std::string& material :
         {std::string("Kd 0.5 0.25 1\n"), std::string("Kd 0.5 0.25 1\nKs 0.04\n")}) {
        Scene scene = texturedQuad(rgba, true, material);
        ASSERT_EQ(scene.materials[0].type,
                  material.find("Ks") != std::string::npos ? MaterialType::Plastic : MaterialType::Diffuse);
        Renderer renderer(scene, testShaders());
        Image image = albedoView(renderer, kTexSize);
        for (int y = 0; y < kTexSize; ++y)
            for (int x = 0; x < kTexSize; ++x) {
                glm::vec3 expected = glm::vec3(0.5f, 0.25f, 1.0f) * decodedTexel(rgba, x, y);
                for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(x, y)[c], expected[c], 1e-4f) << material;
            }
    }
}

// White furnace: the quad under a uniform sky of radiance 1 reflects albedo(uv) * 1 at every point after
// one bounce, and nothing comes back to a plane. Pixels sample the quad uniformly (it is perpendicular to
// the view axis), and a bilinear, repeating texture over whole periods averages to its texels' mean.
TEST(Textures, EveryIntegratorSeesTheTexturedAlbedoUnderAUniformSky) {
    ensureGlContext();
    std::vector<uint8_t> rgba = gradientTexels();
    Scene scene = texturedQuad(rgba, true);
    scene.environment.color = glm::vec3(1.0f);
    glm::vec3 mean(0.0f);
    for (int y = 0; y < kTexSize; ++y)
        for (int x = 0; x < kTexSize; ++x) mean += decodedTexel(rgba, x, y) / float(kTexSize * kTexSize);
    Renderer renderer(scene, testShaders());
    for (Integrator integrator : {Integrator::Naive, Integrator::Bsdf, Integrator::Nee, Integrator::Bdpt})
        for (int depth : {1, 3}) {
            Accumulation acc = renderScene(renderer, quadCamera(), integrator, 16, 64, depth);
            ImageEstimate e = estimate(acc);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(e.mean[c], mean[c], 5.0f * e.standardError[c] + 1e-5f)
                    << integratorName(integrator) << " depth " << depth << " channel " << c;
                EXPECT_LT(5.0f * e.standardError[c], 0.1f * mean[c])
                    << "too noisy to tell Kd 1 from the texture";
            }
            EXPECT_EQ(acc.droppedSamples(), 0u);
        }
}

// Expects bdpt and nee to agree (block z-scores) on `scene` seen from insideCamera() after 3 bounces;
// returns nee's mean.
glm::vec3 neeAgreesWithBdptInTheBox(const Scene& scene) {
    Renderer renderer(scene, testShaders());
    Accumulation nee = renderScene(renderer, insideCamera(), Integrator::Nee, 16, 64, 3);
    Accumulation bdpt = renderScene(renderer, insideCamera(), Integrator::Bdpt, 16, 64, 3);
    std::vector<float> z = blockZScores(bdpt, nee, 2);
    EXPECT_GT(z.size(), 100u);
    expectZScoresOfNoise(z);
    return estimate(nee).mean;
}

// Bidirectional joins evaluate the BSDF at stored vertices, away from where the Surface was built: the
// textured Kd must travel with them. In a closed emissive box with textured walls bdpt and nee must agree.
TEST(Textures, BdptJoinsSeeTheSameTexturedKdAsNee) {
    ensureGlContext();
    Scene scene = furnaceBox(1.0f, 1.0f);
    for (Triangle& t : scene.triangles) {
        glm::vec3 n = glm::abs(t.geometricNormal());
        int axis = n.x > n.y && n.x > n.z ? 0 : n.y > n.z ? 1 : 2;
        for (int k = 0; k < 3; ++k)
            t.uv[size_t(k)] =
                0.5f * (glm::vec2(t.p[size_t(k)][(axis + 1) % 3], t.p[size_t(k)][(axis + 2) % 3]) + 1.0f);
    }
    scene.textures.push_back({"gradient", Rgba8Image{kTexSize, kTexSize, gradientTexels()}});
    scene.materials[0].diffuseTexture = 0;
    // With Kd 1 the box would hold radiance 1 + 1 + 1 + 1 after 3 bounces; the texture's albedo is
    // below 0.6, so the image must be well below that.
    EXPECT_LT(neeAgreesWithBdptInTheBox(scene).g, 2.5f);
}

// Vertex colours (Scene::colors, glTF COLOR_0) multiply Kd in a scene without textures too
// (VERTEX_COLORS alone), and bdpt's joins keep the coloured Kd of their stored vertices as they keep a
// textured one: in the closed emissive box of orange walls bdpt and nee agree, and the light is orange.
TEST(Textures, VertexColoursMultiplyKdForNeeAndBdptAlike) {
    ensureGlContext();
    Scene scene = furnaceBox(1.0f, 1.0f);
    const glm::vec4 orange(0.9f, 0.5f, 0.2f, 1.0f);
    scene.colors.assign(scene.triangles.size(), {orange, orange, orange});
    // Emission 1 plus Kd times it, bounce after bounce: 1 + k + k^2 + k^3 per channel with k = Kd times
    // the colour, so red well above blue.
    glm::vec3 mean = neeAgreesWithBdptInTheBox(scene);
    EXPECT_GT(mean.r, 1.4f * mean.b);
}

// Documented fallback: faces without vt show Kd times the texture's mean colour, with one warning, and
// the scene needs no texture data on the GPU at all.
TEST(Textures, QuadWithoutTexcoordsShowsTheMeanColour) {
    ensureGlContext();
    std::vector<uint8_t> rgba = gradientTexels();
    WarningCapture capture;
    Scene scene = texturedQuad(rgba, false);
    EXPECT_TRUE(capture.contains("without texture coordinates (vt)")) << joined(capture);
    glm::vec3 mean = meanLinearColor(Rgba8Image{kTexSize, kTexSize, rgba});
    Renderer renderer(scene, testShaders());
    EXPECT_EQ(renderer.stats().gpuTextureBytes, 0u);
    Image image = albedoView(renderer, 8);
    for (const glm::vec3& p : image.pixels)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], mean[c], 1e-6f);
}

TEST(Textures, TexelsOverTheBufferTextureLimitAreAClearError) {
    ensureGlContext();
    Scene scene = texturedQuad(gradientTexels(), true);  // 16 texels; 2 triangles: 6 texels of uvs
    AabbArray bounds;
    for (const Triangle& t : scene.triangles) bounds.push_back(t.bounds());
    PackedScene packed = packScene(scene, buildBinnedSah(bounds));
    EXPECT_NO_THROW(SceneTextures(packed, 16));
    std::string message = errorOf([&] { SceneTextures textures(packed, 15); });
    EXPECT_CONTAINS_ALL(message, "scene too large for this GPU", "texture texels buffer needs 16 texels",
                        "GL_MAX_TEXTURE_BUFFER_SIZE is 15", "1 textures");
}

}  // namespace
}  // namespace fp::test
