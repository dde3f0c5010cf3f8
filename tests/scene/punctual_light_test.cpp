// Point, spot and directional lights on the CPU side (scene/punctual_light.h, scene/light_selection.h,
// scene/scene_file.cpp): the scene file's "lights", its errors, the spot's falloff, the powers that light
// selection weighs, and the one-line description the viewer's panel shows.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scene/light_selection.h"
#include "scene/load.h"
#include "scene/punctual_light.h"
#include "scene_test_util.h"

namespace fp {
namespace {

using test::errorOf;

constexpr double kPi = 3.14159265358979324;

// A directory holding a one-triangle mesh.obj and scene.json with `lights` as its "lights" value.
struct LightsFile {
    test::TempDir dir;
    std::string json;
    explicit LightsFile(const std::string& lights) {
        dir.write("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        json = dir.write("scene.json", R"({"mesh": "mesh.obj", "lights": )" + lights + "}");
    }
    Scene load() const { return loadScene(json); }
    // The error loading it gives; expects it to name the scene file and contain every fragment.
    template <typename... Fragments>
    void reject(const Fragments&... fragments) const {
        std::string message = errorOf([this] { load(); });
        EXPECT_CONTAINS_ALL(message, json, fragments...);
    }
};

TEST(PunctualLightFile, EveryTypeParsedInTheRendererUnits) {
    LightsFile f(R"([
        {"type": "point", "position": [1, 2, 3], "intensity": 10, "color": [1, 0.5, 0.25], "name": "bulb"},
        {"type": "spot", "position": [0, 5, 0], "direction": [0, -2, 0], "intensity": [4, 5, 6],
         "inner_cone": 20, "outer_cone": 30},
        {"type": "spot", "position": [0, 5, 0], "direction": [1, 0, 0], "intensity": 1},
        {"type": "directional", "direction": [0, 0, -3], "irradiance": 2.5}])");
    WarningCapture capture;
    Scene scene = f.load();
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    ASSERT_EQ(scene.punctualLights.size(), 4u);
    const PunctualLight &point = scene.punctualLights[0], &spot = scene.punctualLights[1],
                        &spotDefaults = scene.punctualLights[2], &sun = scene.punctualLights[3];
    EXPECT_EQ(point.type, PunctualLightType::Point);
    EXPECT_EQ(point.name, "bulb");
    EXPECT_EQ(point.position, glm::vec3(1, 2, 3));
    EXPECT_EQ(point.intensity, glm::vec3(10.0f, 5.0f, 2.5f)) << "colour x intensity";
    EXPECT_EQ(spot.type, PunctualLightType::Spot);
    EXPECT_EQ(spot.direction, glm::vec3(0, -1, 0)) << "normalised";
    EXPECT_EQ(spot.intensity, glm::vec3(4, 5, 6));
    EXPECT_FLOAT_EQ(spot.innerConeAngle, float(20.0 * kPi / 180.0))
        << "degrees in the file, radians in the scene";
    EXPECT_FLOAT_EQ(spot.outerConeAngle, float(30.0 * kPi / 180.0));
    EXPECT_FLOAT_EQ(spotDefaults.innerConeAngle, 0.0f) << "glTF's default";
    EXPECT_FLOAT_EQ(spotDefaults.outerConeAngle, float(kPi / 4.0)) << "glTF's default";
    EXPECT_EQ(sun.type, PunctualLightType::Directional);
    EXPECT_EQ(sun.direction, glm::vec3(0, 0, -1));
    EXPECT_EQ(sun.intensity, glm::vec3(2.5f));
    // A scene file without lights has none, and an empty list is allowed.
    EXPECT_TRUE(LightsFile("[]").load().punctualLights.empty());
}

// Caught: the scene file's inner < outer check dropped (validatePunctualLight still refuses, but with
// another message, not naming the key).
TEST(PunctualLightFile, ErrorsNameTheLightAndTheKey) {
    LightsFile("{}").reject("lights must be an array");
    LightsFile("[3]").reject("lights[0] must be a JSON object");
    LightsFile(R"([{"position": [0, 0, 0]}])").reject("lights[0] needs a \"type\"");
    LightsFile(R"([{"type": "area", "intensity": 1}])")
        .reject("lights[0].type", "unknown light type 'area'", "point, spot or directional");
    LightsFile(R"([{"type": 1}])").reject("lights[0].type must be a string");
    // Missing what the type needs.
    LightsFile(R"([{"type": "point", "intensity": 1}])").reject("lights[0] (point) needs a \"position\"");
    LightsFile(R"([{"type": "point", "position": [0, 0, 0]}])").reject("needs \"intensity\" (W/sr)");
    LightsFile(R"([{"type": "spot", "position": [0, 0, 0], "intensity": 1}])")
        .reject("needs a \"direction\"");
    LightsFile(R"([{"type": "directional", "direction": [0, -1, 0]}])").reject("needs \"irradiance\" (W/m^2");
    // Keys of another type of light.
    LightsFile(
        R"([{"type": "directional", "direction": [0, -1, 0], "irradiance": 1, "position": [0, 0, 0]}])")
        .reject("lights[0] (directional)", "has no \"position\"");
    LightsFile(R"([{"type": "point", "position": [0, 0, 0], "intensity": 1, "direction": [0, 1, 0]}])")
        .reject("takes no \"direction\"");
    LightsFile(R"([{"type": "point", "position": [0, 0, 0], "intensity": 1, "outer_cone": 20}])")
        .reject("only spot lights have");
    LightsFile(R"([{"type": "directional", "direction": [0, -1, 0], "intensity": 1}])")
        .reject("strength is \"irradiance\"");
    LightsFile(R"([{"type": "spot", "position": [0, 0, 0], "direction": [0, -1, 0], "irradiance": 1}])")
        .reject("spot light's strength is \"intensity\"");
    // Values.
    LightsFile(R"([{"type": "point", "position": [0, 0], "intensity": 1}])")
        .reject("lights[0].position must be an array of 3 numbers");
    LightsFile(R"([{"type": "point", "position": [0, 0, 0], "intensity": -1}])")
        .reject("lights[0].intensity must not be negative");
    LightsFile(R"([{"type": "point", "position": [0, 0, 0], "intensity": [1, -1, 1]}])")
        .reject("lights[0].intensity must not be negative");
    LightsFile(R"([{"type": "point", "position": [0, 0, 0], "intensity": "bright"}])")
        .reject("lights[0].intensity must be an array of 3 numbers");
    LightsFile(R"([{"type": "point", "position": [0, 0, 0], "intensity": 1, "color": [1, -0.5, 1]}])")
        .reject("lights[0].color must not be negative");
    LightsFile(R"([{"type": "point", "position": [0, 0, 1e39], "intensity": 1}])")
        .reject("lights[0].position[2] must be a finite number");
    LightsFile(R"([{"type": "directional", "direction": [0, 0, 0], "irradiance": 1}])")
        .reject("lights[0].direction must not be the zero vector");
    const std::string spot =
        R"({"type": "spot", "position": [0, 0, 0], "direction": [0, -1, 0], "intensity": 1, )";
    LightsFile("[" + spot + R"("inner_cone": 30, "outer_cone": 20}])")
        .reject("lights[0].inner_cone must be", "less than outer_cone");
    LightsFile("[" + spot + R"("inner_cone": 20, "outer_cone": 20}])").reject("lights[0].inner_cone");
    LightsFile("[" + spot + R"("inner_cone": -1, "outer_cone": 20}])")
        .reject("lights[0].inner_cone must be at least 0");
    LightsFile("[" + spot + R"("outer_cone": 91}])").reject("lights[0].outer_cone must be in (0, 90]");
    LightsFile("[" + spot + R"("outer_cone": 0}])").reject("lights[0].outer_cone must be in (0, 90]");
    LightsFile("[" + spot + R"("inner_cone": 50}])").reject("less than outer_cone (45");
    // The second light is the one named.
    LightsFile(R"([{"type": "point", "position": [0, 0, 0], "intensity": 1}, {"type": "spot"}])")
        .reject("lights[1] (spot) needs");
}

TEST(PunctualLightFile, UnknownKeysWarned) {
    WarningCapture capture;
    LightsFile(R"([{"type": "point", "position": [0, 0, 0], "intensity": 1, "range": 10}])").load();
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], "unknown key", "'lights[0].range'");
}

// What the glTF loader maps onto: validatePunctualLight refuses what glTF's schema refuses.
TEST(PunctualLight, ValidationFollowsGltf) {
    PunctualLight spot;
    spot.type = PunctualLightType::Spot;
    spot.direction = glm::vec3(0, 0, -1);
    EXPECT_NO_THROW(validatePunctualLight(spot, "light"));  // glTF's defaults: 0 and pi / 4
    spot.outerConeAngle = float(kPi / 2.0);
    EXPECT_NO_THROW(validatePunctualLight(spot, "light")) << "outer <= pi / 2";
    spot.outerConeAngle = 1.6f;
    EXPECT_THROW(validatePunctualLight(spot, "light"), Error);
    spot.outerConeAngle = 0.5f;
    spot.innerConeAngle = 0.5f;
    EXPECT_THROW(validatePunctualLight(spot, "light"), Error) << "inner < outer";
    spot.innerConeAngle = 0.2f;
    spot.direction = glm::vec3(0, 0, -2);
    EXPECT_THROW(validatePunctualLight(spot, "light"), Error) << "a unit direction";
    PunctualLight point;
    point.direction = glm::vec3(0.0f);  // ignored for a point light
    EXPECT_NO_THROW(validatePunctualLight(point, "light"));
    point.position.x = std::nanf("");
    std::string message = errorOf([&] { validatePunctualLight(point, "node 'lamp'"); });
    EXPECT_CONTAINS_ALL(message, "node 'lamp' (point)", "position must be finite");
    point.position.x = 0.0f;
    point.intensity.y = -1.0f;
    EXPECT_THROW(validatePunctualLight(point, "light"), Error);
}

// glTF's reference falloff: t = (cos - cos outer) / (cos inner - cos outer), clamped, squared.
TEST(PunctualLight, SpotFalloffIsGltfs) {
    float ci = std::cos(0.3f), co = std::cos(0.5f);
    EXPECT_EQ(spotFalloff(1.0f, ci, co), 1.0f);
    EXPECT_EQ(spotFalloff(ci, ci, co), 1.0f);
    EXPECT_EQ(spotFalloff(co, ci, co), 0.0f);
    EXPECT_EQ(spotFalloff(std::cos(0.6f), ci, co), 0.0f);
    EXPECT_NEAR(spotFalloff(0.5f * (ci + co), ci, co), 0.25f, 1e-6f);
    EXPECT_NEAR(spotFalloff(co + 0.1f * (ci - co), ci, co), 0.01f, 1e-5f);
}

// The spot's solid angle (its power over I) against the falloff integrated numerically over the sphere.
TEST(PunctualLight, SpotSolidAngleIntegratesTheFalloff) {
    for (auto [inner, outer] :
         {std::pair{0.0f, 0.785398f}, {0.3f, 0.5f}, {1.0f, 1.5707963f}, {0.1f, 0.11f}}) {
        const int n = 200000;
        double integral = 0.0, ci = std::cos(double(inner)), co = std::cos(double(outer));
        for (int i = 0; i < n; ++i) {  // midpoint rule over cos theta in [-1, 1]: d omega = 2 pi d cos
            double c = -1.0 + (i + 0.5) * 2.0 / n;
            integral += 2.0 * kPi * double(spotFalloff(float(c), float(ci), float(co))) * 2.0 / n;
        }
        EXPECT_NEAR(spotSolidAngle(inner, outer), integral, 2e-4 * integral) << inner << " " << outer;
    }
    EXPECT_NEAR(spotSolidAngle(0.0f, 1.5707963f), 2.0 * kPi / 3.0, 1e-6);
}

// Caught: a directional light's power pi r E instead of pi r^2 E.
TEST(PunctualLight, PowersAsPbrt) {
    PunctualLight point;
    point.intensity = glm::vec3(2.0f);
    EXPECT_NEAR(punctualLightPower(point, 0.0f), 4.0 * kPi * 2.0, 1e-5);
    PunctualLight spot = point;
    spot.type = PunctualLightType::Spot;
    spot.direction = glm::vec3(0, 0, -1);
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = 0.4f;
    EXPECT_NEAR(punctualLightPower(spot, 0.0f), 2.0 * spotSolidAngle(0.2f, 0.4f), 1e-5);
    PunctualLight sun = point;
    sun.type = PunctualLightType::Directional;
    sun.direction = glm::vec3(0, -1, 0);
    sun.intensity = glm::vec3(3.0f, 0.0f, 0.0f);  // the luminance of the colour counts
    EXPECT_NEAR(punctualLightPower(sun, 5.0f), kPi * 25.0 * 3.0 * 0.2126, 1e-4);
}

// Two triangles (area 0.5 each, one emitting radiance 1) and three punctual lights: each is picked in
// proportion to its power / pi (the unit of luminance(Ke) * area), and adding punctual lights leaves the
// triangles' shares in proportion.
TEST(PunctualLight, SelectedByPowerWithTheEmitters) {
    Scene scene;
    Material plain, lamp;
    lamp.emission = glm::vec3(1.0f);
    scene.materials = {plain, lamp};
    for (uint32_t m : {0u, 1u}) {
        Triangle t;
        t.p = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, 1)};
        t.material = m;
        scene.triangles.push_back(t);
    }
    uint32_t order[] = {0, 1};
    EmitterPmfs alone = emitterPmfs(scene, order, 2);
    EXPECT_EQ(alone.pmf[0], 0.0f);
    EXPECT_EQ(alone.pmf[1], 1.0f);
    EXPECT_TRUE(alone.punctualPmf.empty());

    PunctualLight point, sun;
    point.intensity = glm::vec3(0.125f);  // 4 pi I / pi = 0.5: the emitter's power
    sun.type = PunctualLightType::Directional;
    sun.direction = glm::vec3(0, -1, 0);
    sun.intensity = glm::vec3(1.0f);
    scene.punctualLights = {point, sun};
    EmitterPmfs both = emitterPmfs(scene, order, 2);
    float r = directionalLightSphere(scene).radius;
    EXPECT_NEAR(r, 0.5 * std::sqrt(2.0) * 1.001, 1e-6) << "half the diagonal of the triangles' box, enlarged";
    double total = 0.5 + 0.5 + double(r) * r;  // emitter, point, sun (pi r^2 E / pi)
    EXPECT_NEAR(both.totalPower, total, 1e-6);
    ASSERT_EQ(both.punctualPmf.size(), 2u);
    EXPECT_NEAR(both.pmf[1], 0.5 / total, 1e-7);
    EXPECT_NEAR(both.punctualPmf[0], 0.5 / total, 1e-7);
    EXPECT_NEAR(both.punctualPmf[1], r * r / total, 1e-7);
    EXPECT_EQ(double(both.pmf[1]) + both.punctualPmf[0] + both.punctualPmf[1], 1.0) << "exactly, on the grid";
}

TEST(PunctualLight, DescribedOnOneLine) {
    PunctualLight spot;
    spot.type = PunctualLightType::Spot;
    spot.name = "key";
    spot.position = glm::vec3(1, 2, 3);
    spot.direction = glm::vec3(0, -1, 0);
    spot.intensity = glm::vec3(100, 90, 80);
    spot.innerConeAngle = float(20.0 * kPi / 180.0);
    spot.outerConeAngle = float(30.0 * kPi / 180.0);
    EXPECT_EQ(describePunctualLight(spot),
              "spot 'key': (1, 2, 3) -> (0, -1, 0), 20-30 deg, I = 100, 90, 80 W/sr");
    PunctualLight sun;
    sun.type = PunctualLightType::Directional;
    sun.intensity = glm::vec3(2.0f);
    EXPECT_EQ(describePunctualLight(sun), "directional: -> (0, 0, -1), E = 2, 2, 2 W/m^2");
    EXPECT_EQ(describePunctualLight(PunctualLight{}), "point: (0, 0, 0), I = 1, 1, 1 W/sr");
}

}  // namespace
}  // namespace fp
