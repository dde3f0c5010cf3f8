// The file as tinygltf 2.7 can read it (gltf_internal.h): what the compression extensions allow but
// tinygltf refuses or misreads is moved out of its way, for the decoders to put back.
#include <nlohmann/json.hpp>

#include "scene/gltf_internal.h"

namespace fp::gltf {

namespace {

using nlohmann::json;

// A .glb with `text` as its JSON chunk and the chunks after the original's JSON chunk as they were.
std::string withJsonChunk(std::string_view bytes, const Container& container, std::string text) {
    while (text.size() % 4) text += ' ';
    size_t rest = size_t(container.json.data() - bytes.data()) + container.json.size();
    uint32_t length = 0;  // the header's, checked by readContainer
    for (int k = 3; k >= 0; --k) length = (length << 8) | static_cast<unsigned char>(bytes[8 + size_t(k)]);
    std::string out = "glTF";
    auto u32 = [&out](uint64_t v) {
        for (int k = 0; k < 4; ++k) out += char((v >> (8 * k)) & 0xff);
    };
    u32(2);
    u32(12 + 8 + text.size() + (length - rest));
    u32(text.size());
    out += "JSON";
    out += text;
    out += bytes.substr(rest, length - rest);
    return out;
}

}  // namespace

TinygltfInput tinygltfInput(std::string_view bytes, const Container& container, json root) {
    TinygltfInput input;
    bool changed = false;
    // EXT_meshopt_compression's fallback buffers: one zero byte for tinygltf to load (it would look for a
    // file, or copy the BIN chunk); the views that refer to them are decoded instead.
    if (auto buffers = root.find("buffers"); buffers != root.end())
        for (size_t i = 0; i < buffers->size(); ++i)
            if (isPlaceholderBuffer(root, container, i)) {
                (*buffers)[i] = {{"byteLength", 1}, {"uri", "data:application/octet-stream;base64,AA=="}};
                changed = true;
            }
    // KHR_draco_mesh_compression's indices accessors have no buffer view, which tinygltf refuses.
    if (auto meshes = root.find("meshes"); meshes != root.end())
        for (size_t m = 0; m < meshes->size(); ++m) {
            json& primitives = (*meshes)[m]["primitives"];
            for (size_t p = 0; p < primitives.size(); ++p) {
                json& primitive = primitives[p];
                auto extensions = primitive.find("extensions");
                if (extensions == primitive.end() || !extensions->contains("KHR_draco_mesh_compression") ||
                    !primitive.contains("indices"))
                    continue;
                input.dracoIndices[{m, p}] = primitive["indices"].get<int>();
                primitive.erase("indices");
                changed = true;
            }
        }
    if (changed) input.bytes = container.binary ? withJsonChunk(bytes, container, root.dump()) : root.dump();
    return input;
}

}  // namespace fp::gltf
