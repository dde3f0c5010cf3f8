#include "study/scene_set.h"

#include <filesystem>

#include "core/error.h"
#include "core/text.h"
#include "scene/builtin_scene.h"
#include "scene/load.h"
#include "scene/procedural.h"
#include "study/name_list.h"

namespace fp::study {

namespace {

// A scene file below assetDir; a clear message if the directory is not there (a binary moved away from
// its source tree).
std::function<Scene()> fromAssets(const std::string& assetDir, const std::string& file) {
    return [assetDir, file] {
        std::filesystem::path path = std::filesystem::path(assetDir) / file;
        std::error_code error;
        if (!std::filesystem::is_regular_file(path, error))
            throw Error("the study's scene set reads " + path.string() +
                        ", which is missing (assets/ of the source tree this binary was built from); "
                        "name one scene file instead: fragpath study SCENE");
        return loadScene(path.string());
    };
}

}  // namespace

std::string defaultAssetDir() {
    return FP_ASSET_DIR;
}

std::vector<StudyScene> studySceneSet(const std::string& assetDir) {
    return {
        {"cornell", "The built-in Cornell box: 32 triangles, Lambertian, one area light",
         [] { return builtinCornellBox(); }},
        {"cornell-checker", "The Cornell box with a checker-textured floor (assets/cornell_checker)",
         fromAssets(assetDir, "cornell_checker/cornell_checker.json")},
        {"cornell-spheres",
         "The Cornell room with a glass and a gold sphere (assets/cornell_spheres): glossy and glass "
         "surfaces, and the caustic the glass sphere focuses on the floor",
         fromAssets(assetDir, "cornell_spheres/cornell_spheres.json")},
        {"environment",
         "Three spheres on a ground lit by an HDR sky with a small bright sun alone (scene/procedural.h "
         "environmentLitScene)",
         [] { return environmentLitScene(); }},
        {"sphere-1m", "The benchmark's million-triangle sphere in a lit room (fragpath bench, sphere-1m)",
         [] { return benchmarkSphereScene(1000000); }},
        {"gltf-showcase",
         "A glTF 2.0 file (assets/gltf_showcase): textures, a normal map, transmission, punctual lights "
         "and an emissive surface",
         fromAssets(assetDir, "gltf_showcase/showcase.json")},
    };
}

std::vector<StudyScene> selectScenes(const std::vector<StudyScene>& set, const std::string& list) {
    std::vector<std::string> known;
    for (const StudyScene& s : set) known.push_back(s.name);
    std::vector<StudyScene> chosen;
    for (const std::string& name : splitNameList(list, "--scenes"))
        chosen.push_back(set[indexOfName(known, name, "scene")]);
    return chosen;
}

std::string referenceFileName(const std::string& name) {
    return "reference_" + name + ".exr";
}

std::string stripFileName(const std::string& name) {
    return "strip_" + name + ".png";
}

std::string sceneNameOf(const std::string& path) {
    return std::filesystem::path(path).stem().string();
}

}  // namespace fp::study
