// A screenshot shows what the window shows: the CPU heat map of a count view matches the display pass.
#include "viewer/screenshot.h"

#include <gtest/gtest.h>
#include <stb_image.h>
#include <unistd.h>

#include <filesystem>

#include "gl/context.h"
#include "render/render_test_util.h"
#include "render/renderer.h"
#include "scene/builtin_scene.h"

namespace fp {
namespace {

TEST(Screenshot, CountViewPngMatchesTheDisplayPass) {
    test::ensureGlContext();
    Scene scene = builtinCornellBox();
    Renderer renderer(scene, test::testShaders());
    RenderSettings settings;
    settings.width = 32;
    settings.height = 24;
    settings.view = View::Nodes;
    renderer.configure(settings, *scene.camera);
    renderer.render(2);
    Image mean = renderer.readback().mean();

    DisplayOptions options;
    options.heatMax = 9.0f;  // some pixels above it: the clamp is covered too
    const int w = settings.width, h = settings.height;
    std::vector<unsigned char> gpu;
    {
        test::Rgba8Target target(w, h);
        Display display(test::testShaders());
        display.draw(renderer.textures(), w, h, options);
        gpu = target.read();
    }

    std::string path =
        (std::filesystem::temp_directory_path() / ("fragpath_heat_" + std::to_string(getpid()) + ".png"))
            .string();
    writeViewImage(path, mean, options);
    int pw = 0, ph = 0, channels = 0;
    unsigned char* png = stbi_load(path.c_str(), &pw, &ph, &channels, 3);
    std::filesystem::remove(path);
    ASSERT_NE(png, nullptr);
    ASSERT_EQ(pw, w);
    ASSERT_EQ(ph, h);
    int colours = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                int g = gpu[(size_t(h - 1 - y) * w + size_t(x)) * 4 + size_t(c)];  // GL rows bottom first
                int e = png[(size_t(y) * w + size_t(x)) * 3 + size_t(c)];
                EXPECT_NEAR(g, e, 1) << "pixel " << x << "," << y << " channel " << c;
                colours += e != png[(size_t(y) * w) * 3 + size_t(c)];
            }
    stbi_image_free(png);
    EXPECT_GT(colours, 0) << "not a uniform image";
}

}  // namespace
}  // namespace fp
