#pragma once
// glTF 2.0 scenes: .gltf (JSON with data-URI or external buffers) and .glb (binary), read through
// tinygltf (Debian's libtinygltf-dev) and flattened into a Scene: every triangle primitive of every node
// of the default scene, in world space, with its material mapped onto fragpath's models (docs/gltf.md)
// and the first perspective camera. Anything that cannot be rendered as the file means it (compressed
// meshes, required extensions we lack, sparse or quantized data, out-of-range indices, cycles in the
// node graph, non-finite values...) is an fp::Error naming the file and the part of it; what can be
// drawn approximately (texture maps the models cannot use yet, lines and points, lights) is a warning.
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "scene/obj_parse.h"  // LibraryFile
#include "scene/scene.h"

namespace fp {

// Finds a file a glTF refers to: a buffer or an image, by its URI as a path (percent-decoded) relative to
// the glTF file, or absolute. nullopt if there is none or it cannot be read.
using GltfLookup = std::function<std::optional<LibraryFile>(const std::string& file)>;

// Parses glTF `bytes` (binary when they begin with the GLB magic "glTF", else JSON text), naming the
// file `name` in errors and warnings; external files come through `lookup`. The Scene has at least one
// triangle and one material; its camera is the default scene's first perspective camera, if any.
Scene parseGltf(std::string_view bytes, const std::string& name, const GltfLookup& lookup);

}  // namespace fp
