// libFuzzer harness for the JSON scene file. The mesh it names is always a fixed one-triangle scene and
// environment maps are refused, so only the scene-file parsing and validation are exercised.
#include <cstdint>
#include <string>

#include "core/error.h"
#include "core/log.h"
#include "scene/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string input(reinterpret_cast<const char*>(data), size);
    fp::WarningCapture quiet;
    try {
        fp::Scene scene = fp::parseSceneFile(input, "fuzz.json", [](const std::string&) {
            fp::Scene mesh;
            mesh.materials.resize(1);
            fp::Triangle t;
            t.p = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
            t.n = {glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), glm::vec3(0, 0, 1)};
            mesh.triangles.push_back(t);
            return mesh;
        });
        // A camera that passed validation must be usable.
        if (scene.camera) fp::validateCamera(*scene.camera, "camera");
    } catch (const fp::Error&) {
    }
    return 0;
}
