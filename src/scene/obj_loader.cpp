#include <filesystem>

#include "core/error.h"
#include "scene/load.h"
#include "scene/obj_parse.h"
#include "scene/text_file.h"

namespace fp {

namespace fs = std::filesystem;

Scene loadObj(const std::string& path) {
    std::string bytes = readFileBytes(path);
    fs::path directory = fs::path(path).parent_path();
    // MTL libraries and their textures, relative to the OBJ's directory (or absolute).
    MtlLookup lookup = [&directory](const std::string& file) -> std::optional<LibraryFile> {
        fs::path library = fs::path(file).is_absolute() ? fs::path(file) : directory / file;
        std::error_code ec;
        if (!fs::is_regular_file(library, ec)) return std::nullopt;
        try {
            return LibraryFile{library.string(), readFileBytes(library.string())};
        } catch (const Error&) {
            return std::nullopt;  // unreadable: treated like missing
        }
    };
    return parseObj(bytes, path, lookup);
}

}  // namespace fp
