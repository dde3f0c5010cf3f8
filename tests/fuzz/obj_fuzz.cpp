// libFuzzer harness for the OBJ + MTL loader. The input is split at the first NUL-free "\n#MTL\n" line:
// before it the OBJ text, after it the text of every MTL library the OBJ names. Anything the loader
// rejects must be an fp::Error; a crash, a hang, a sanitizer report or another exception is a bug.
#include <cstdint>
#include <string>

#include "core/error.h"
#include "core/log.h"
#include "scene/obj_parse.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string input(reinterpret_cast<const char*>(data), size);
    std::string obj = input, mtl;
    size_t split = input.find("\n#MTL\n");
    if (split != std::string::npos) {
        obj = input.substr(0, split);
        mtl = input.substr(split + 6);
    }
    fp::WarningCapture quiet;
    try {
        fp::Scene scene = fp::parseObj(obj, "fuzz.obj", [&](const std::string& file) {
            return std::optional<fp::LibraryFile>(fp::LibraryFile{file, mtl});
        });
        // What the loader promises downstream: triangles, materials, finite unit normals.
        if (scene.triangles.empty() || scene.materials.empty()) __builtin_trap();
        for (const fp::Triangle& t : scene.triangles) {
            if (t.material >= scene.materials.size()) __builtin_trap();
            for (const glm::vec3& n : t.n)
                if (!(std::abs(glm::length(n) - 1.0f) < 1e-3f)) __builtin_trap();
        }
    } catch (const fp::Error&) {
    }
    return 0;
}
