// EXT_meshopt_compression: buffer views whose bytes are meshoptimizer's compressed streams, decoded by
// libmeshoptimizer (Debian's, 0.18) before any accessor reads them (gltf_internal.h).
#include <meshoptimizer.h>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "scene/gltf_internal.h"

namespace fp::gltf {

namespace {

using nlohmann::json;

constexpr const char* kExtension = "EXT_meshopt_compression";

// Every mode's stream holds at least one byte per 64 it decodes to: the attribute codec spends at least
// a 2-bit header per 16 bytes of a byte column (4 header bytes per 256 elements' column), the triangle
// codec at least a byte per triangle (12 bytes of 32-bit indices), the index sequence at least a byte per
// index (4 bytes). A view that claims more is refused before its bytes are allocated.
constexpr uint64_t kMaxExpansion = 64;

// A compressed byte count or offset: an integer in [lo, 2^53] (JSON numbers are exact up to there).
uint64_t integer(const json& extension, const char* key, uint64_t lo, const std::string& path, bool required,
                 uint64_t fallback, const std::string& name) {
    auto it = extension.find(key);
    if (it == extension.end()) {
        if (required) throw Error(name + ": " + path + ": missing \"" + key + "\"");
        return fallback;
    }
    constexpr uint64_t hi = uint64_t(1) << 53;
    if (!it->is_number_integer() || !it->is_number_unsigned() || it->get<uint64_t>() < lo ||
        it->get<uint64_t>() > hi)
        throw Error(name + ": " + path + "." + key + ": must be an integer in [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "], got " + shown(*it));
    return it->get<uint64_t>();
}

// A string property; required when there is no fallback.
std::string word(const json& extension, const char* key, const char* fallback, const std::string& path,
                 const std::string& name) {
    auto it = extension.find(key);
    if (it == extension.end()) {
        if (!fallback) throw Error(name + ": " + path + ": missing \"" + key + "\"");
        return fallback;
    }
    if (!it->is_string())
        throw Error(name + ": " + path + "." + key + ": must be a string, got " + shown(*it));
    return it->get<std::string>();
}

}  // namespace

bool isPlaceholderBuffer(const json& root, const Container& container, size_t buffer) {
    const json& b = root.at("buffers").at(buffer);
    return !b.contains("uri") && !(container.binary && container.hasBin && buffer == 0);
}

std::vector<MeshoptView> meshoptViews(const json& root, const Container& container, const std::string& name) {
    std::vector<MeshoptView> views;
    auto viewList = root.find("bufferViews");
    if (viewList == root.end()) return views;
    const json& buffers = root.at("buffers");  // the schema check found it, since views exist
    for (size_t i = 0; i < viewList->size(); ++i) {
        const json& v = (*viewList)[i];
        std::string path = "bufferViews[" + std::to_string(i) + "]";
        auto fail = [&](const std::string& where, const std::string& problem) {
            throw Error(name + ": " + where + ": " + problem);
        };
        const json* extension = nullptr;
        if (auto e = v.find("extensions"); e != v.end() && e->is_object())
            if (auto m = e->find(kExtension); m != e->end()) extension = &*m;
        size_t parentBuffer = v.at("buffer").get<size_t>();
        if (!extension) {
            if (isPlaceholderBuffer(root, container, parentBuffer))
                fail(path,
                     "refers to buffers[" + std::to_string(parentBuffer) +
                         "], which has no uri (only the first buffer of a .glb may omit it, or a fallback "
                         "for views compressed with EXT_meshopt_compression)");
            continue;
        }
        path += ".extensions." + std::string(kExtension);
        if (!extension->is_object()) fail(path, "must be a JSON object, got " + shown(*extension));
        MeshoptView m;
        m.view = i;
        uint64_t buffer = integer(*extension, "buffer", 0, path, true, 0, name);
        if (buffer >= buffers.size())
            fail(path + ".buffer", "buffers[" + std::to_string(buffer) + "] does not exist (the file has " +
                                       std::to_string(buffers.size()) + ")");
        if (isPlaceholderBuffer(root, container, size_t(buffer)))
            fail(path + ".buffer", "buffers[" + std::to_string(buffer) +
                                       "] has no uri, so holds no compressed data (a fallback buffer)");
        m.buffer = size_t(buffer);
        m.byteOffset = integer(*extension, "byteOffset", 0, path, false, 0, name);
        m.byteLength = integer(*extension, "byteLength", 1, path, true, 0, name);
        m.byteStride = integer(*extension, "byteStride", 1, path, true, 0, name);
        m.count = integer(*extension, "count", 1, path, true, 0, name);
        m.mode = word(*extension, "mode", nullptr, path, name).substr(0, 40);  // quoted in messages
        m.filter = word(*extension, "filter", "NONE", path, name).substr(0, 40);
        uint64_t bufferLength = buffers[buffer].at("byteLength").get<uint64_t>();
        if (m.byteOffset > bufferLength || m.byteLength > bufferLength - m.byteOffset)
            fail(path, "bytes " + std::to_string(m.byteOffset) + " and " + std::to_string(m.byteLength) +
                           " more lie beyond the end of buffers[" + std::to_string(buffer) + "] (" +
                           std::to_string(bufferLength) + " bytes)");
        // The specification's rules for the extension object, in its order.
        uint64_t stride = m.byteStride, length = v.at("byteLength").get<uint64_t>();
        if (v.contains("byteStride") && v["byteStride"].get<uint64_t>() != stride)
            fail(path + ".byteStride",
                 std::to_string(stride) + " differs from the view's byteStride " + v["byteStride"].dump());
        if (m.count > length / stride || m.count * stride != length)
            fail(path, std::to_string(m.count) + " elements of " + std::to_string(stride) +
                           " bytes (count, byteStride) do not make the view's byteLength " +
                           std::to_string(length));
        bool indices = m.mode == "TRIANGLES" || m.mode == "INDICES";
        if (m.mode == "ATTRIBUTES") {
            if (stride % 4 != 0 || stride > 256)
                fail(path + ".byteStride",
                     "must be a multiple of 4 up to 256 in mode ATTRIBUTES, got " + std::to_string(stride));
        } else if (indices) {
            if (stride != 2 && stride != 4)
                fail(path + ".byteStride",
                     "must be 2 or 4 in mode " + m.mode + ", got " + std::to_string(stride));
            if (m.mode == "TRIANGLES" && m.count % 3 != 0)
                fail(path + ".count",
                     "must be a multiple of 3 in mode TRIANGLES, got " + std::to_string(m.count));
            if (m.filter != "NONE")
                fail(path + ".filter", "must be NONE in mode " + m.mode + ", got " + m.filter);
        } else {
            fail(path + ".mode", "'" + m.mode + "' is not ATTRIBUTES, TRIANGLES or INDICES");
        }
        if (m.filter == "OCTAHEDRAL"    ? stride != 4 && stride != 8
            : m.filter == "QUATERNION"  ? stride != 8
            : m.filter == "EXPONENTIAL" ? stride % 4 != 0
                                        : m.filter != "NONE")
            fail(path + ".filter", "'" + m.filter + "' with byteStride " + std::to_string(stride) +
                                       " is not a filter the extension defines (NONE; OCTAHEDRAL with 4 "
                                       "or 8; QUATERNION with 8; EXPONENTIAL with a multiple of 4)");
        if (length / kMaxExpansion > m.byteLength)
            fail(path, "its " + std::to_string(m.byteLength) + " compressed bytes cannot decode to the " +
                           std::to_string(length) + " of the view (at most " + std::to_string(kMaxExpansion) +
                           " times as many)");
        views.push_back(m);
    }
    return views;
}

void decodeMeshoptViews(const std::vector<MeshoptView>& views, tinygltf::Model* model,
                        const std::string& name) {
    for (const MeshoptView& m : views) {
        const std::vector<unsigned char>& source = model->buffers.at(m.buffer).data;
        std::string path = "bufferViews[" + std::to_string(m.view) + "] (" + std::string(kExtension) +
                           ", mode " + m.mode + ")";
        if (m.byteOffset > source.size() || m.byteLength > source.size() - m.byteOffset)
            throw Error(name + ": " + path + ": its compressed bytes lie beyond the " +
                        std::to_string(source.size()) + " of buffers[" + std::to_string(m.buffer) + "]");
        const unsigned char* in = source.data() + m.byteOffset;
        size_t count = size_t(m.count), stride = size_t(m.byteStride), length = size_t(m.byteLength);
        tinygltf::Buffer decoded;
        decoded.data.resize(count * stride);
        int status = m.mode == "ATTRIBUTES"
                         ? meshopt_decodeVertexBuffer(decoded.data.data(), count, stride, in, length)
                     : m.mode == "TRIANGLES"
                         ? meshopt_decodeIndexBuffer(decoded.data.data(), count, stride, in, length)
                         : meshopt_decodeIndexSequence(decoded.data.data(), count, stride, in, length);
        // meshoptimizer's codes: -1 an unknown header or version, -2 the stream ends before the elements
        // do, -3 it does not end where they do.
        if (status != 0)
            throw Error(name + ": " + path + ": its " + std::to_string(length) + " bytes do not decode to " +
                        std::to_string(count) + " elements of " + std::to_string(stride) + " bytes (" +
                        (status == -1 ? "not a stream this meshoptimizer (0.18) reads"
                         : status == -2
                             ? "the stream ends before its elements do: truncated, or count too large"
                             : "the stream's length does not fit its elements: truncated, padded "
                               "or the wrong count") +
                        ")");
        if (m.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(decoded.data.data(), count, stride);
        if (m.filter == "QUATERNION") meshopt_decodeFilterQuat(decoded.data.data(), count, stride);
        if (m.filter == "EXPONENTIAL") meshopt_decodeFilterExp(decoded.data.data(), count, stride);
        tinygltf::BufferView& view = model->bufferViews.at(m.view);
        model->buffers.push_back(std::move(decoded));
        view.buffer = int(model->buffers.size()) - 1;
        view.byteOffset = 0;
        view.byteLength = count * stride;
    }
}

}  // namespace fp::gltf
