// The Khronos sample models (../shared/gltf-samples, tests/gltf_samples.h; credits in its README.md)
// rendered as a user's first command renders them: the plain defaults of the render request (its
// framing and its default light), small and with few samples. Each must show the model, lit: a smoke
// test of the whole path from file to image, and of the defaults of issue 34 (items 1 and 2): the
// camera in front, a flat model not seen edge-on, glowing detail not taken for light.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>

#include "gltf_samples.h"
#include "render_test_util.h"
#include "request/render_request.h"
#include "scene/lighting.h"
#include "scene/scene_test_util.h"

namespace fp::test {
namespace {

constexpr int kWidth = 64, kHeight = 48, kSpp = 4;

// One render of `path` with the plain command's defaults (RenderRequest, as `fragpath render PATH`
// reads them) at kWidth x kHeight and kSpp, with the first-hit guides the denoisers use (which change
// nothing in the radiance and cost no second shader compile): per pixel, the mean over the samples of
// the distance to the first surface (0 where none is seen), its shading normal (the side facing the
// camera) and its albedo.
struct DefaultRender {
    Scene scene;
    Image radiance, depth, normal, albedo;
};

DefaultRender renderWithDefaults(const std::string& path) {
    ensureGlContext();
    const std::vector<std::string> argv = {path, "--size",
                                           std::to_string(kWidth) + "x" + std::to_string(kHeight), "--spp",
                                           std::to_string(kSpp)};
    const RenderRequest request(Args(argv, requestOptionGroups(kAllRequestOptions)));
    DefaultRender out;
    out.scene = request.loadScene();
    RenderSettings settings = request.settings(out.scene);
    settings.guides = true;
    Renderer renderer(out.scene, testShaders());
    renderer.configure(settings, request.camera(out.scene));
    renderer.render(request.spp(out.scene));
    const Accumulation a = renderer.readback();
    out.radiance = a.mean();
    out.depth = out.normal = out.albedo = Image(a.width, a.height);
    for (size_t i = 0; i < a.albedo.size(); ++i) {
        const float samples = std::max(a.albedo[i].w, 1.0f);
        out.depth.pixels[i] = glm::vec3(a.normalDepth[i].w / samples);
        out.normal.pixels[i] = glm::vec3(a.normalDepth[i]) / samples;
        out.albedo.pixels[i] = glm::vec3(a.albedo[i]) / samples;
    }
    return out;
}

// The fraction of pixels where the camera sees a surface.
double coverage(const DefaultRender& r) {
    int seen = 0;
    for (const glm::vec3& d : r.depth.pixels) seen += d.x > 0.0f ? 1 : 0;
    return double(seen) / double(r.depth.pixels.size());
}

double luminanceOf(const glm::vec3& p) {
    return 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z;
}

// The mean luminance of `image` where a surface is seen.
double meanOnModel(const DefaultRender& r, const Image& image) {
    double sum = 0.0;
    int n = 0;
    for (size_t i = 0; i < r.depth.pixels.size(); ++i)
        if (r.depth.pixels[i].x > 0.0f) {
            sum += luminanceOf(image.pixels[i]);
            ++n;
        }
    return n == 0 ? 0.0 : sum / n;
}

struct SampleModel {
    const char* name;
    const char* variant;
    const char* file;
};

// One variant of each of the 14 models, and AnimatedMorphCube's glTF-Quantized as well.
const SampleModel kSamples[] = {
    {"AnimatedMorphCube", "glTF-Binary", "AnimatedMorphCube.glb"},
    {"AnimatedMorphCube", "glTF-Quantized", "AnimatedMorphCube.gltf"},
    {"Box With Spaces", "glTF", "Box With Spaces.gltf"},
    {"Cameras", "glTF", "Cameras.gltf"},
    {"MultiUVTest", "glTF-Binary", "MultiUVTest.glb"},
    {"NegativeScaleTest", "glTF-Binary", "NegativeScaleTest.glb"},
    {"NormalTangentTest", "glTF-Binary", "NormalTangentTest.glb"},
    {"OrientationTest", "glTF-Binary", "OrientationTest.glb"},
    {"SimpleInstancing", "glTF-Binary", "SimpleInstancing.glb"},
    {"TextureCoordinateTest", "glTF-Binary", "TextureCoordinateTest.glb"},
    {"TextureSettingsTest", "glTF-Binary", "TextureSettingsTest.glb"},
    {"TextureTransformTest", "glTF", "TextureTransformTest.gltf"},
    {"TwoSidedPlane", "glTF", "TwoSidedPlane.gltf"},
    {"UnlitTest", "glTF-Binary", "UnlitTest.glb"},
    {"VertexColorTest", "glTF-Binary", "VertexColorTest.glb"},
};

// Every model renders, seen and lit: finite radiance everywhere, the model over at least 5 % of the
// image (a camera behind a flat model, or edge-on to it, sees less), and its mean radiance at least a
// fifth of its mean albedo (the studio light shows a surface facing the camera at 0.87 of its
// albedo, a surface facing away at about a third; unlit, it would be black).
// Two files need extensions that other parts of issue 34 add: until then each must fail with the
// loader's clear message, after which it renders like the rest.
TEST(GltfSamples, EveryModelRendersSeenAndLitWithThePlainDefaults) {
    WarningCapture quiet;  // the models' own warnings (ignored occlusion maps, ...) are not tested here
    const std::map<std::string, std::string> pending = {
        {"UnlitTest", "requires the extension KHR_materials_unlit, which fragpath does not implement"},
        {"AnimatedMorphCube/glTF-Quantized", "KHR_mesh_quantization"}};
    for (const SampleModel& m : kSamples) {
        SCOPED_TRACE(std::string(m.name) + "/" + m.variant);
        const auto waiting = pending.count(m.name) ? pending.find(m.name)
                                                   : pending.find(std::string(m.name) + "/" + m.variant);
        std::optional<DefaultRender> rendered;
        try {
            rendered = renderWithDefaults(gltfSample(m.name, m.variant, m.file));
        } catch (const Error& e) {
            ASSERT_NE(waiting, pending.end()) << e.what();
            EXPECT_NE(std::string(e.what()).find(waiting->second), std::string::npos) << e.what();
            continue;
        }
        const DefaultRender& r = *rendered;
        ASSERT_EQ(r.radiance.width, kWidth);
        for (const glm::vec3& p : r.radiance.pixels)
            ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        EXPECT_GT(coverage(r), 0.05);
        EXPECT_GT(meanOnModel(r, r.radiance), 0.2 * meanOnModel(r, r.albedo));
        EXPECT_GT(meanOnModel(r, r.radiance), 0.01);
    }
}

// TwoSidedPlane is a square lying in y = 0: the old camera, level on the -z side, saw it edge-on and
// drew nothing. From 15 degrees above it covers a band across the image.
TEST(GltfSamples, TwoSidedPlaneIsSeenNotEdgeOn) {
    const DefaultRender r = renderWithDefaults(gltfSample("TwoSidedPlane", "glTF", "TwoSidedPlane.gltf"));
    EXPECT_GT(coverage(r), 0.15);
    EXPECT_GT(meanOnModel(r, r.radiance), 0.2 * meanOnModel(r, r.albedo));
}

// OrientationTest is a cube with an arrow on each face; its +z face carries the blue arrow (rotations
// about z by quaternion), the -z face the yellow one (the same by matrix). Seen from the front (+z),
// the first hits' normals (facing the camera) point along +z, none along -z, and the blue arrow's
// albedo shows, the yellow one's does not; from the old -z side it was the other way round.
TEST(GltfSamples, OrientationTestIsSeenFromTheFront) {
    const DefaultRender r =
        renderWithDefaults(gltfSample("OrientationTest", "glTF-Binary", "OrientationTest.glb"));
    int towardsPlusZ = 0, towardsMinusZ = 0, blue = 0, yellow = 0;
    for (size_t i = 0; i < r.depth.pixels.size(); ++i) {
        if (!(r.depth.pixels[i].x > 0.0f)) continue;
        const glm::vec3 n = r.normal.pixels[i], a = r.albedo.pixels[i];
        towardsPlusZ += n.z > 0.8f ? 1 : 0;
        towardsMinusZ += n.z < -0.2f ? 1 : 0;
        blue += a.z > 0.3f && a.x < 0.1f && a.y < 0.1f ? 1 : 0;
        yellow += a.x > 0.3f && a.y > 0.3f && a.z < 0.1f ? 1 : 0;
    }
    EXPECT_GT(towardsPlusZ, kWidth * kHeight / 10);
    EXPECT_EQ(towardsMinusZ, 0);
    EXPECT_GT(blue, 20);
    EXPECT_EQ(yellow, 0);
}

// MultiUVTest glows all over (emissiveFactor 1 times a texture): glowing detail, not light, so it gets
// the studio environment, which the old rule (any emitter counts) switched off.
TEST(GltfSamples, GlowingDetailGetsTheStudioLight) {
    const DefaultRender r = renderWithDefaults(gltfSample("MultiUVTest", "glTF-Binary", "MultiUVTest.glb"));
    EXPECT_TRUE(hasLight(r.scene)) << "it has emitters";
    EXPECT_TRUE(r.scene.environment.hasMap()) << "and the studio light as well";
}

// A grey cube (faces outward) with one small glowing quad on its front: the quad's light leaves the
// model, so the cube's other faces would be black without the studio light.
TEST(GltfSamples, AModelWithAGlowingPatchIsLit) {
    TempDir dir;
    dir.write("glow.mtl", "newmtl grey\nKd 0.5 0.5 0.5\nnewmtl glow\nKd 0 0 0\nKe 4 4 4\n");
    const std::string obj =
        dir.write("glow.obj",
                  "mtllib glow.mtl\n"
                  "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
                  "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                  "v -0.2 -0.2 1.001\nv 0.2 -0.2 1.001\nv 0.2 0.2 1.001\nv -0.2 0.2 1.001\n"
                  "usemtl grey\n"
                  "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n"
                  "usemtl glow\nf 9 10 11 12\n");
    const DefaultRender r = renderWithDefaults(obj);
    EXPECT_TRUE(r.scene.environment.hasMap());
    // The patch covers under a tenth of the model's pixels: the rest must be lit by the studio.
    EXPECT_GT(coverage(r), 0.2);
    EXPECT_GT(meanOnModel(r, r.radiance), 0.2 * 0.5);
}

}  // namespace
}  // namespace fp::test
