// The glTF container and the schema check of its JSON, before tinygltf sees the file (gltf_internal.h).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "scene/gltf_internal.h"
#include "scene/text_file.h"

namespace fp::gltf {

namespace {

using nlohmann::json;

constexpr uint32_t kChunkJson = 0x4E4F534A;  // "JSON", little-endian
constexpr uint32_t kChunkBin = 0x004E4942;   // "BIN\0"
// Byte counts and offsets beyond this are not exact in the JSON numbers every reader parses as double.
constexpr uint64_t kMaxByteCount = uint64_t(1) << 53;
// Component types of glTF 2.0 accessors (INT and DOUBLE are not glTF 2.0, though tinygltf reads them).
constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125,
              kFloat = 5126;

uint32_t littleEndian32(std::string_view bytes, uint64_t at) {
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[size_t(at) + size_t(i)]);
    return v;
}

std::string withoutId(const json::exception& e) {
    std::string what = e.what();
    size_t start = what.find("] ");
    return start == std::string::npos ? what : what.substr(start + 2);
}

// The data-URI prefixes tinygltf decodes (all base64).
const char* const kDataUriPrefixes[] = {"data:application/octet-stream;base64,",
                                        "data:application/gltf-buffer;base64,",
                                        "data:image/jpeg;base64,",
                                        "data:image/png;base64,",
                                        "data:image/bmp;base64,",
                                        "data:image/gif;base64,",
                                        "data:text/plain;base64,"};

bool startsWith(const std::string& s, const char* prefix) {
    return s.compare(0, std::char_traits<char>::length(prefix), prefix) == 0;
}

// The payload of a data URI tinygltf decodes, or nullopt for another kind of data URI.
std::optional<std::string_view> base64Payload(const std::string& uri) {
    for (const char* prefix : kDataUriPrefixes)
        if (startsWith(uri, prefix))
            return std::string_view(uri).substr(std::char_traits<char>::length(prefix));
    return std::nullopt;
}

bool isBase64Digit(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/';
}

// The number of bytes a base64 payload decodes to, or an explanation of why it is not base64.
std::optional<uint64_t> decodedSize(std::string_view payload, std::string* why) {
    size_t digits = 0;
    while (digits < payload.size() && isBase64Digit(payload[digits])) ++digits;
    size_t padding = 0;
    while (digits + padding < payload.size() && payload[digits + padding] == '=') ++padding;
    if (digits + padding != payload.size()) {
        *why = "its base64 data has a character that is not base64 at offset " +
               std::to_string(digits + padding);
        return std::nullopt;
    }
    if (padding > 2 || digits % 4 == 1 || (padding > 0 && (digits + padding) % 4 != 0)) {
        *why = "its base64 data is truncated or wrongly padded";
        return std::nullopt;
    }
    return uint64_t(digits) / 4 * 3 + (digits % 4 == 0 ? 0 : digits % 4 - 1);
}

// Whether the URI names a scheme ("http:", "file:"): only relative references and data URIs are files
// we can open.
bool hasScheme(const std::string& uri) {
    if (uri.empty() || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
    for (char c : uri) {
        if (c == ':') return true;
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return false;
    }
    return false;
}

class Schema {
  public:
    Schema(const json& root, const Container& container, const std::string& name)
        : root_(root), container_(container), name_(name) {}

    void run() {
        if (!root_.is_object()) fail("the top level", "must be a JSON object, got " + shown(root_));
        asset();
        extensionLists();
        for (const char* array : {"accessors", "animations", "buffers", "bufferViews", "cameras", "images",
                                  "materials", "meshes", "nodes", "samplers", "scenes", "skins", "textures"})
            arrayOfObjects(root_, "", array);
        lightCount_ = lights();
        index(root_, "", "scene", "scenes", false);
        each("scenes", [&](const json& o, const std::string& path) { scene(o, path); });
        each("nodes", [&](const json& o, const std::string& path) { node(o, path); });
        each("meshes", [&](const json& o, const std::string& path) { mesh(o, path); });
        each("buffers", [&](const json& o, const std::string& path) { buffer(o, path); });
        each("bufferViews", [&](const json& o, const std::string& path) { bufferView(o, path); });
        each("accessors", [&](const json& o, const std::string& path) { accessor(o, path); });
        each("images", [&](const json& o, const std::string& path) { image(o, path); });
        each("textures", [&](const json& o, const std::string& path) {
            index(o, path, "source", "images", false);
            index(o, path, "sampler", "samplers", false);
        });
        each("samplers", [&](const json& o, const std::string& path) { sampler(o, path); });
        each("materials", [&](const json& o, const std::string& path) { material(o, path); });
        each("cameras", [&](const json& o, const std::string& path) { camera(o, path); });
    }

  private:
    [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
        throw Error(name_ + ": " + path + ": " + problem);
    }

    static std::string join(const std::string& path, const char* key) {
        return path.empty() ? std::string(key) : path + "." + key;
    }

    const json* find(const json& object, const char* key) const {
        auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    size_t count(const char* array) const {
        const json* a = find(root_, array);
        return a && a->is_array() ? a->size() : 0;
    }

    template <typename F>
    void each(const char* array, F check) {
        const json* a = find(root_, array);
        if (!a) return;
        for (size_t i = 0; i < a->size(); ++i)
            check((*a)[i], std::string(array) + "[" + std::to_string(i) + "]");
    }

    const json* object(const json& o, const std::string& path, const char* key, bool required = false) const {
        const json* v = find(o, key);
        if (!v) {
            if (required) fail(path, "missing \"" + std::string(key) + "\"");
            return nullptr;
        }
        if (!v->is_object()) fail(join(path, key), "must be a JSON object, got " + shown(*v));
        return v;
    }

    const json* array(const json& o, const std::string& path, const char* key, bool required = false) const {
        const json* v = find(o, key);
        if (!v) {
            if (required) fail(path, "missing \"" + std::string(key) + "\"");
            return nullptr;
        }
        if (!v->is_array()) fail(join(path, key), "must be an array, got " + shown(*v));
        return v;
    }

    void arrayOfObjects(const json& o, const std::string& path, const char* key) const {
        const json* a = array(o, path, key);
        if (!a) return;
        for (size_t i = 0; i < a->size(); ++i)
            if (!(*a)[i].is_object())
                fail(join(path, key) + "[" + std::to_string(i) + "]",
                     "must be a JSON object, got " + shown((*a)[i]));
    }

    // An integer in [lo, hi] (1.0 is not an integer here: tinygltf would silently ignore it).
    uint64_t integerValue(const json& v, const std::string& path, uint64_t lo, uint64_t hi) const {
        std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
        if (!v.is_number_integer()) fail(path, "must be an integer in " + range + ", got " + shown(v));
        if (!v.is_number_unsigned()) fail(path, "must be in " + range + ", got " + shown(v));  // negative
        uint64_t u = v.get<uint64_t>();
        if (u < lo || u > hi) fail(path, "must be in " + range + ", got " + shown(v));
        return u;
    }

    std::optional<uint64_t> integer(const json& o, const std::string& path, const char* key, uint64_t lo,
                                    uint64_t hi, bool required = false) const {
        const json* v = find(o, key);
        if (!v) {
            if (required) fail(path, "missing \"" + std::string(key) + "\"");
            return std::nullopt;
        }
        return integerValue(*v, join(path, key), lo, hi);
    }

    int indexValue(const json& v, const std::string& path, const char* target) const {
        if (!v.is_number_integer() || !v.is_number_unsigned())
            fail(path,
                 "must be an index into " + std::string(target) + " (an integer from 0), got " + shown(v));
        uint64_t u = v.get<uint64_t>();
        size_t n = std::string(target) == "lights" ? lightCount_ : count(target);
        if (u >= n)
            fail(path, std::string(target) + "[" + std::to_string(u) + "] does not exist (the file has " +
                           std::to_string(n) + ")");
        return int(u);
    }

    std::optional<int> index(const json& o, const std::string& path, const char* key, const char* target,
                             bool required) const {
        const json* v = find(o, key);
        if (!v) {
            if (required) fail(path, "missing \"" + std::string(key) + "\"");
            return std::nullopt;
        }
        return indexValue(*v, join(path, key), target);
    }

    void indexArray(const json& o, const std::string& path, const char* key, const char* target,
                    bool unique) const {
        const json* a = array(o, path, key);
        if (!a) return;
        std::set<int> seen;
        for (size_t i = 0; i < a->size(); ++i) {
            std::string item = join(path, key) + "[" + std::to_string(i) + "]";
            int at = indexValue((*a)[i], item, target);
            if (unique && !seen.insert(at).second)
                fail(item, "lists " + std::string(target) + "[" + std::to_string(at) + "] twice");
        }
    }

    double numberValue(const json& v, const std::string& path, double lo, double hi, bool aboveLo) const {
        if (!v.is_number()) fail(path, "must be a number, got " + shown(v));
        double d = v.get<double>();
        bool ok = (aboveLo ? d > lo : d >= lo) && d <= hi;
        if (!ok) {
            std::string range = std::string(aboveLo ? "(" : "[") + json(lo).dump() + ", " +
                                (std::isinf(hi) ? std::string("infinity)") : json(hi).dump() + "]");
            fail(path, "must be in " + range + ", got " + shown(v));
        }
        return d;
    }

    std::optional<double> number(const json& o, const std::string& path, const char* key, double lo,
                                 double hi, bool required = false, bool aboveLo = false) const {
        const json* v = find(o, key);
        if (!v) {
            if (required) fail(path, "missing \"" + std::string(key) + "\"");
            return std::nullopt;
        }
        return numberValue(*v, join(path, key), lo, hi, aboveLo);
    }

    // An array of exactly n numbers, each in [lo, hi].
    const json* numbers(const json& o, const std::string& path, const char* key, size_t n, double lo,
                        double hi) const {
        const json* a = find(o, key);
        if (!a) return nullptr;
        if (!a->is_array() || a->size() != n)
            fail(join(path, key), "must be an array of " + std::to_string(n) + " numbers, got " + shown(*a));
        for (size_t i = 0; i < n; ++i)
            numberValue((*a)[i], join(path, key) + "[" + std::to_string(i) + "]", lo, hi, false);
        return a;
    }

    std::optional<std::string> string(const json& o, const std::string& path, const char* key,
                                      bool required = false) const {
        const json* v = find(o, key);
        if (!v) {
            if (required) fail(path, "missing \"" + std::string(key) + "\"");
            return std::nullopt;
        }
        if (!v->is_string()) fail(join(path, key), "must be a string, got " + shown(*v));
        return v->get<std::string>();
    }

    void boolean(const json& o, const std::string& path, const char* key) const {
        const json* v = find(o, key);
        if (v && !v->is_boolean()) fail(join(path, key), "must be true or false, got " + shown(*v));
    }

    // ---- the sections

    void asset() const {
        const json* a = object(root_, "the top level", "asset", true);
        std::string version = *string(*a, "asset", "version", true);
        if (version.compare(0, 2, "2.") != 0)
            fail("asset.version", "'" + version + "': only glTF 2.0 files are supported");
        std::optional<std::string> minVersion = string(*a, "asset", "minVersion");
        if (minVersion && *minVersion != "2.0")
            fail("asset.minVersion", "'" + *minVersion + "': the file needs a newer glTF than 2.0");
    }

    void extensionLists() const {
        for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
            const json* a = array(root_, "", key);
            if (!a) continue;
            for (size_t i = 0; i < a->size(); ++i)
                if (!(*a)[i].is_string())
                    fail(std::string(key) + "[" + std::to_string(i) + "]",
                         "must be a string, got " + shown((*a)[i]));
        }
        const json* required = find(root_, "extensionsRequired");
        if (!required) return;
        for (const json& e : *required) {
            std::string extension = e.get<std::string>();
            if (isImplementedExtension(extension)) continue;
            if (extension == "KHR_meshopt_compression")
                throw Error(name_ + ": buffers compressed with " + extension +
                            " are not supported (only EXT_meshopt_compression is: save the file with it, or "
                            "without meshopt compression)");
            throw Error(name_ + ": the file requires the extension " + extension +
                        ", which fragpath does not implement");
        }
    }

    bool declares(const char* extension) const {
        const json* used = find(root_, "extensionsUsed");
        return used && std::find(used->begin(), used->end(), json(extension)) != used->end();
    }

    size_t lights() const {
        const json* extensions = object(root_, "", "extensions");
        if (!extensions) return 0;
        const json* punctual = object(*extensions, "extensions", "KHR_lights_punctual");
        if (!punctual) return 0;
        const json* list = array(*punctual, "extensions.KHR_lights_punctual", "lights");
        if (!list) return 0;
        for (size_t i = 0; i < list->size(); ++i) {
            std::string path = "extensions.KHR_lights_punctual.lights[" + std::to_string(i) + "]";
            if (!(*list)[i].is_object()) fail(path, "must be a JSON object, got " + shown((*list)[i]));
            string((*list)[i], path, "type", true);
        }
        return list->size();
    }

    void scene(const json& o, const std::string& path) const { indexArray(o, path, "nodes", "nodes", true); }

    void node(const json& o, const std::string& path) const {
        indexArray(o, path, "children", "nodes", true);
        index(o, path, "mesh", "meshes", false);
        index(o, path, "camera", "cameras", false);
        index(o, path, "skin", "skins", false);
        const double inf = std::numeric_limits<double>::infinity();
        const json* matrix = numbers(o, path, "matrix", 16, -inf, inf);
        const json* translation = numbers(o, path, "translation", 3, -inf, inf);
        const json* rotation = numbers(o, path, "rotation", 4, -1.0, 1.0);
        const json* scale = numbers(o, path, "scale", 3, -inf, inf);
        if (matrix && (translation || rotation || scale))
            fail(path, "has both a matrix and translation/rotation/scale (glTF allows one or the other)");
        if (matrix) {
            // Column-major: elements 3, 7 and 11 are the bottom row of the first three columns.
            const json& m = *matrix;
            if (m[3].get<double>() != 0.0 || m[7].get<double>() != 0.0 || m[11].get<double>() != 0.0 ||
                m[15].get<double>() != 1.0)
                fail(join(path, "matrix"), "must be an affine transform (bottom row 0, 0, 0, 1)");
        }
        if (rotation) {
            double norm = 0.0;
            for (const json& c : *rotation) norm += c.get<double>() * c.get<double>();
            if (!(norm > 1e-12)) fail(join(path, "rotation"), "is not a rotation (a zero quaternion)");
        }
        if (const json* extensions = object(o, path, "extensions"))
            if (const json* light = object(*extensions, join(path, "extensions"), "KHR_lights_punctual"))
                index(*light, join(path, "extensions.KHR_lights_punctual"), "light", "lights", true);
    }

    void mesh(const json& o, const std::string& path) const {
        const json* primitives = array(o, path, "primitives", true);
        if (primitives->empty()) fail(join(path, "primitives"), "must not be empty");
        for (size_t i = 0; i < primitives->size(); ++i) {
            std::string p = join(path, "primitives") + "[" + std::to_string(i) + "]";
            const json& primitive = (*primitives)[i];
            if (!primitive.is_object()) fail(p, "must be a JSON object, got " + shown(primitive));
            const json* attributes = object(primitive, p, "attributes", true);
            for (const auto& item : attributes->items())
                indexValue(item.value(), join(p, "attributes") + "." + item.key(), "accessors");
            index(primitive, p, "indices", "accessors", false);
            index(primitive, p, "material", "materials", false);
            integer(primitive, p, "mode", 0, 6);
            if (const json* extensions = object(primitive, p, "extensions"))
                if (const json* draco =
                        object(*extensions, join(p, "extensions"), "KHR_draco_mesh_compression"))
                    dracoExtension(*draco, join(p, "extensions.KHR_draco_mesh_compression"));
            if (const json* targets = array(primitive, p, "targets"))
                for (size_t t = 0; t < targets->size(); ++t) {
                    std::string tp = join(p, "targets") + "[" + std::to_string(t) + "]";
                    if (!(*targets)[t].is_object())
                        fail(tp, "must be a JSON object, got " + shown((*targets)[t]));
                    for (const auto& item : (*targets)[t].items())
                        indexValue(item.value(), tp + "." + item.key(), "accessors");
                }
        }
    }

    // The Draco data's view, and the attribute ids (gltf_draco.cpp decodes them).
    void dracoExtension(const json& o, const std::string& path) const {
        index(o, path, "bufferView", "bufferViews", true);
        const json* attributes = object(o, path, "attributes", true);
        for (const auto& item : attributes->items())
            integerValue(item.value(), join(path, "attributes") + "." + item.key(), 0,
                         (uint64_t(1) << 31) - 1);
    }

    void buffer(const json& o, const std::string& path) const {
        uint64_t byteLength = *integer(o, path, "byteLength", 1, kMaxByteCount, true);
        std::optional<std::string> uri = string(o, path, "uri");
        bool first = path == "buffers[0]";
        if (!uri) {
            // A fallback for views compressed with EXT_meshopt_compression (gltf_meshopt.cpp checks that
            // only those refer to it).
            if (!(container_.binary && first && container_.hasBin) && declares("EXT_meshopt_compression"))
                return;
            if (!container_.binary || !first)
                fail(path, "has no uri (only the first buffer of a .glb may omit it, to use the BIN chunk)");
            if (!container_.hasBin) fail(path, "refers to the .glb's BIN chunk, but the file has none");
            if (byteLength > container_.binSize)
                fail(join(path, "byteLength"), std::to_string(byteLength) + " exceeds the BIN chunk's " +
                                                   std::to_string(container_.binSize) + " bytes");
            return;
        }
        if (uri->empty()) fail(join(path, "uri"), "must not be empty");
        if (startsWith(*uri, "data:")) {
            std::optional<std::string_view> payload = base64Payload(*uri);
            if (!payload)
                fail(join(path, "uri"),
                     "is a data URI of a kind fragpath does not read (only base64, of type "
                     "application/octet-stream or application/gltf-buffer)");
            std::string why;
            std::optional<uint64_t> size = decodedSize(*payload, &why);
            if (!size) fail(join(path, "uri"), why);
            if (*size != byteLength)
                fail(path, "its data URI holds " + std::to_string(*size) + " bytes, but byteLength says " +
                               std::to_string(byteLength));
        } else if (hasScheme(*uri)) {
            fail(join(path, "uri"), "'" + uri->substr(0, 60) + "' is not a relative file path or a data URI");
        }
    }

    void bufferView(const json& o, const std::string& path) const {
        int buffer = *index(o, path, "buffer", "buffers", true);
        uint64_t offset = integer(o, path, "byteOffset", 0, kMaxByteCount).value_or(0);
        uint64_t length = *integer(o, path, "byteLength", 1, kMaxByteCount, true);
        if (std::optional<uint64_t> stride = integer(o, path, "byteStride", 4, 252))
            if (*stride % 4 != 0)
                fail(join(path, "byteStride"), "must be a multiple of 4, got " + std::to_string(*stride));
        integer(o, path, "target", 0, 65535);
        uint64_t bufferLength = root_.at("buffers").at(size_t(buffer)).at("byteLength").get<uint64_t>();
        if (offset + length > bufferLength)
            fail(path, "bytes " + std::to_string(offset) + " to " + std::to_string(offset + length) +
                           " lie beyond the end of buffers[" + std::to_string(buffer) + "] (" +
                           std::to_string(bufferLength) + " bytes)");
    }

    void accessor(const json& o, const std::string& path) const {
        index(o, path, "bufferView", "bufferViews", false);
        integer(o, path, "byteOffset", 0, kMaxByteCount);
        const json* componentType = find(o, "componentType");
        if (!componentType) fail(path, "missing \"componentType\"");
        int ct = int(integerValue(*componentType, join(path, "componentType"), 0, 65535));
        if (ct != kByte && ct != kUnsignedByte && ct != kShort && ct != kUnsignedShort &&
            ct != kUnsignedInt && ct != kFloat)
            fail(join(path, "componentType"), std::to_string(ct) + " is not a glTF 2.0 component type");
        integer(o, path, "count", 1, kMaxByteCount, true);
        std::string type = *string(o, path, "type", true);
        static const std::set<std::string> kTypes = {"SCALAR", "VEC2", "VEC3", "VEC4",
                                                     "MAT2",   "MAT3", "MAT4"};
        if (!kTypes.count(type)) fail(join(path, "type"), "'" + type + "' is not an accessor type");
        boolean(o, path, "normalized");
        if (const json* sparse = object(o, path, "sparse")) {
            std::string sp = join(path, "sparse");
            integer(*sparse, sp, "count", 1, (uint64_t(1) << 31) - 1, true);
            const json* indices = object(*sparse, sp, "indices", true);
            index(*indices, join(sp, "indices"), "bufferView", "bufferViews", true);
            integer(*indices, join(sp, "indices"), "byteOffset", 0, (uint64_t(1) << 31) - 1);
            integer(*indices, join(sp, "indices"), "componentType", 0, 65535, true);
            const json* values = object(*sparse, sp, "values", true);
            index(*values, join(sp, "values"), "bufferView", "bufferViews", true);
            integer(*values, join(sp, "values"), "byteOffset", 0, (uint64_t(1) << 31) - 1);
        }
    }

    void image(const json& o, const std::string& path) const {
        std::optional<std::string> uri = string(o, path, "uri");
        std::optional<int> view = index(o, path, "bufferView", "bufferViews", false);
        string(o, path, "mimeType");
        if (uri.has_value() == view.has_value())
            fail(path, "needs either a uri or a bufferView (and not both)");
        if (uri) {
            if (std::optional<std::string_view> payload = base64Payload(*uri)) {
                std::string why;
                if (!decodedSize(*payload, &why) || payload->empty())
                    fail(join(path, "uri"), why.empty() ? "its data URI is empty" : why);
            }
        }
    }

    void sampler(const json& o, const std::string& path) const {
        integer(o, path, "magFilter", 0, 65535);
        integer(o, path, "minFilter", 0, 65535);
        for (const char* wrap : {"wrapS", "wrapT"})
            if (std::optional<uint64_t> w = integer(o, path, wrap, 0, 65535))
                if (*w != 33071 && *w != 33648 && *w != 10497)
                    fail(join(path, wrap),
                         std::to_string(*w) + " is not a wrap mode (33071, 33648 or 10497)");
    }

    void textureInfo(const json& o, const std::string& path, const char* key) const {
        const json* info = object(o, path, key);
        if (!info) return;
        std::string p = join(path, key);
        index(*info, p, "index", "textures", true);
        integer(*info, p, "texCoord", 0, 1u << 16);
        number(*info, p, "scale", -std::numeric_limits<double>::infinity(),
               std::numeric_limits<double>::infinity());
        number(*info, p, "strength", 0.0, 1.0);
    }

    void material(const json& o, const std::string& path) const {
        const double inf = std::numeric_limits<double>::infinity();
        if (const json* pbr = object(o, path, "pbrMetallicRoughness")) {
            std::string p = join(path, "pbrMetallicRoughness");
            numbers(*pbr, p, "baseColorFactor", 4, 0.0, 1.0);
            number(*pbr, p, "metallicFactor", 0.0, 1.0);
            number(*pbr, p, "roughnessFactor", 0.0, 1.0);
            textureInfo(*pbr, p, "baseColorTexture");
            textureInfo(*pbr, p, "metallicRoughnessTexture");
        }
        for (const char* map : {"normalTexture", "occlusionTexture", "emissiveTexture"})
            textureInfo(o, path, map);
        numbers(o, path, "emissiveFactor", 3, 0.0, 1.0);
        if (std::optional<std::string> mode = string(o, path, "alphaMode"))
            if (*mode != "OPAQUE" && *mode != "MASK" && *mode != "BLEND")
                fail(join(path, "alphaMode"), "'" + *mode + "' is not OPAQUE, MASK or BLEND");
        number(o, path, "alphaCutoff", 0.0, inf);
        boolean(o, path, "doubleSided");
        const json* extensions = object(o, path, "extensions");
        if (!extensions) return;
        std::string ep = join(path, "extensions");
        if (const json* e = object(*extensions, ep, "KHR_materials_emissive_strength"))
            number(*e, join(ep, "KHR_materials_emissive_strength"), "emissiveStrength", 0.0, inf);
        if (const json* e = object(*extensions, ep, "KHR_materials_transmission")) {
            std::string p = join(ep, "KHR_materials_transmission");
            number(*e, p, "transmissionFactor", 0.0, 1.0);
            textureInfo(*e, p, "transmissionTexture");
        }
        if (const json* e = object(*extensions, ep, "KHR_materials_ior")) {
            std::string p = join(ep, "KHR_materials_ior");
            // The extension allows 0 (a special value) or an index of 1 or more.
            if (std::optional<double> ior = number(*e, p, "ior", 0.0, inf))
                if (*ior != 0.0 && *ior < 1.0)
                    fail(join(p, "ior"), "must be 0 or at least 1, got " + shown((*e)["ior"]));
        }
        if (const json* e = object(*extensions, ep, "KHR_materials_specular")) {
            std::string p = join(ep, "KHR_materials_specular");
            number(*e, p, "specularFactor", 0.0, 1.0);
            numbers(*e, p, "specularColorFactor", 3, 0.0, inf);
            textureInfo(*e, p, "specularTexture");
            textureInfo(*e, p, "specularColorTexture");
        }
        if (const json* e = object(*extensions, ep, "KHR_materials_volume")) {
            std::string p = join(ep, "KHR_materials_volume");
            number(*e, p, "thicknessFactor", 0.0, inf);
            number(*e, p, "attenuationDistance", 0.0, inf, false, true);
            numbers(*e, p, "attenuationColor", 3, 0.0, 1.0);
            textureInfo(*e, p, "thicknessTexture");
        }
        object(*extensions, ep, "KHR_materials_unlit");  // an object, of no properties
        if (const json* e = object(*extensions, ep, "KHR_materials_sheen")) {
            std::string p = join(ep, "KHR_materials_sheen");
            numbers(*e, p, "sheenColorFactor", 3, 0.0, 1.0);
            number(*e, p, "sheenRoughnessFactor", 0.0, 1.0);
            textureInfo(*e, p, "sheenColorTexture");
            textureInfo(*e, p, "sheenRoughnessTexture");
        }
        if (const json* e = object(*extensions, ep, "KHR_materials_clearcoat")) {
            std::string p = join(ep, "KHR_materials_clearcoat");
            number(*e, p, "clearcoatFactor", 0.0, 1.0);
            number(*e, p, "clearcoatRoughnessFactor", 0.0, 1.0);
            for (const char* map :
                 {"clearcoatTexture", "clearcoatRoughnessTexture", "clearcoatNormalTexture"})
                textureInfo(*e, p, map);
        }
    }

    void camera(const json& o, const std::string& path) const {
        std::string type = *string(o, path, "type", true);
        const double inf = std::numeric_limits<double>::infinity();
        if (type == "perspective") {
            const json* p = object(o, path, "perspective", true);
            std::string pp = join(path, "perspective");
            number(*p, pp, "yfov", 0.0, inf, true, true);
            number(*p, pp, "znear", 0.0, inf, true, true);
            number(*p, pp, "zfar", 0.0, inf, false, true);
            number(*p, pp, "aspectRatio", 0.0, inf, false, true);
        } else if (type == "orthographic") {
            const json* p = object(o, path, "orthographic", true);
            std::string pp = join(path, "orthographic");
            for (const char* key : {"xmag", "ymag", "zfar", "znear"}) number(*p, pp, key, -inf, inf, true);
        } else {
            fail(join(path, "type"), "'" + type + "' is neither perspective nor orthographic");
        }
    }

    const json& root_;
    const Container& container_;
    const std::string& name_;
    size_t lightCount_ = 0;
};

}  // namespace

std::string shown(const json& value) {
    std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
    return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

bool isImplementedExtension(const std::string& extension) {
    return extension == "KHR_materials_emissive_strength" || extension == "KHR_materials_transmission" ||
           extension == "KHR_materials_ior" || extension == "KHR_materials_specular" ||
           extension == "KHR_materials_unlit" || extension == "KHR_materials_volume" ||
           extension == "KHR_materials_clearcoat" || extension == "KHR_materials_sheen" ||
           extension == "KHR_lights_punctual" || extension == "KHR_texture_transform" ||
           extension == "KHR_mesh_quantization" || extension == "KHR_draco_mesh_compression" ||
           extension == "EXT_meshopt_compression" || extension == "EXT_mesh_gpu_instancing";
}

std::string percentDecoded(const std::string& uri) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

Container readContainer(std::string_view bytes, const std::string& name) {
    Container c;
    if (bytes.size() < 4 || bytes.substr(0, 4) != "glTF") {
        c.json = requireText(bytes, name);
        return c;
    }
    auto fail = [&name](const std::string& problem) { throw Error(name + ": not a valid .glb: " + problem); };
    c.binary = true;
    if (bytes.size() < 20)
        fail("it has " + std::to_string(bytes.size()) + " bytes, fewer than the 20 of its headers");
    uint32_t version = littleEndian32(bytes, 4), length = littleEndian32(bytes, 8);
    uint32_t jsonLength = littleEndian32(bytes, 12), jsonType = littleEndian32(bytes, 16);
    if (version != 2) fail("version " + std::to_string(version) + " (only glTF 2.0 binaries are supported)");
    if (length > bytes.size())
        fail("its header says " + std::to_string(length) + " bytes, but the file has " +
             std::to_string(bytes.size()) + " (truncated?)");
    if (jsonType != kChunkJson) fail("its first chunk is not JSON");
    uint64_t jsonEnd = 20 + uint64_t(jsonLength);
    if (jsonLength == 0 || jsonEnd > length)
        fail("its JSON chunk of " + std::to_string(jsonLength) + " bytes does not fit in the file's " +
             std::to_string(length));
    if (jsonEnd % 4 != 0) fail("its JSON chunk does not end on a 4-byte boundary");
    c.json = bytes.substr(20, jsonLength);
    if (jsonEnd < length) {
        if (jsonEnd + 12 > length) fail("a chunk after the JSON chunk is truncated");
        uint32_t binLength = littleEndian32(bytes, jsonEnd), binType = littleEndian32(bytes, jsonEnd + 4);
        if (binType != kChunkBin) fail("its second chunk is not BIN");
        if (binLength < 4 || binLength % 4 != 0 || jsonEnd + 8 + binLength > length)
            fail("its BIN chunk of " + std::to_string(binLength) +
                 " bytes is empty, not a multiple of 4 or does not fit in the file");
        c.hasBin = true;
        c.binSize = binLength;
    }
    return c;
}

json parseJson(std::string_view text, const std::string& name) {
    // Nesting depth, outside strings. tinygltf copies "extras" and extensions recursively.
    int depth = 0;
    bool inString = false, escaped = false;
    for (size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth)
                throw Error(name + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) +
                            " levels (at byte " + std::to_string(i) + ")");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    try {
        return json::parse(text.begin(), text.end());
    } catch (const json::parse_error& e) {
        throw Error(name + ": invalid JSON: " + withoutId(e));
    } catch (const json::exception& e) {
        throw Error(name + ": invalid JSON: " + withoutId(e));
    }
}

void checkSchema(const json& root, const Container& container, const std::string& name) {
    Schema(root, container, name).run();
}

}  // namespace fp::gltf
