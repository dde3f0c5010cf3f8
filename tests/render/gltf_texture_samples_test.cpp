// glTF's core texture features on the Khronos sample models (tests/gltf_samples.h): KHR_texture_transform
// (TextureTransformTest), COLOR_0 (VertexColorTest), sampler wrap modes (TextureSettingsTest) and maps on
// TEXCOORD_1 (MultiUVTest), each rendered as its README says it must look. The albedo view (the base
// colour at the first hit) and the emission of a model under a black sky have no Monte Carlo noise, so
// the checks are exact up to the pixels' footprint; each camera is set here, looking at the models' front
// (+z) square on, whatever the default framing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "gltf_samples.h"
#include "image/tone_map.h"
#include "render_test_util.h"
#include "scene/instancing.h"
#include "scene/load.h"

namespace fp::test {
namespace {

// A camera at distance `distance` in front (+z) of the square of half-side `half` about `centre` in
// the plane z = `plane`, which fills a square image.
struct SquareView {
    glm::vec2 centre;
    float half;
    float distance = 4.0f;
    float plane = 0.0f;

    Camera camera() const {
        Camera c;
        c.eye = glm::vec3(centre, plane + distance);
        c.target = glm::vec3(centre, plane);
        c.fovY = glm::degrees(2.0f * std::atan(half / distance));
        return c;
    }
    // The point of the plane at pixel coordinates (x, y) of a size x size image (row 0 at the top).
    glm::vec2 planePoint(float x, float y, int size) const {
        return centre + half * glm::vec2(2.0f * x / float(size) - 1.0f, 1.0f - 2.0f * y / float(size));
    }
    // The pixel coordinates of point p (at depth z).
    glm::vec2 pixelOf(glm::vec3 p, int size) const {
        float scale = distance / (distance + plane - p.z);  // perspective: nearer points spread out
        glm::vec2 ndc = (glm::vec2(p) - centre) * scale / half;
        return float(size) * glm::vec2(ndc.x + 1.0f, 1.0f - ndc.y) / 2.0f;
    }
};

Image renderSquare(const Scene& scene, const SquareView& view, View debugView, int size, int spp) {
    ensureGlContext();
    Renderer renderer(scene, testShaders());
    RenderSettings s;
    s.width = s.height = size;
    s.view = debugView;
    s.maxDepth = 1;
    renderer.configure(s, view.camera());
    renderer.render(spp);
    return renderer.readback().mean();
}

// The bounding box in the plane z = 0 of the world triangles `which` selects.
Aabb boundsOf(const Scene& scene, const std::function<bool(size_t)>& which) {
    Aabb box;
    for (size_t t = 0; t < scene.triangles.size(); ++t)
        if (which(t)) box.grow(scene.triangles[t].bounds());
    return box;
}

bool materialNamed(const Scene& scene, size_t triangle, const std::string& name) {
    return scene.materials[scene.triangles[triangle].material].name == name;
}

// The pixels whose footprint lies inside `box` (shrunk by `margin` pixels on every side).
std::vector<glm::ivec2> pixelsInside(const Aabb& box, const SquareView& view, int size, int margin) {
    glm::vec2 a = view.pixelOf(box.lo, size), b = view.pixelOf(box.hi, size);
    glm::ivec2 lo(std::ceil(std::min(a.x, b.x)) + margin, std::ceil(std::min(a.y, b.y)) + margin);
    glm::ivec2 hi(std::floor(std::max(a.x, b.x)) - margin, std::floor(std::max(a.y, b.y)) - margin);
    std::vector<glm::ivec2> pixels;
    for (int y = std::max(lo.y, 0); y < std::min(hi.y, size); ++y)
        for (int x = std::max(lo.x, 0); x < std::min(hi.x, size); ++x) pixels.push_back({x, y});
    return pixels;
}

glm::vec3 linearTexel(const Rgba8Image& image, int x, int y) {
    const uint8_t* t = &image.texels[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
    return glm::vec3(srgbDecode(t[0] / 255.0f), srgbDecode(t[1] / 255.0f), srgbDecode(t[2] / 255.0f));
}

// Expects `rendered` (size x size) to show texture `image` wherever the texture is one colour over the
// whole bilinear footprint of a pixel (edges blur), with uvAt giving glTF's uv (v down the image) of each
// point of the plane the view looks at, wrapped by `wrap`, times `factor`; pixels that `hidden` marks are
// skipped.
void expectTheTexture(const Image& rendered, const SquareView& view, const Rgba8Image& image,
                      const std::function<glm::vec2(glm::vec2)>& uvAt, TextureWrap wrap,
                      const std::vector<bool>& hidden, glm::vec3 factor = glm::vec3(1.0f)) {
    const int size = rendered.width;
    auto wrapped = [wrap](float v, int n) {
        int i = int(std::floor(v));
        if (wrap == TextureWrap::ClampToEdge) return std::clamp(i, 0, n - 1);
        return ((i % n) + n) % n;
    };
    int compared = 0, wrong = 0;
    for (int y = 1; y < size - 1; ++y)
        for (int x = 1; x < size - 1; ++x) {
            if (!hidden.empty() && hidden[size_t(y) * size_t(size) + size_t(x)]) continue;
            glm::vec2 lo(1e9f), hi(-1e9f);  // the pixel's footprint in texels (centres at half-integers)
            for (int corner = 0; corner < 4; ++corner) {
                glm::vec2 t = uvAt(view.planePoint(float(x + (corner & 1)), float(y + (corner >> 1)), size)) *
                              glm::vec2(image.width, image.height);
                lo = glm::min(lo, t);
                hi = glm::max(hi, t);
            }
            glm::vec3 first =
                linearTexel(image, wrapped(lo.x - 0.5f, image.width), wrapped(lo.y - 0.5f, image.height));
            bool solid = true;
            for (float ty = std::floor(lo.y - 0.5f); ty <= std::floor(hi.y + 0.5f) && solid; ty += 1.0f)
                for (float tx = std::floor(lo.x - 0.5f); tx <= std::floor(hi.x + 0.5f) && solid; tx += 1.0f)
                    solid = glm::all(glm::lessThan(
                        glm::abs(linearTexel(image, wrapped(tx, image.width), wrapped(ty, image.height)) -
                                 first),
                        glm::vec3(1e-3f)));
            if (!solid) continue;
            ++compared;
            glm::vec3 got = rendered.at(x, y), expected = factor * first;
            if (!glm::all(glm::lessThan(glm::abs(got - expected), glm::vec3(0.02f)))) {
                if (wrong < 5)
                    ADD_FAILURE() << "pixel (" << x << ", " << y << "): " << got.x << " " << got.y << " "
                                  << got.z << ", expected " << expected.x << " " << expected.y << " "
                                  << expected.z;
                ++wrong;
            }
        }
    EXPECT_GT(compared, size * size / 4) << "too few pixels of one texture colour to compare";
    EXPECT_EQ(wrong, 0) << "of " << compared << " pixels";
}

// TextureTransformTest: six unit quads (local (x, y) in [-1/2, 1/2]^2 at glTF uv (x + 1/2, 1/2 - y),
// scaled to a half for the offset row) whose base colour textures go through KHR_texture_transform with a
// CLAMP_TO_EDGE sampler. Each cell's albedo must be its texture at uv' = T R S uv, clamped, with R the
// rotation the README asks for: u' = c u + s v, v' = -s u + c v, which turns the arrow (pointing down
// and right in Arrow.png) 22.5 degrees clockwise on the quad towards the green marker ("Rotation -
// Correct" at (-0.079, -0.516) from the cell's centre); the transpose would turn it onto the red one at
// (0.516, 0.079). Compared where the texture is one colour over the pixel's whole footprint (edges
// blur), away from the markers drawn in front.
struct TransformCell {
    const char* material;
    glm::vec2 centre;
    glm::vec2 uvScale;  // of the quad's TEXCOORD_0 (the offset row's reach (0.5, 0.5))
    glm::vec2 offset, scale;
    float rotation;
};

TEST(GltfTextureSamples, TextureTransformTestCellsShowTheirTransformedTexture) {
    Scene scene = loadScene(gltfSample("TextureTransformTest", "glTF", "TextureTransformTest.gltf"));
    const Scene flat = flattenInstances(scene);  // the markers are instanced
    const TransformCell cells[] = {
        {"Offset U", {-1.1f, 0.55f}, {0.5f, 0.5f}, {0.5f, 0.0f}, {1.0f, 1.0f}, 0.0f},
        {"Offset V", {0.0f, 0.55f}, {0.5f, 0.5f}, {0.0f, 0.5f}, {1.0f, 1.0f}, 0.0f},
        {"Offset UV", {1.1f, 0.55f}, {0.5f, 0.5f}, {0.5f, 0.5f}, {1.0f, 1.0f}, 0.0f},
        {"Rotation", {-1.1f, -0.55f}, {1.0f, 1.0f}, {0.0f, 0.0f}, {1.0f, 1.0f}, 0.39269908f},
        {"Scale", {0.0f, -0.55f}, {1.0f, 1.0f}, {0.0f, 0.0f}, {1.5f, 1.5f}, 0.0f},
        {"All", {1.1f, -0.55f}, {1.0f, 1.0f}, {-0.2f, -0.1f}, {1.5f, 1.5f}, 0.3f},
    };
    const char* markers[] = {"Correct", "NotSupported", "Error"};
    const int size = 48;
    for (const TransformCell& cell : cells) {
        SCOPED_TRACE(cell.material);
        SquareView view{cell.centre, 0.5f};
        Image albedo = renderSquare(scene, view, View::Albedo, size, 16);
        size_t quad = 0;
        while (!materialNamed(flat, quad, cell.material)) ++quad;
        const Material& material = flat.materials[flat.triangles[quad].material];
        const Rgba8Image& image = flat.textures[size_t(material.diffuseTexture)].image;
        std::vector<bool> hidden(size_t(size) * size_t(size), false);  // behind a marker
        for (const char* marker : markers)
            for (glm::ivec2 p :
                 pixelsInside(boundsOf(flat, [&](size_t t) { return materialNamed(flat, t, marker); }), view,
                              size, -2))
                hidden[size_t(p.y) * size_t(size) + size_t(p.x)] = true;
        const float c = std::cos(cell.rotation), s = std::sin(cell.rotation);
        auto uvAt = [&](glm::vec2 q) {
            glm::vec2 local = q - cell.centre;
            glm::vec2 uv = glm::vec2(local.x + 0.5f, 0.5f - local.y) * cell.uvScale * cell.scale;
            return glm::vec2(c * uv.x + s * uv.y, -s * uv.x + c * uv.y) + cell.offset;
        };
        expectTheTexture(albedo, view, image, uvAt, TextureWrap::ClampToEdge, hidden);
    }
}

// VertexColorTest: the top row's three cells (x in [-0.779, -0.317], [-0.231, 0.231] and [0.361, 0.823],
// y in [0.109, 0.572]) hold checkmarks of every colour over crosses of the other two channels, and
// COLOR_0 of pure red, green and blue: multiplied by it, each cell shows only its own channel (the
// README: a cross that shows means the vertex colours were ignored).
TEST(GltfTextureSamples, VertexColorTestShowsOnlyEachCellsChannel) {
    Scene scene = loadScene(gltfSample("VertexColorTest", "glTF-Binary", "VertexColorTest.glb"));
    SquareView view{{0.0f, 0.0f}, 1.0f};
    const int size = 64;
    Image albedo = renderSquare(scene, view, View::Albedo, size, 8);
    const float xs[3][2] = {{-0.779f, -0.317f}, {-0.231f, 0.231f}, {0.361f, 0.823f}};
    for (int channel = 0; channel < 3; ++channel) {
        SCOPED_TRACE("the cell of channel " + std::to_string(channel));
        Aabb cell;
        cell.grow(glm::vec3(xs[channel][0], 0.109f, 0.0f));
        cell.grow(glm::vec3(xs[channel][1], 0.572f, 0.0f));
        float own = 0.0f, others = 0.0f;
        for (glm::ivec2 p : pixelsInside(cell, view, size, 1)) {
            glm::vec3 a = albedo.at(p.x, p.y);
            own = std::max(own, a[channel]);
            others = std::max({others, a[(channel + 1) % 3], a[(channel + 2) % 3]});
        }
        EXPECT_GT(own, 0.3f) << "the checkmark";
        EXPECT_LT(others, 0.01f) << "a cross of the other channels shows";
    }
}

// TextureSettingsTest: the "Test" column's clamp, repeat and mirror cells (materials
// Texture{Clamp,Repeat,Mirror}Material{S,T}) show a green check or a green box when their sampler's wrap
// mode is honoured, and a red cross or a red box where another mode is used instead (the README).
TEST(GltfTextureSamples, TextureSettingsTestWrapCellsShowNoRed) {
    Scene scene = loadScene(gltfSample("TextureSettingsTest", "glTF-Binary", "TextureSettingsTest.glb"));
    const Scene flat = flattenInstances(scene);
    Aabb all = flat.bounds();
    glm::vec2 centre = glm::vec2(all.lo + all.hi) / 2.0f;
    SquareView view{centre, 0.52f * std::max(all.hi.x - all.lo.x, all.hi.y - all.lo.y),
                    4.0f * (all.hi.y - all.lo.y)};
    const int size = 128;
    Image albedo = renderSquare(scene, view, View::Albedo, size, 8);
    for (const char* material :
         {"TextureClampMaterialS", "TextureClampMaterialT", "TextureRepeatMaterialS",
          "TextureRepeatMaterialT", "TextureMirrorMaterialS", "TextureMirrorMaterialT"}) {
        SCOPED_TRACE(material);
        Aabb cell = boundsOf(flat, [&](size_t t) { return materialNamed(flat, t, material); });
        ASSERT_TRUE(cell.lo.x < cell.hi.x) << "no such material";
        int red = 0, green = 0;
        for (glm::ivec2 p : pixelsInside(cell, view, size, 1)) {
            glm::vec3 a = albedo.at(p.x, p.y);
            red += a.r > 0.1f && a.r > 3.0f * a.g;
            green += a.g > 0.1f && a.g > 3.0f * a.r;
        }
        EXPECT_EQ(red, 0) << "red pixels: the wrong wrap mode";
        EXPECT_GT(green, 10) << "the green check or box";
    }
}

// MultiUVTest: a cube whose emissive texture reads TEXCOORD_1 (emissiveFactor 1) over a base colour on
// TEXCOORD_0. Its +z face has TEXCOORD_1 u = (x + 1) / 8, v = (1 - y) / 8: the glTF logo of the
// texture's top left. Under a black sky the face's radiance is exactly its emission, that texture.
TEST(GltfTextureSamples, MultiUVTestShowsTheEmissiveMapOnTheSecondSet) {
    Scene scene = loadScene(gltfSample("MultiUVTest", "glTF-Binary", "MultiUVTest.glb"));
    ASSERT_TRUE(scene.environment.isBlack());
    SquareView view{{0.0f, 0.0f}, 1.0f, 5.0f, 1.0f};  // the face's plane, z = 1
    Image radiance = renderSquare(scene, view, View::Radiance, 64, 8);
    size_t quad = 0;
    while (quad < scene.triangles.size() &&
           !(scene.materials[scene.triangles[quad].material].emission.x > 0.0f))
        ++quad;
    ASSERT_LT(quad, scene.triangles.size());
    const Material& material = scene.materials[scene.triangles[quad].material];
    ASSERT_GE(material.emissionTexture, 0) << "the emissive map was dropped";
    const Rgba8Image& image = scene.textures[size_t(material.emissionTexture)].image;
    auto uvAt = [](glm::vec2 q) { return glm::vec2(q.x + 1.0f, 1.0f - q.y) / 8.0f; };
    expectTheTexture(radiance, view, image, uvAt, TextureWrap::Repeat, {});
}

// TextureCoordinateTest: four quads of side 1 at x, y = +-0.2 to +-1.2, each showing the part of one
// texture that lies where the quad lies (its accessors' names: TopLeft_TEXCOORD_0 spans u and v from 0 to
// 0.4, glTF's v = 0 being the image's top), at 0.4 uv per unit, times its base colour factor.
TEST(GltfTextureSamples, TextureCoordinateTestQuadsShowTheirCornerOfTheTexture) {
    Scene scene = loadScene(gltfSample("TextureCoordinateTest", "glTF-Binary", "TextureCoordinateTest.glb"));
    struct Quad {
        const char* material;
        glm::vec2 topLeft;  // of the quad, in the plane
        glm::vec2 uv;       // there
    };
    const Quad quads[] = {{"TopLeftMat", {-1.2f, 1.2f}, {0.0f, 0.0f}},
                          {"TopRightMat", {0.2f, 1.2f}, {0.6f, 0.0f}},
                          {"BottomLeftMat", {-1.2f, -0.2f}, {0.0f, 0.6f}},
                          {"BottomRightMat", {0.2f, -0.2f}, {0.6f, 0.6f}}};
    for (const Quad& quad : quads) {
        SCOPED_TRACE(quad.material);
        SquareView view{quad.topLeft + glm::vec2(0.5f, -0.5f), 0.45f};
        Image albedo = renderSquare(scene, view, View::Albedo, 32, 8);
        size_t t = 0;
        while (!materialNamed(scene, t, quad.material)) ++t;
        const Material& material = scene.materials[scene.triangles[t].material];
        ASSERT_GE(material.diffuseTexture, 0);
        auto uvAt = [&](glm::vec2 q) {
            return quad.uv + 0.4f * glm::vec2(q.x - quad.topLeft.x, quad.topLeft.y - q.y);
        };
        expectTheTexture(albedo, view, scene.textures[size_t(material.diffuseTexture)].image, uvAt,
                         TextureWrap::Repeat, {}, material.diffuse);
    }
}

}  // namespace
}  // namespace fp::test
