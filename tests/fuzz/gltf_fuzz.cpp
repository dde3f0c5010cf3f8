// libFuzzer harness for the glTF loader (tinygltf included). The input is the glTF file (.glb when it
// begins with "glTF", else JSON), optionally followed by a "\n#FILE\n" line and the bytes every external
// file it names (buffer or image) gets. Anything the loader rejects must be an fp::Error; a crash, a
// hang, a sanitizer report, a huge allocation or another exception is a bug. The compressed paths
// (KHR_draco_mesh_compression, EXT_meshopt_compression, KHR_mesh_quantization) are reached from the seeds
// in tests/fuzz/corpus/gltf: .glb files, and .gltf files whose stream follows "#FILE" as their external
// buffer, where most mutations land in the compressed bytes; tests/fuzz/gltf.dict holds their words.
#include <cmath>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "core/log.h"
#include "scene/gltf.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string input(reinterpret_cast<const char*>(data), size);
    std::string gltf = input, file;
    size_t split = input.find("\n#FILE\n");
    if (split != std::string::npos) {
        gltf = input.substr(0, split);
        file = input.substr(split + 7);
    }
    fp::WarningCapture quiet;
    try {
        fp::Scene scene = fp::parseGltf(gltf, "fuzz.gltf", [&](const std::string& name) {
            return std::optional<fp::LibraryFile>(fp::LibraryFile{name, file});
        });
        // What the loader promises downstream: triangles with valid materials and textures, finite
        // positions, unit normals, a usable camera.
        if (scene.triangles.empty() || scene.materials.empty()) __builtin_trap();
        for (const fp::Triangle& t : scene.triangles) {
            if (t.material >= scene.materials.size()) __builtin_trap();
            for (const glm::vec3& p : t.p)
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) __builtin_trap();
            for (const glm::vec3& n : t.n)
                if (!(std::abs(glm::length(n) - 1.0f) < 1e-3f)) __builtin_trap();
        }
        for (const fp::Material& m : scene.materials)
            if (m.diffuseTexture >= int32_t(scene.textures.size())) __builtin_trap();
        if (scene.camera) fp::validateCamera(*scene.camera, "camera");
    } catch (const fp::Error&) {
    }
    return 0;
}
