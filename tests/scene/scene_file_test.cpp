// Scene files (JSON): mesh, camera, render settings, and everything they may get wrong.
#include <gtest/gtest.h>

#include "scene/load.h"
#include "scene_test_util.h"

namespace fp {
namespace {

using test::errorOf;

const std::string kObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
const std::string kCamera = R"("camera": {"eye": [0, 0, -5], "target": [0, 0, 0]})";

// A directory holding mesh.obj and scene.json with `json` as its text.
struct SceneDir {
    test::TempDir dir;
    std::string json;
    explicit SceneDir(const std::string& text) {
        dir.write("mesh.obj", kObj);
        json = dir.write("scene.json", text);
    }
    Scene load() const { return loadScene(json); }
    // The error loading it gives; expects it to name the scene file and contain `fragment`.
    std::string reject(const std::string& fragment) const {
        std::string message = errorOf([this] { load(); });
        EXPECT_CONTAINS_ALL(message, json, fragment);
        return message;
    }
};

// A scene file around `body` (extra members after "mesh").
std::string sceneWith(const std::string& body) {
    return R"({"mesh": "mesh.obj")" + (body.empty() ? "" : ", " + body) + "}";
}

TEST(SceneFile, CameraAndRenderParsed) {
    SceneDir s(sceneWith(R"("camera": {"eye": [1, 2, 3], "target": [4, 5, 6], "up": [0, 0, 1], "fov": 55.5},
        "render": {"width": 640, "height": 480, "spp": 16, "max_depth": 0, "seed": 2147483647,
                   "integrator": "bsdf", "sampler": "independent", "light_sampling": "area",
                   "light_selection": "tree", "caustics": "path", "clamp_indirect": 4.5})"));
    WarningCapture capture;
    Scene scene = s.load();
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
    EXPECT_EQ(scene.triangles.size(), 1u);
    EXPECT_EQ(scene.source, s.json);
    ASSERT_TRUE(scene.camera.has_value());
    EXPECT_EQ(scene.camera->eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(scene.camera->target, glm::vec3(4, 5, 6));
    EXPECT_EQ(scene.camera->up, glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(scene.camera->fovY, 55.5f);
    EXPECT_EQ(scene.fileSettings.get("width"), 640);
    EXPECT_EQ(scene.fileSettings.get("height"), 480);
    EXPECT_EQ(scene.fileSettings.get("spp"), 16);
    EXPECT_EQ(scene.fileSettings.get("max_depth"), 0);
    EXPECT_EQ(scene.fileSettings.get("seed"), 2147483647u);
    EXPECT_EQ(scene.fileSettings.get("integrator"), int(Integrator::Bsdf));
    EXPECT_EQ(scene.fileSettings.get("sampler"), int(Sampler::Independent));
    EXPECT_EQ(scene.fileSettings.get("light_sampling"), int(LightSampling::Area));
    EXPECT_EQ(scene.fileSettings.get("light_selection"), int(LightSelection::Tree));
    EXPECT_EQ(scene.fileSettings.get("caustics"), int(Caustics::Path));
    EXPECT_EQ(scene.fileSettings.get("clamp_indirect"), 4.5f);
}

TEST(SceneFile, CameraDefaults) {
    Scene scene = SceneDir(sceneWith(kCamera)).load();
    ASSERT_TRUE(scene.camera.has_value());
    EXPECT_EQ(scene.camera->up, glm::vec3(0, 1, 0));
    EXPECT_EQ(scene.camera->fovY, 40.0f);
    // A pinhole, and the plane of focus through the target were there a lens.
    EXPECT_EQ(scene.camera->aperture, 0.0f);
    EXPECT_FALSE(scene.camera->focusDistance.has_value());
    EXPECT_EQ(resolvedFocusDistance(*scene.camera), 5.0f);
}

TEST(SceneFile, ThinLensParsed) {
    Scene scene = SceneDir(sceneWith(R"("camera": {"eye": [0, 0, -5], "target": [0, 0, 0], "aperture": 0.25,
        "focus_distance": 3.5})"))
                      .load();
    ASSERT_TRUE(scene.camera.has_value());
    EXPECT_EQ(scene.camera->aperture, 0.25f);
    EXPECT_EQ(scene.camera->focusDistance, 3.5f);
    EXPECT_EQ(resolvedFocusDistance(*scene.camera), 3.5f);
    // The aperture alone: the focus follows the target.
    Scene apertureOnly =
        SceneDir(sceneWith(R"("camera": {"eye": [0, 3, -4], "target": [0, 0, 0], "aperture": 1})")).load();
    EXPECT_EQ(apertureOnly.camera->aperture, 1.0f);
    EXPECT_FALSE(apertureOnly.camera->focusDistance.has_value());
    EXPECT_EQ(resolvedFocusDistance(*apertureOnly.camera), 5.0f);
}

TEST(SceneFile, BadThinLens) {
    std::string camera = R"("camera": {"eye": [0, 0, -5], "target": [0, 0, 0], )";
    SceneDir(sceneWith(camera + R"("aperture": -0.5})"))
        .reject("camera.aperture must be a finite number, 0 (a pinhole) or more");
    SceneDir(sceneWith(camera + R"("aperture": "wide"})")).reject("camera.aperture must be a number");
    SceneDir(sceneWith(camera + R"("aperture": 1e39})")).reject("camera.aperture must be a finite number");
    SceneDir(sceneWith(camera + R"("focus_distance": 0})"))
        .reject("camera.focus_distance must be a finite number above 0");
    SceneDir(sceneWith(camera + R"("focus_distance": -2})")).reject("camera.focus_distance must be");
    SceneDir(sceneWith(camera + R"("focus_distance": [1]})"))
        .reject("camera.focus_distance must be a number");
}

TEST(SceneFile, CameraAndRenderOptional) {
    Scene scene = SceneDir(sceneWith("")).load();
    EXPECT_FALSE(scene.camera.has_value());
    EXPECT_FALSE(scene.fileSettings.get("width") || scene.fileSettings.get("height") ||
                 scene.fileSettings.get("spp") || scene.fileSettings.get("max_depth") ||
                 scene.fileSettings.get("seed") || scene.fileSettings.get("integrator"));
    Scene partial = SceneDir(sceneWith(R"("render": {"spp": 4, "integrator": "naive"})")).load();
    EXPECT_EQ(partial.fileSettings.get("spp"), 4);
    EXPECT_EQ(partial.fileSettings.get("integrator"), int(Integrator::Naive));
    EXPECT_FALSE(partial.fileSettings.get("width").has_value());
}

TEST(SceneFile, MeshRelativeToTheSceneFile) {
    test::TempDir dir;
    dir.write("meshes/thing.obj", kObj);
    std::string json = dir.write("scenes/a/scene.json",
                                 R"({"mesh": "../../meshes/thing.obj", "render": {"integrator": "nee"}})");
    EXPECT_EQ(loadScene(json).triangles.size(), 1u);
    // An absolute mesh path is used as it is.
    std::string absolute = dir.write("abs.json", "{\"mesh\": \"" + dir.path("meshes/thing.obj") + "\"}");
    EXPECT_EQ(loadScene(absolute).triangles.size(), 1u);
}

TEST(SceneFile, ExtensionsAreCaseInsensitiveAndCommentsAllowed) {
    test::TempDir dir;
    dir.write("MESH.OBJ", kObj);
    std::string json = dir.write("SCENE.JSON", "// a scene\n{\"mesh\": \"MESH.OBJ\" /* the mesh */}\n");
    EXPECT_EQ(loadScene(json).triangles.size(), 1u);
    EXPECT_EQ(loadScene(dir.path("MESH.OBJ")).triangles.size(), 1u);
}

TEST(SceneFile, UnknownKeysWarned) {
    SceneDir s(
        sceneWith(R"("camera": {"eye": [0, 0, -5], "target": [0, 0, 0], "fov_y": 30}, "animations": [])"));
    WarningCapture capture;
    s.load();
    ASSERT_EQ(capture.messages().size(), 1u) << test::joined(capture);
    EXPECT_CONTAINS_ALL(capture.messages()[0], s.json, "unknown keys", "'animations'", "'camera.fov_y'");
}

TEST(SceneFile, InvalidJson) {
    std::string message = SceneDir("{\n  \"mesh\": \"mesh.obj\",\n}\n").reject("invalid JSON");
    EXPECT_CONTAINS_ALL(message, "line 3, column 1", "byte");
    SceneDir("{\"mesh\": \"mesh.obj\"").reject("invalid JSON");
    SceneDir("not json at all").reject("line 1");
    SceneDir(sceneWith(R"("camera": {"eye": [NaN, 0, 0], "target": [0, 0, 0]})")).reject("invalid JSON");
    SceneDir(sceneWith(R"("render": {"width": 1e999})")).reject("number overflow");
}

TEST(SceneFile, NotTextOrEmpty) {
    SceneDir("").reject("empty");
    SceneDir(std::string("{\"mesh\"\0: 1}", 12)).reject("binary");
    SceneDir(std::string("\xFF\xFE{\0}\0", 6)).reject("UTF-16");
}

TEST(SceneFile, MeshMissingOrWrong) {
    SceneDir("{}").reject("missing \"mesh\"");
    SceneDir(R"({"camera": {"eye": [0, 0, -5], "target": [0, 0, 0]}})").reject("missing \"mesh\"");
    SceneDir(R"({"mesh": 3})").reject("mesh must be a string");
    SceneDir(R"({"mesh": ""})").reject("mesh must not be empty");
    SceneDir(R"({"mesh": "mesh.png"})").reject("must be an .obj, .gltf or .glb file");
    std::string message = SceneDir(R"({"mesh": "other.obj"})").reject("mesh 'other.obj' not found");
    EXPECT_CONTAINS_ALL(message, "other.obj)");
    SceneDir("[1, 2]").reject("the top level must be a JSON object");
}

TEST(SceneFile, MeshErrorsNameTheMesh) {
    test::TempDir dir;
    std::string obj = dir.write("broken.obj", "v 0 0 zero\n");
    std::string json = dir.write("scene.json", R"({"mesh": "broken.obj"})");
    EXPECT_CONTAINS_ALL(errorOf([&] { loadScene(json); }), "broken.obj:1:", "'zero'");
    std::filesystem::create_directories(dir.path("folder.obj"));
    std::string toFolder = dir.write("folder.json", R"({"mesh": "folder.obj"})");
    EXPECT_CONTAINS_ALL(errorOf([&] { loadScene(toFolder); }), "folder.obj", "is a directory");
}

TEST(SceneFile, HalfSpecifiedCamera) {
    SceneDir(sceneWith(R"("camera": {"eye": [0, 0, -5]})"))
        .reject("camera needs both eye and target (target is missing)");
    SceneDir(sceneWith(R"("camera": {"target": [0, 0, 0], "fov": 30})")).reject("(eye is missing)");
    SceneDir(sceneWith(R"("camera": {})")).reject("camera needs both eye and target");
    SceneDir(sceneWith(R"("camera": [0, 0, 0])")).reject("camera must be a JSON object");
}

TEST(SceneFile, DegenerateCamera) {
    SceneDir(sceneWith(R"("camera": {"eye": [1, 2, 3], "target": [1, 2, 3]})")).reject("same point");
    SceneDir(sceneWith(R"("camera": {"eye": [0, 0, -5], "target": [0, 0, 0], "up": [0, 0, 2]})"))
        .reject("parallel to the view direction");
    SceneDir(sceneWith(R"("camera": {"eye": [0, 5, 0], "target": [0, 0, 0]})"))
        .reject("parallel");  // default up
    SceneDir(sceneWith(R"("camera": {"eye": [0, 0, -5], "target": [0, 0, 0], "up": [0, 0, 0]})"))
        .reject("zero vector");
}

TEST(SceneFile, FovOutOfRange) {
    for (const char* fov : {"0", "180", "-10", "360"})
        SceneDir(sceneWith(R"("camera": {"eye": [0, 0, -5], "target": [0, 0, 0], "fov": )" +
                           std::string(fov) + "}"))
            .reject("camera.fov must be in (0, 180)");
}

TEST(SceneFile, WrongTypes) {
    std::string eye = R"("camera": {"target": [0, 0, 0], "eye": )";
    SceneDir(sceneWith(eye + "[1, 2]}")).reject("camera.eye must be an array of 3 numbers");
    SceneDir(sceneWith(eye + "\"here\"}")).reject("camera.eye must be an array of 3 numbers");
    SceneDir(sceneWith(eye + "[1, \"2\", 3]}")).reject("camera.eye[1] must be a number");
    SceneDir(sceneWith(eye + "[1, true, 3]}")).reject("camera.eye[1] must be a number");
    SceneDir(sceneWith(R"("camera": {"eye": [0, 0, -5], "target": [0, 0, 0], "fov": "wide"})"))
        .reject("camera.fov must be a number");
    SceneDir(sceneWith(R"("render": {"width": "512"})"))
        .reject("render.width must be a whole number from 1 to 65536, got \"512\"");
    SceneDir(sceneWith(R"("render": {"spp": 1.5})"))
        .reject("render.spp must be a whole number from 1 to 16777216, or unlimited, got 1.5");
    SceneDir(sceneWith(R"("render": {"integrator": 3})"))
        .reject("render.integrator must be one of naive, bsdf, nee or bdpt, got 3");
    SceneDir(sceneWith(R"("render": 5)")).reject("render must be a JSON object");
    // An integral number written with a fraction is still an integer.
    EXPECT_EQ(SceneDir(sceneWith(R"("render": {"width": 512.0})")).load().fileSettings.get("width"), 512);
}

TEST(SceneFile, NonFiniteNumbers) {
    // JSON has no NaN or infinity literals; numbers too large for a float are the way in.
    SceneDir(sceneWith(R"("camera": {"eye": [0, 0, 1e39], "target": [0, 0, 0]})"))
        .reject("camera.eye[2] must be a finite number");
    SceneDir(sceneWith(R"("camera": {"eye": [0, 0, -5], "target": [0, 0, 0], "fov": -1e300})"))
        .reject("camera.fov must be a finite");
}

TEST(SceneFile, BadRenderSettings) {
    SceneDir(sceneWith(R"("render": {"width": 0})"))
        .reject("render.width must be a whole number from 1 to 65536, got 0");
    SceneDir(sceneWith(R"("render": {"height": -4})"))
        .reject("render.height must be a whole number from 1 to");
    SceneDir(sceneWith(R"("render": {"spp": 0})")).reject("render.spp must be a whole number from 1 to");
    SceneDir(sceneWith(R"("render": {"max_depth": -1})"))
        .reject("render.max_depth must be a whole number from 0 to 1000, got -1");
    SceneDir(sceneWith(R"("render": {"width": 3000000000})")).reject("render.width must be a whole number");
    SceneDir(sceneWith(R"("render": {"seed": -1})"))
        .reject("render.seed must be a whole number from 0 to 2147483647, got -1");
    SceneDir(sceneWith(R"("render": {"seed": 4294967296})"))
        .reject("render.seed must be a whole number from 0 to 2147483647, got 4294967296");
    SceneDir(sceneWith(R"("render": {"integrator": "path"})"))
        .reject("render.integrator: unknown integrator 'path' (choose naive, bsdf, nee or bdpt)");
    SceneDir(sceneWith(R"("render": {"sampler": "halton"})"))
        .reject("render.sampler: unknown sampler 'halton' (choose sobol or independent)");
    SceneDir(sceneWith(R"("render": {"light_sampling": "cone"})"))
        .reject("render.light_sampling: unknown light sampling 'cone'");
    SceneDir(sceneWith(R"("render": {"clamp_indirect": -1})"))
        .reject("render.clamp_indirect must be a number, 0 or more, got -1");
    SceneDir(sceneWith(R"("render": {"clamp_indirect": "big"})"))
        .reject("render.clamp_indirect must be a number");
}

TEST(SceneFile, ErrorsBeforeMeshWarnings) {
    // The scene file is checked completely before its mesh is loaded.
    test::TempDir dir;
    dir.write("mesh.obj", "mtllib missing.mtl\n" + kObj);
    std::string json = dir.write("scene.json", sceneWith(R"("render": {"spp": 0})"));
    WarningCapture capture;
    EXPECT_CONTAINS_ALL(errorOf([&] { loadScene(json); }), "render.spp");
    EXPECT_TRUE(capture.messages().empty()) << test::joined(capture);
}

}  // namespace
}  // namespace fp
