#pragma once
// glTF files written by the tests themselves: a builder that lays typed arrays into one buffer (with a
// buffer view and an accessor each) next to the JSON the test writes, and saves the lot as a .gltf with
// a base64 data URI, a .gltf with an external .bin, or a .glb.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace fp::test {

inline std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        uint32_t v =
            uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 | uint8_t(bytes[i + 2]);
        for (int k = 3; k >= 0; --k) out += digits[(v >> (6 * k)) & 63];
    }
    if (i < bytes.size()) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

class GltfBuilder {
  public:
    using json = nlohmann::json;
    static constexpr int kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;

    json doc = {{"asset", {{"version", "2.0"}, {"generator", "fragpath tests"}}}};
    std::string bin;  // buffers[0]

    // Appends raw bytes (4-byte aligned) with a buffer view; returns the view's index.
    int view(const std::string& bytes, json extra = json::object()) {
        while (bin.size() % 4) bin += '\0';
        json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}};
        v.update(extra);
        bin += bytes;
        return push("bufferViews", v);
    }

    // An accessor over `bytes` in a view of its own.
    int accessor(const std::string& bytes, int componentType, size_t count, const char* type,
                 json extra = json::object()) {
        json a = {
            {"bufferView", view(bytes)}, {"componentType", componentType}, {"count", count}, {"type", type}};
        a.update(extra);
        return push("accessors", a);
    }

    template <typename T>
    static std::string raw(const std::vector<T>& values) {
        return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    }

    int vec3(const std::vector<glm::vec3>& v) { return accessor(raw(v), kFloat, v.size(), "VEC3"); }
    int vec2(const std::vector<glm::vec2>& v) { return accessor(raw(v), kFloat, v.size(), "VEC2"); }
    int vec4(const std::vector<glm::vec4>& v) { return accessor(raw(v), kFloat, v.size(), "VEC4"); }
    int indices16(const std::vector<uint16_t>& v) {
        return accessor(raw(v), kUnsignedShort, v.size(), "SCALAR");
    }
    int indices32(const std::vector<uint32_t>& v) {
        return accessor(raw(v), kUnsignedInt, v.size(), "SCALAR");
    }

    int push(const char* array, const json& item) {
        if (!doc.contains(array)) doc[array] = json::array();
        doc[array].push_back(item);
        return int(doc[array].size()) - 1;
    }
    int mesh(const json& primitives) { return push("meshes", {{"primitives", primitives}}); }
    int node(const json& n) { return push("nodes", n); }
    int material(const json& m) { return push("materials", m); }
    void scene(const std::vector<int>& roots) {
        doc["scenes"] = json::array({{{"nodes", roots}}});
        doc["scene"] = 0;
    }

    // The JSON with buffers[0] as a data URI (or as `binName`, whose bytes the caller writes: bin), unless
    // the test wrote "buffers" itself.
    std::string gltf(const std::string& binName = "") const {
        json d = doc;
        if (!bin.empty() && !d.contains("buffers")) {
            std::string uri =
                binName.empty() ? "data:application/octet-stream;base64," + base64(bin) : binName;
            d["buffers"] = json::array({{{"byteLength", bin.size()}, {"uri", uri}}});
        }
        return d.dump(1);
    }

    // A binary glTF: the JSON chunk (padded with spaces) and the BIN chunk (padded with zeros).
    std::string glb() const {
        json d = doc;
        std::string payload = bin;
        if (!payload.empty() && !d.contains("buffers"))
            d["buffers"] = json::array({{{"byteLength", payload.size()}}});
        std::string text = d.dump();
        while (text.size() % 4) text += ' ';
        while (payload.size() % 4) payload += '\0';
        std::string out = "glTF";
        auto u32 = [&out](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
        u32(2);
        u32(uint32_t(12 + 8 + text.size() + (payload.empty() ? 0 : 8 + payload.size())));
        u32(uint32_t(text.size()));
        u32(0x4E4F534A);
        out += text;
        if (!payload.empty()) {
            u32(uint32_t(payload.size()));
            u32(0x004E4942);
            out += payload;
        }
        return out;
    }
};

}  // namespace fp::test
