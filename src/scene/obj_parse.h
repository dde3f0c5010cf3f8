#pragma once
// The OBJ loader's core, shared by files on disk and the built-in Cornell box: text in, Scene out, with
// the MTL libraries found through a lookup so that neither needs to know where the text came from.
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace fp {

struct LibraryFile {
    std::string name;   // for messages
    std::string bytes;  // unchecked
};

// Finds a file the OBJ refers to, by its path relative to the OBJ (or absolute): an MTL library a
// `mtllib` statement names, or a texture a library's map_Kd names (the parser makes its path relative
// to the OBJ). nullopt if there is none.
using MtlLookup = std::function<std::optional<LibraryFile>(const std::string& fileName)>;

// Parses OBJ `bytes`, naming the file `name` in errors and warnings. Throws fp::Error on input it must
// reject; warns (once per kind) about what it repairs. Scene::source is set to `name`.
Scene parseObj(std::string_view bytes, const std::string& name, const MtlLookup& lookup);

}  // namespace fp
