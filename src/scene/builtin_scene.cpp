#include "scene/builtin_scene.h"

#include "core/error.h"
#include "scene/obj_parse.h"
#include "scene/scene_file.h"

namespace fp {

Scene builtinCornellBox() {
    // The same parsers as for files on disk, reading the embedded copies instead: the built-in box is
    // exactly what `assets/cornell/cornell.json` loads to.
    const std::map<std::string, std::string>& files = embeddedCornellBox();
    auto find = [&files](const std::string& file) -> std::optional<LibraryFile> {
        auto it = files.find(file);
        if (it == files.end()) return std::nullopt;
        return LibraryFile{"built-in " + file, it->second};
    };
    std::optional<LibraryFile> json = find("cornell.json");
    if (!json) throw Error("built-in Cornell box: cornell.json is not embedded");
    Scene scene = parseSceneFile(json->bytes, json->name, [&find](const std::string& mesh) {
        std::optional<LibraryFile> obj = find(mesh);
        if (!obj) throw Error("built-in Cornell box: mesh '" + mesh + "' is not embedded");
        return parseObj(obj->bytes, obj->name, find);
    });
    return scene;
}

}  // namespace fp
