// The Khronos sample models (../shared/gltf-samples, tests/gltf_samples.h; credits in its README.md)
// rendered as a user's first command renders them: the plain defaults of the render request (its
// framing and its default light), small and with few samples. Each must show the model, lit: a smoke
// test of the whole path from file to image, and of the defaults of issue 34 (items 1 and 2): the
// camera in front, a flat model not seen edge-on, glowing detail not taken for light.
#include <gtest/gtest.h>

#include <cmath>

#include "gltf_samples.h"
#include "render_test_util.h"
#include "request/render_request.h"
#include "scene/lighting.h"
#include "scene/scene_test_util.h"

namespace fp::test {
namespace {

constexpr int kWidth = 64, kHeight = 48, kSpp = 4;

// One render of `path` with the plain command's defaults (RenderRequest, as `fragpath render PATH`
// reads them) at kWidth x kHeight and kSpp, with the same camera's depth (0 where no surface is seen)
// and, optionally, another debug view.
struct DefaultRender {
    Scene scene;
    Image radiance, depth, view;
};

DefaultRender renderWithDefaults(const std::string& path, View view = View::Radiance) {
    ensureGlContext();
    const std::vector<std::string> argv = {path, "--size",
                                           std::to_string(kWidth) + "x" + std::to_string(kHeight), "--spp",
                                           std::to_string(kSpp)};
    const RenderRequest request(Args(argv, requestOptionGroups(kAllRequestOptions)));
    DefaultRender out;
    out.scene = request.loadScene();
    RenderSettings settings = request.settings(out.scene);
    const Camera camera = request.camera(out.scene);
    Renderer renderer(out.scene, testShaders());
    renderer.configure(settings, camera);
    renderer.render(request.spp(out.scene));
    out.radiance = renderer.readback().mean();
    for (View v : {View::Depth, view}) {
        if (v == View::Radiance) continue;
        settings.view = v;
        renderer.configure(settings, camera);
        renderer.render(1);
        (v == View::Depth ? out.depth : out.view) = renderer.readback().mean();
    }
    return out;
}

// The fraction of pixels where the camera sees a surface.
double coverage(const DefaultRender& r) {
    int seen = 0;
    for (const glm::vec3& d : r.depth.pixels) seen += d.x > 0.0f ? 1 : 0;
    return double(seen) / double(r.depth.pixels.size());
}

// The mean luminance of the radiance where a surface is seen.
double meanOnModel(const DefaultRender& r) {
    double sum = 0.0;
    int n = 0;
    for (size_t i = 0; i < r.depth.pixels.size(); ++i)
        if (r.depth.pixels[i].x > 0.0f) {
            const glm::vec3& p = r.radiance.pixels[i];
            sum += 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z;
            ++n;
        }
    return n == 0 ? 0.0 : sum / n;
}

struct SampleModel {
    const char* name;
    const char* variant;
    const char* file;
};

// One variant of each of the 14 models. AnimatedMorphCube's glTF-Quantized needs KHR_mesh_quantization
// and is left to the compressed-mesh tests.
const SampleModel kSamples[] = {
    {"AnimatedMorphCube", "glTF-Binary", "AnimatedMorphCube.glb"},
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
// image (a camera behind it, or edge-on to a flat one, sees less), and its mean above 0.05 (the studio
// light gives a grey surface of albedo 0.5 about 0.4; unlit, it would be black).
TEST(GltfSamples, EveryModelRendersSeenAndLitWithThePlainDefaults) {
    WarningCapture quiet;  // the models' own warnings (ignored occlusion maps, ...) are not tested here
    for (const SampleModel& m : kSamples) {
        SCOPED_TRACE(m.name);
        const DefaultRender r = renderWithDefaults(gltfSample(m.name, m.variant, m.file));
        ASSERT_EQ(r.radiance.width, kWidth);
        for (const glm::vec3& p : r.radiance.pixels)
            ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        EXPECT_GT(coverage(r), 0.05);
        EXPECT_GT(meanOnModel(r), 0.05);
    }
}

// TwoSidedPlane is a square lying in y = 0: the old camera, level on the -z side, saw it edge-on and
// drew nothing. From 15 degrees above it covers a band across the image.
TEST(GltfSamples, TwoSidedPlaneIsSeenNotEdgeOn) {
    const DefaultRender r = renderWithDefaults(gltfSample("TwoSidedPlane", "glTF", "TwoSidedPlane.gltf"));
    EXPECT_GT(coverage(r), 0.15);
    EXPECT_GT(meanOnModel(r), 0.05);
}

// OrientationTest is a cube with an arrow on each face; its +z face carries the blue arrow (rotations
// about z by quaternion), the -z face the yellow one (the same by matrix). Seen from the front (+z),
// the normals facing the camera point along +z and blue shows, yellow does not; from the old -z side it
// was the other way round.
TEST(GltfSamples, OrientationTestIsSeenFromTheFront) {
    const DefaultRender normals =
        renderWithDefaults(gltfSample("OrientationTest", "glTF-Binary", "OrientationTest.glb"), View::Normal);
    int towardsPlusZ = 0, towardsMinusZ = 0;
    for (const glm::vec3& n : normals.view.pixels) {
        // The normal view maps n to 0.5 n + 0.5; a miss is 0 (z 0 too, so it counts as neither).
        if (n == glm::vec3(0.0f)) continue;
        towardsPlusZ += n.z > 0.9f ? 1 : 0;
        towardsMinusZ += n.z < 0.1f ? 1 : 0;
    }
    EXPECT_GT(towardsPlusZ, kWidth * kHeight / 10);
    EXPECT_EQ(towardsMinusZ, 0);
    const DefaultRender albedo =
        renderWithDefaults(gltfSample("OrientationTest", "glTF-Binary", "OrientationTest.glb"), View::Albedo);
    int blue = 0, yellow = 0;
    for (const glm::vec3& a : albedo.view.pixels) {
        blue += a.z > 0.3f && a.x < 0.1f && a.y < 0.1f ? 1 : 0;
        yellow += a.x > 0.3f && a.y > 0.3f && a.z < 0.1f ? 1 : 0;
    }
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
    EXPECT_GT(meanOnModel(r), 0.1);
}

}  // namespace
}  // namespace fp::test
