// Debug views and the display pass.
#include <gtest/gtest.h>

#include "image/png.h"
#include "render/display.h"
#include "render_test_util.h"
#include "scene/builtin_scene.h"

namespace fp::test {
namespace {

Image renderView(Renderer& renderer, const Camera& camera, View view, int maxDepth, int spp) {
    RenderSettings s;
    s.width = s.height = 24;
    s.view = view;
    s.maxDepth = maxDepth;
    renderer.configure(s, camera);
    renderer.render(spp);
    return renderer.readback().mean();
}

TEST(Views, CountsAreWithinTheirBounds) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    for (int depth : {0, 2, 5}) {
        Image bounces = renderView(renderer, *scene.camera, View::Bounces, depth, 8);
        float maxBounces = 0.0f;
        for (const glm::vec3& p : bounces.pixels) maxBounces = std::max(maxBounces, p.x);
        EXPECT_LE(maxBounces, float(depth));
        if (depth > 0) {
            EXPECT_GT(maxBounces, 0.0f);
        }
    }
    Image nodes = renderView(renderer, *scene.camera, View::Nodes, 5, 1);
    Image triangles = renderView(renderer, *scene.camera, View::Triangles, 5, 1);
    for (size_t i = 0; i < nodes.pixels.size(); ++i) {
        EXPECT_GE(nodes.pixels[i].x, 1.0f) << "the root is always visited";
        EXPECT_LE(nodes.pixels[i].x, float(renderer.stats().bvh.nodeCount));
        EXPECT_LE(triangles.pixels[i].x, 32.0f);
    }
}

// The cost view (the study's counting mode) sums over every ray of a path: with max depth 0 a path is
// its camera ray alone, which shades at most one surface; with light sampling every ray visits at
// least the root node and tests at most all 32 triangles.
TEST(Views, CostCountsTheWholePath) {
    ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, testShaders());
    for (int depth : {0, 5}) {
        RenderSettings s;
        s.width = s.height = 16;
        s.view = View::Cost;
        s.maxDepth = depth;
        renderer.configure(s, *scene.camera);
        renderer.render(4);
        Accumulation acc = renderer.readback();
        double rays = acc.raysTraced() / (16.0 * 16.0 * 4.0);
        glm::dvec3 cost = meanColor(acc.mean());  // nodes, triangles, surfaces per path
        if (depth == 0) {
            EXPECT_EQ(rays, 1.0);
            EXPECT_LE(cost.z, 1.0);
            EXPECT_GT(cost.z, 0.5) << "most camera rays hit the box";
        } else {
            EXPECT_GT(rays, 2.0) << "bounce and shadow rays";
            EXPECT_GT(cost.z, 1.5);
        }
        EXPECT_GE(cost.x, rays);
        EXPECT_LE(cost.y, 32.0 * rays);
        EXPECT_LE(cost.z, rays);
    }
}

TEST(Views, NormalsAreUnitVectorsFacingTheCamera) {
    ensureGlContext();
    Scene scene = furnaceBox(0.5f, 0.0f);
    Renderer renderer(scene, testShaders());
    Image normals = renderView(renderer, insideCamera(), View::Normal, 5, 1);
    Image albedo = renderView(renderer, insideCamera(), View::Albedo, 5, 1);
    for (size_t i = 0; i < normals.pixels.size(); ++i) {
        glm::vec3 n = 2.0f * normals.pixels[i] - 1.0f;
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f);
        // Inside the cube every face is axis-aligned: one component is +-1.
        EXPECT_NEAR(std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)}), 1.0f, 1e-4f);
        EXPECT_EQ(albedo.pixels[i], glm::vec3(0.5f));
    }
}

// The window shows what a PNG would: the GPU display pass and the PNG writer agree to one code value.
TEST(DisplayPass, MatchesThePngWriter) {
    ensureGlContext();
    const int w = 16, h = 4;
    Image linear(w, h);
    std::vector<glm::vec4> sums(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::vec3 v(0.001f * float(x * x * x), 0.05f * float(x + y), 3.0f * float(y) / float(x + 1));
            float samples = float(1 + x % 3);
            linear.at(x, h - 1 - y) = v;  // Image rows are top first; GL rows bottom first
            sums[size_t(y) * w + size_t(x)] = glm::vec4(v * samples, samples);
        }
    GLuint texture;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, sums.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // complete without mipmaps
    Rgba8Target target(w, h);
    Display display(testShaders());
    for (ToneMap toneMap : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces}) {
        DisplayOptions options;
        options.tone = {0.5f, toneMap};
        display.draw({texture, 0, 0.0f}, w, h, options);
        std::vector<uint8_t> gpu = target.read();
        std::vector<uint8_t> cpu = toDisplay8(linear, options.tone);  // RGB, top row first
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) {
                    int g = gpu[(size_t(y) * w + size_t(x)) * 4 + size_t(c)];
                    int e = cpu[(size_t(h - 1 - y) * w + size_t(x)) * 3 + size_t(c)];
                    EXPECT_NEAR(g, e, 1) << "tone map " << int(toneMap) << " pixel " << x << "," << y;
                }
    }
    glDeleteTextures(1, &texture);
}

}  // namespace
}  // namespace fp::test
