// Environment maps: read from .hdr files, importance-sampled by luminance, rotated, and consistent
// with BSDF sampling (MIS only stays unbiased if both strategies agree on every density).
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <filesystem>
#include <fstream>

#include "analytic_lamp.h"
#include "core/error.h"
#include "render_test_util.h"
#include "scene/load.h"

namespace fp::test {
namespace {

Image skyWithSun(int width, int height) {
    Image map(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            map.at(x, y) = glm::vec3(0.2f, 0.3f, 0.5f) * (y < height / 2 ? 1.0f : 0.3f);
    // A small, very bright sun: the case where sampling the map by luminance matters.
    for (int y = 3; y < 5; ++y)
        for (int x = 10; x < 12; ++x) map.at(x, y) = glm::vec3(400.0f, 300.0f, 200.0f);
    return map;
}

Camera view() {
    Camera c;
    c.eye = glm::vec3(0.0f, 0.4f, -3.5f);
    c.fovY = 40.0f;
    return c;
}

TEST(EnvironmentMap, ConstantMapIsTheConstantEnvironment) {
    ensureGlContext();
    Image white(16, 8);
    for (glm::vec3& p : white.pixels) p = glm::vec3(1.0f);
    Scene scene = sphereUnderSky(white);
    scene.materials[0].diffuse = glm::vec3(0.5f);
    Renderer renderer(scene, testShaders());
    Accumulation acc = renderScene(renderer, view(), Integrator::Nee, 24, 64, 5);
    // A convex Lambertian object of albedo 0.5 under radiance 1 is 0.5; the background is 1.
    Image mean = acc.mean();
    EXPECT_EQ(mean.at(0, 0), glm::vec3(1.0f));
    ImageEstimate centre = estimate(acc, 9, 9, 6, 6);
    EXPECT_NEAR(centre.mean.g, 0.5f, 5.0f * centre.standardError.g + 1e-5f);
    EXPECT_LT(centre.standardError.g, 0.01f);
}

TEST(EnvironmentMap, LightSamplingAndBsdfSamplingAgree) {
    ensureGlContext();
    Scene scene = sphereUnderSky(skyWithSun(32, 16));
    Renderer renderer(scene, testShaders());
    Accumulation nee = renderScene(renderer, view(), Integrator::Nee, 24, 256, 3);
    Accumulation bsdf = renderScene(renderer, view(), Integrator::Bsdf, 24, 1024, 3);
    ImageEstimate a = estimate(nee), b = estimate(bsdf);
    for (int c = 0; c < 3; ++c) {
        float se =
            std::sqrt(a.standardError[c] * a.standardError[c] + b.standardError[c] * b.standardError[c]);
        EXPECT_NEAR(a.mean[c], b.mean[c], 5.0f * se) << "channel " << c;
        EXPECT_LT(se, 0.03f * a.mean[c]);
    }
    // Importance sampling the sun makes light sampling far less noisy per sample.
    EXPECT_LT(a.standardError.g * 2.0f, b.standardError.g);
}

// A grey plane under a dim 1024 x 512 sky with a sun of 2 x 2 texels 30 degrees high, 10^6 times as bright
// (the sun is nearly all the light, which keeps the estimate's noise low):
// every point of the plane sees the upper hemisphere, so its radiance is albedo / pi times the sum over
// the upper rows of radiance x the texel's cosine-weighted solid angle, (2 pi / W) (sin^2 theta1 -
// sin^2 theta0) / 2. Light samples that took the texel found again from their direction (a neighbour
// for about 0.4 % of them, whose small density gave them a small MIS weight) lost 0.4 % of the sun.
TEST(EnvironmentMap, SmallBrightSunLightsAPlaneExactly) {
    ensureGlContext();
    const int width = 1024, height = 512;
    Image map(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            map.at(x, y) = y < height / 2 ? glm::vec3(0.03f, 0.04f, 0.08f) : glm::vec3(0.02f);
    for (int y = 170; y < 172; ++y)
        for (int x = 600; x < 602; ++x) map.at(x, y) = glm::vec3(160000.0f, 150000.0f, 130000.0f);
    const float albedo = 0.5f;
    glm::dvec3 irradiance(0.0);
    for (int y = 0; y < height / 2; ++y) {
        double t0 = M_PI * y / height, t1 = M_PI * (y + 1) / height;
        double weight =
            2.0 * M_PI / width * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) / 2.0;
        for (int x = 0; x < width; ++x) irradiance += glm::dvec3(map.at(x, y)) * weight;
    }
    const glm::dvec3 expected = double(albedo) / M_PI * irradiance;

    Scene scene;
    scene.source = "plane under a sky with a small sun";
    Material floor;
    floor.diffuse = glm::vec3(albedo);
    scene.materials = {floor};
    const float f = 100.0f;
    const glm::vec3 corners[4] = {{-f, 0, -f}, {-f, 0, f}, {f, 0, f}, {f, 0, -f}};
    appendQuad(scene, corners, 0);
    scene.environment.map = map;
    Camera camera;  // a 2-degree spot under a pinhole 1 above the plane: the whole image sees the plane
    camera.eye = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.target = glm::vec3(0.0f);
    camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
    camera.fovY = 2.0f;
    Renderer renderer(scene, testShaders());
    Accumulation acc = renderScene(renderer, camera, Integrator::Nee, 16, 4096, 1);
    ImageEstimate whole = estimate(acc);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(whole.mean[c], expected[c], 4.0f * whole.standardError[c]) << "channel " << c;
        EXPECT_LT(whole.standardError[c], 1e-3 * expected[c]) << "channel " << c;  // 0.4 % is 4 errors
    }
    for (int by = 0; by < 16; by += 8)
        for (int bx = 0; bx < 16; bx += 8) {
            ImageEstimate block = estimate(acc, bx, by, 8, 8);
            EXPECT_NEAR(block.mean.g, expected.g, 4.5f * block.standardError.g)
                << "block " << bx << ", " << by;
        }
}

TEST(EnvironmentMap, RotationTurnsTheMapAboutUp) {
    ensureGlContext();
    // Left half of the map red, right half green: the camera looks along +z, which is u = 1/2 + ...
    Image map(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) map.at(x, y) = x < 4 ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    Scene scene = sphereUnderSky(map);
    Camera c;
    c.eye = glm::vec3(0.0f, 5.0f, 0.0f);  // above the sphere, looking past it along +x
    c.target = glm::vec3(1.0f, 5.0f, 0.0f);
    c.fovY = 5.0f;
    auto centre = [&](float degrees) {
        scene.environment.rotationDegrees = degrees;
        Renderer renderer(scene, testShaders());
        RenderSettings s;
        s.width = s.height = 9;
        s.integrator = Integrator::Bsdf;
        renderer.configure(s, c);
        renderer.render(1);
        return renderer.readback().mean().at(4, 4);
    };
    glm::vec3 unrotated = centre(0.0f), turned = centre(180.0f);
    // +x maps to u = 1/2 + atan(1, 0) / 2pi = 3/4: green. Turned half a turn, u = 1/4: red.
    EXPECT_EQ(unrotated, glm::vec3(0, 1, 0));
    EXPECT_EQ(turned, glm::vec3(1, 0, 0));
}

class EnvironmentFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() / ("fragpath_env_" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
        std::ofstream(dir_ / "box.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::string scene(const std::string& environment) {
        std::ofstream(dir_ / "scene.json")
            << "{\"mesh\": \"box.obj\", \"environment\": " << environment << "}";
        return (dir_ / "scene.json").string();
    }
    std::filesystem::path dir_;
};

TEST_F(EnvironmentFiles, HdrMapLoadsWithIntensityAndRotation) {
    Image sky = skyWithSun(32, 16);
    std::vector<float> rgb;
    for (const glm::vec3& p : sky.pixels) rgb.insert(rgb.end(), {p.x, p.y, p.z});
    ASSERT_TRUE(stbi_write_hdr((dir_ / "sky.hdr").c_str(), 32, 16, 3, rgb.data()));
    Scene s = loadScene(scene(R"({"map": "sky.hdr", "intensity": 2, "rotation": 90})"));
    ASSERT_TRUE(s.environment.hasMap());
    EXPECT_EQ(s.environment.map.width, 32);
    EXPECT_EQ(s.environment.intensity, 2.0f);
    EXPECT_EQ(s.environment.rotationDegrees, 90.0f);
    // RGBE keeps 8 bits of mantissa.
    EXPECT_NEAR(s.environment.map.at(10, 3).x, 400.0f, 400.0f / 128.0f);
}

TEST_F(EnvironmentFiles, BadMapsAreClearErrors) {
    std::ofstream(dir_ / "fake.hdr") << "this is not an image";
    auto message = [&](const std::string& environment) {
        try {
            loadScene(scene(environment));
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(R"({"map": "fake.hdr"})").find("not a Radiance HDR image"), std::string::npos);
    EXPECT_NE(message(R"({"map": "missing.hdr"})").find("missing.hdr"), std::string::npos);
    EXPECT_NE(message(R"({"map": "box.obj"})").find("must be a Radiance .hdr or an OpenEXR .exr file"),
              std::string::npos);
    EXPECT_NE(message(R"({"color": [1, 1, 1], "map": "fake.hdr"})").find("either"), std::string::npos);
    EXPECT_NE(message(R"({"color": [1, -1, 1]})").find("negative"), std::string::npos);
}

}  // namespace
}  // namespace fp::test
