#pragma once
// The scenes `fragpath study` studies when it is given none: one each for what changes the answer
// (textures, glossy and glass surfaces with caustics, light from an environment map, a million
// triangles, a glTF file), beside the Cornell box.
#include <functional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace fp::study {

struct StudyScene {
    std::string name;  // in file names (reference_<name>.exr) and the report's headings
    std::string what;  // what it adds to the study, a sentence for the report
    std::function<Scene()> load;
};

// The source tree's assets/ directory, where the set's scene files are read from.
std::string defaultAssetDir();

// The set, in the order it is studied: cornell (built in), cornell-checker (a checker-textured floor),
// cornell-spheres (a glass and a gold sphere: glossy and glass surfaces, caustics), environment (lit by
// an HDR sky alone, scene/procedural.h), sphere-1m (the benchmark's million-triangle sphere in a lit
// room) and gltf-showcase (a glTF 2.0 file with textures, transmission and punctual lights). Scene files
// are read from `assetDir` when loaded.
std::vector<StudyScene> studySceneSet(const std::string& assetDir);

// The entries of `set` a comma-separated list names, in the list's order; throws fp::Error for an
// unknown, empty or repeated name.
std::vector<StudyScene> selectScenes(const std::vector<StudyScene>& set, const std::string& list);

// The files of one scene in the output directory: reference_<name>.exr, strip_<name>.png.
std::string referenceFileName(const std::string& name);
std::string stripFileName(const std::string& name);

// The name a scene file is studied under: its file name without the extension.
std::string sceneNameOf(const std::string& path);

}  // namespace fp::study
