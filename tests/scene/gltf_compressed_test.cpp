// Compressed glTF meshes load to the triangles of their uncompressed originals:
// - KHR_mesh_quantization: the Khronos sample AnimatedMorphCube, quantized by gltfpack (BYTE normals,
//   UNSIGNED_SHORT positions dequantized by its node's scale and translation), against its float
//   glTF-Binary variant; and a bumpy grid quantized in the test (integer positions, normalized BYTE
//   normals and UNSIGNED_SHORT texture coordinates) against the same grid in floats.
// - EXT_meshopt_compression: a small bumpy grid encoded in the test with meshoptimizer's encoders
//   (positions through the EXPONENTIAL filter, normals through OCTAHEDRAL, texture coordinates as they
//   are; indices as TRIANGLES and as INDICES), its fallback buffer a placeholder without data, against
//   the same grid uncompressed.
// - KHR_draco_mesh_compression: the same grid encoded in the test with Draco's encoder (positions
//   quantized to 14 bits, normals 10, texture coordinates 12), against the plain grid.
// Bad compressed data (truncated, counts that disagree, modes and filters the extension does not
// define) is one fp::Error naming the file, the buffer view or primitive and the problem.
#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "gltf_samples.h"
#include "gltf_test_util.h"
#include "scene/gltf.h"
#include "scene/load.h"
#include "scene_test_util.h"

namespace fp {
namespace {

using json = nlohmann::json;

float maxDistance(const glm::vec3& a, const glm::vec3& b) {
    glm::vec3 d = glm::abs(a - b);
    return std::max({d.x, d.y, d.z});
}

// The rotation r for which corner k of `t` is corner (k + r) % 3 of `u` within `tolerance` (per
// coordinate), or -1.
int sameTriangle(const Triangle& t, const Triangle& u, float tolerance) {
    for (int r = 0; r < 3; ++r) {
        bool all = true;
        for (size_t k = 0; k < 3; ++k)
            all = all && maxDistance(t.p[k], u.p[(k + size_t(r)) % 3]) <= tolerance;
        if (all) return r;
    }
    return -1;
}

// How far a loaded scene may be from its original.
struct Tolerances {
    float position = 0.0f;
    float normal = 2.0f;    // per coordinate; 2 checks nothing
    float texcoord = 2.0f;  // per coordinate
};

// Every triangle of `a` is one of `b` (as many of each), in the same winding, with the same normals and
// texture coordinates at its corners, within `tol`; the triangles' order and first corners may differ
// (compressors reorder and rotate them).
void expectSameTriangles(const Scene& a, const Scene& b, const Tolerances& tol) {
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    std::vector<bool> used(b.triangles.size(), false);
    for (size_t i = 0; i < a.triangles.size(); ++i) {
        const Triangle& t = a.triangles[i];
        int r = -1;
        size_t j = 0;
        for (; j < b.triangles.size() && r < 0; ++j)
            if (!used[j]) r = sameTriangle(t, b.triangles[j], tol.position);
        if (r < 0) {
            ADD_FAILURE() << "triangle " << i << " (" << t.p[0].x << ", " << t.p[0].y << ", " << t.p[0].z
                          << ") ... has no counterpart";
            continue;
        }
        const Triangle& u = b.triangles[--j];
        used[j] = true;
        for (size_t k = 0; k < 3; ++k) {
            size_t m = (k + size_t(r)) % 3;
            EXPECT_LE(maxDistance(t.n[k], u.n[m]), tol.normal) << "triangle " << i << " corner " << k;
            glm::vec2 d = glm::abs(t.uv[k] - u.uv[m]);
            EXPECT_LE(std::max(d.x, d.y), tol.texcoord) << "triangle " << i << " corner " << k;
        }
    }
}

TEST(GltfQuantized, AnimatedMorphCubeLoadsAsItsFloatVariant) {
    Scene quantized =
        loadScene(test::gltfSample("AnimatedMorphCube", "glTF-Quantized", "AnimatedMorphCube.gltf"));
    Scene plain = loadScene(test::gltfSample("AnimatedMorphCube", "glTF-Binary", "AnimatedMorphCube.glb"));
    // The positions' quantization step in world units: UNSIGNED_SHORT steps times the node's scale
    // (3.64900689e-06) times its parent's (100); rounding is within half a step.
    const float step = 3.64900689e-06f * 100.0f;
    Aabb q = quantized.bounds(), p = plain.bounds();
    EXPECT_LE(maxDistance(q.lo, p.lo), step) << "quantized bounds differ from the float file's";
    EXPECT_LE(maxDistance(q.hi, p.hi), step);
    EXPECT_GT(maxDistance(p.lo, p.hi), 1000.0f * step);  // the cube spans many steps
    expectSameTriangles(quantized, plain, {step});
    // Normals from normalized BYTEs (steps of 1/127), renormalized after the node's transform.
    for (const Triangle& t : quantized.triangles) {
        glm::vec3 geometric = glm::normalize(t.geometricNormal());
        for (const glm::vec3& n : t.n) {
            EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
            EXPECT_GT(glm::dot(n, geometric), 0.999f) << "a cube's normals are its faces'";
        }
    }
}

// A 4 x 4 grid of vertices over [0, 1]^2 whose heights make every normal different: 18 triangles,
// indexed.
struct Grid {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uv;
    std::vector<uint32_t> indices;
};

Grid bumpyGrid() {
    Grid g;
    const int n = 4;
    auto height = [](float x, float y) { return 0.2f * std::sin(3.0f * x) * std::cos(2.0f * y); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            float x = float(i) / (n - 1), y = float(j) / (n - 1);
            g.positions.push_back({x, y, height(x, y)});
            // The height field's normal (-dh/dx, -dh/dy, 1), normalized.
            glm::vec3 normal(-0.6f * std::cos(3.0f * x) * std::cos(2.0f * y),
                             0.4f * std::sin(3.0f * x) * std::sin(2.0f * y), 1.0f);
            g.normals.push_back(glm::normalize(normal));
            g.uv.push_back({x, 1.0f - y});
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            uint32_t a = uint32_t(j * n + i), b = a + 1, c = a + uint32_t(n), d = c + 1;
            for (uint32_t v : {a, b, d, a, d, c}) g.indices.push_back(v);
        }
    return g;
}

Scene loadBytes(const std::string& file, const std::string& bytes) {
    test::TempDir dir;
    return loadScene(dir.write(file, bytes));
}

std::string rejected(const std::string& file, const std::string& bytes) {
    test::TempDir dir;
    std::string path = dir.write(file, bytes);
    return test::errorOf([&] { loadScene(path); });
}

// Lists the extensions as used and required, as files using compression must.
void requireExtensions(test::GltfBuilder& b, const std::vector<std::string>& extensions) {
    b.doc["extensionsUsed"] = extensions;
    b.doc["extensionsRequired"] = extensions;
}

// The grid as a plain glTF: float attributes, UNSIGNED_SHORT indices.
test::GltfBuilder plainGrid(const Grid& g) {
    test::GltfBuilder b;
    std::vector<uint16_t> indices(g.indices.begin(), g.indices.end());
    json attributes = {
        {"POSITION", b.vec3(g.positions)}, {"NORMAL", b.vec3(g.normals)}, {"TEXCOORD_0", b.vec2(g.uv)}};
    b.mesh(json::array({{{"attributes", attributes}, {"indices", b.indices16(indices)}}}));
    b.node({{"mesh", 0}});
    b.scene({0});
    return b;
}

// ---- KHR_mesh_quantization

// The grid quantized as gltfpack does without normalizing positions: UNSIGNED_SHORT positions (in steps
// of 1/1000, offset by 1) that its node scales and translates back, normalized BYTE normals (stride 4),
// normalized UNSIGNED_SHORT texture coordinates.
test::GltfBuilder quantizedGrid(const Grid& g) {
    test::GltfBuilder b;
    std::vector<uint16_t> p, uv;
    std::vector<int8_t> n;
    for (size_t i = 0; i < g.positions.size(); ++i) {
        for (int c = 0; c < 3; ++c) p.push_back(uint16_t(std::lround((g.positions[i][c] + 1.0f) * 1000.0f)));
        p.push_back(0);
        for (int c = 0; c < 3; ++c) n.push_back(int8_t(std::lround(g.normals[i][c] * 127.0f)));
        n.push_back(0);
        for (int c = 0; c < 2; ++c) uv.push_back(uint16_t(std::lround(g.uv[i][c] * 65535.0f)));
    }
    size_t count = g.positions.size();
    auto accessor = [&](const std::string& bytes, int stride, int componentType, bool normalized,
                        const char* type) {
        json extra = stride ? json{{"byteStride", stride}} : json::object();
        return b.push("accessors", {{"bufferView", b.view(bytes, extra)},
                                    {"componentType", componentType},
                                    {"normalized", normalized},
                                    {"count", count},
                                    {"type", type}});
    };
    json attributes = {{"POSITION", accessor(test::GltfBuilder::raw(p), 8, 5123, false, "VEC3")},
                       {"NORMAL", accessor(test::GltfBuilder::raw(n), 4, 5120, true, "VEC3")},
                       {"TEXCOORD_0", accessor(test::GltfBuilder::raw(uv), 0, 5123, true, "VEC2")}};
    std::vector<uint16_t> indices(g.indices.begin(), g.indices.end());
    b.mesh(json::array({{{"attributes", attributes}, {"indices", b.indices16(indices)}}}));
    b.node({{"mesh", 0}, {"scale", {0.001, 0.001, 0.001}}, {"translation", {-1, -1, -1}}});
    b.scene({0});
    requireExtensions(b, {"KHR_mesh_quantization"});
    return b;
}

TEST(GltfQuantized, IntegerPositionsNormalizedNormalsAndTexcoordsLoadAsThePlainGrid) {
    Grid g = bumpyGrid();
    Scene plain = loadBytes("plain.gltf", plainGrid(g).gltf());
    Scene quantized = loadBytes("grid.gltf", quantizedGrid(g).gltf());
    // Half a step each: positions 1/2000, normals 1/254 per coordinate (then renormalized, allow 2/127),
    // texture coordinates 1/131070.
    expectSameTriangles(quantized, plain, {0.5e-3f + 1e-6f, 2.0f / 127.0f, 1e-5f});
}

// ---- EXT_meshopt_compression

// A glTF whose views are meshopt streams in buffers[0] and whose fallback, buffers[1], has no data.
struct MeshoptFile {
    test::GltfBuilder b;
    uint64_t fallbackSize = 0;

    // A view of `count` elements of `stride` bytes decoded from `stream` (appended to buffers[0]).
    int view(const std::string& stream, size_t count, size_t stride, const char* mode, const char* filter,
             bool withStride) {
        while (b.bin.size() % 4) b.bin += '\0';
        json extension = {{"buffer", 0},
                          {"byteOffset", b.bin.size()},
                          {"byteLength", stream.size()},
                          {"byteStride", stride},
                          {"count", count},
                          {"mode", mode}};
        if (std::string(filter) != "NONE") extension["filter"] = filter;
        b.bin += stream;
        json v = {{"buffer", 1},
                  {"byteOffset", fallbackSize},
                  {"byteLength", count * stride},
                  {"extensions", {{"EXT_meshopt_compression", extension}}}};
        if (withStride) v["byteStride"] = stride;
        fallbackSize += (count * stride + 3) / 4 * 4;
        return b.push("bufferViews", v);
    }

    int accessor(int view, int componentType, size_t count, const char* type, bool normalized = false) {
        json a = {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
        if (normalized) a["normalized"] = true;
        return b.push("accessors", a);
    }

    // `glb`: buffers[0] is the BIN chunk; else a data URI.
    std::string bytes(bool glb) {
        requireExtensions(b, {"EXT_meshopt_compression", "KHR_mesh_quantization"});
        json data = {{"byteLength", b.bin.size()}};
        if (!glb) data["uri"] = "data:application/octet-stream;base64," + test::base64(b.bin);
        json fallback = {{"byteLength", fallbackSize},
                         {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}};
        b.doc["buffers"] = {data, fallback};
        return glb ? b.glb() : b.gltf();
    }
};

std::string encodeVertices(const void* data, size_t count, size_t stride) {
    std::string out(meshopt_encodeVertexBufferBound(count, stride), '\0');
    out.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(out.data()), out.size(), data,
                                          count, stride));
    return out;
}

// The grid with its views meshopt-compressed: positions with the EXPONENTIAL filter (15-bit mantissas),
// normals as OCTAHEDRAL normalized SHORTs (stride 8, 12 bits), texture coordinates unfiltered, indices as
// `indexMode` (TRIANGLES: UNSIGNED_SHORT; INDICES: UNSIGNED_INT).
MeshoptFile meshoptGrid(const Grid& g, const char* indexMode) {
    MeshoptFile f;
    size_t n = g.positions.size();
    std::vector<uint32_t> exp(n * 3);
    meshopt_encodeFilterExp(exp.data(), n, 12, 15, &g.positions[0].x);
    int p = f.view(encodeVertices(exp.data(), n, 12), n, 12, "ATTRIBUTES", "EXPONENTIAL", true);
    std::vector<float> normals4;
    for (const glm::vec3& v : g.normals) normals4.insert(normals4.end(), {v.x, v.y, v.z, 0.0f});
    std::vector<int16_t> oct(n * 4);
    meshopt_encodeFilterOct(oct.data(), n, 8, 12, normals4.data());
    int nv = f.view(encodeVertices(oct.data(), n, 8), n, 8, "ATTRIBUTES", "OCTAHEDRAL", true);
    int uv = f.view(encodeVertices(g.uv.data(), n, 8), n, 8, "ATTRIBUTES", "NONE", true);
    size_t count = g.indices.size();
    std::string stream(
        std::max(meshopt_encodeIndexBufferBound(count, n), meshopt_encodeIndexSequenceBound(count, n)), '\0');
    auto* out = reinterpret_cast<unsigned char*>(stream.data());
    bool triangles = std::string(indexMode) == "TRIANGLES";
    stream.resize(triangles ? meshopt_encodeIndexBuffer(out, stream.size(), g.indices.data(), count)
                            : meshopt_encodeIndexSequence(out, stream.size(), g.indices.data(), count));
    int iv = f.view(stream, count, triangles ? 2 : 4, indexMode, "NONE", false);
    json attributes = {{"POSITION", f.accessor(p, test::GltfBuilder::kFloat, n, "VEC3")},
                       {"NORMAL", f.accessor(nv, 5122, n, "VEC3", true)},
                       {"TEXCOORD_0", f.accessor(uv, test::GltfBuilder::kFloat, n, "VEC2")}};
    int indices = f.accessor(
        iv, triangles ? test::GltfBuilder::kUnsignedShort : test::GltfBuilder::kUnsignedInt, count, "SCALAR");
    f.b.mesh(json::array({{{"attributes", attributes}, {"indices", indices}}}));
    f.b.node({{"mesh", 0}});
    f.b.scene({0});
    return f;
}

TEST(GltfMeshopt, CompressedGridLoadsAsThePlainOne) {
    Grid g = bumpyGrid();
    Scene plain = loadBytes("plain.gltf", plainGrid(g).gltf());
    ASSERT_EQ(plain.triangles.size(), 18u);
    for (const char* mode : {"TRIANGLES", "INDICES"})
        for (bool glb : {false, true}) {
            SCOPED_TRACE(std::string(mode) + (glb ? " .glb" : " .gltf"));
            Scene compressed = loadBytes(glb ? "grid.glb" : "grid.gltf", meshoptGrid(g, mode).bytes(glb));
            // Positions in [0, 1] with 15-bit signed mantissas and an exponent shared by each vector's
            // coordinates: steps of 2^-14 (rounded to within half of one); normals from 12-bit octahedral
            // coordinates stored as 16-bit normalized integers: within 2^-10.
            expectSameTriangles(compressed, plain,
                                {std::ldexp(1.0f, -14), std::ldexp(1.0f, -10), 0.0f});  // uv: stored exactly
        }
}

TEST(GltfMeshopt, BadStreamsAreErrorsNamingTheView) {
    Grid g = bumpyGrid();
    // The file as JSON with its compressed views' extension objects (views 0-3) edited.
    auto edited = [&](const std::function<void(json&)>& edit, const char* mode = "TRIANGLES") {
        json doc = json::parse(meshoptGrid(g, mode).bytes(false));
        edit(doc);
        return rejected("bad.gltf", doc.dump());
    };
    auto ext = [](json& d, int view) -> json& {
        return d["bufferViews"][view]["extensions"]["EXT_meshopt_compression"];
    };
    EXPECT_CONTAINS_ALL(
        edited([&](json& d) { ext(d, 0)["byteLength"] = ext(d, 0)["byteLength"].get<int>() - 8; }),
        "bad.gltf: bufferViews[0] (EXT_meshopt_compression, mode ATTRIBUTES): its ",
        "bytes do not decode to 16 elements of 12 bytes (the stream");
    EXPECT_CONTAINS_ALL(
        edited([&](json& d) { ext(d, 3)["byteLength"] = ext(d, 3)["byteLength"].get<int>() - 4; }),
        "bad.gltf: bufferViews[3] (EXT_meshopt_compression, mode TRIANGLES): its ");
    EXPECT_CONTAINS_ALL(
        edited([&](json& d) { ext(d, 3)["byteLength"] = ext(d, 3)["byteLength"].get<int>() - 4; }, "INDICES"),
        "bad.gltf: bufferViews[3] (EXT_meshopt_compression, mode INDICES): its ");
    // A stream's first byte names its codec and version.
    EXPECT_CONTAINS_ALL(
        edited([&](json& d) { ext(d, 2)["byteOffset"] = ext(d, 2)["byteOffset"].get<int>() + 4; }),
        "bad.gltf: bufferViews[2] (EXT_meshopt_compression, mode ATTRIBUTES): its ",
        "(not a stream this meshoptimizer (0.18) reads)");
    EXPECT_CONTAINS_ALL(edited([&](json& d) { ext(d, 1)["count"] = 15; }),
                        "bad.gltf: bufferViews[1].extensions.EXT_meshopt_compression: 15 elements of 8 bytes "
                        "(count, byteStride) do not make the view's byteLength 128");
    EXPECT_CONTAINS_ALL(
        edited([&](json& d) {
            ext(d, 1)["filter"] = "QUATERNION";
            ext(d, 1)["byteStride"] = 4;
            d["bufferViews"][1].erase("byteStride");
            ext(d, 1)["count"] = 32;
        }),
        "bufferViews[1].extensions.EXT_meshopt_compression.filter: 'QUATERNION' with byteStride 4 "
        "is not a filter the extension defines");
    EXPECT_CONTAINS_ALL(
        edited([&](json& d) { ext(d, 0)["mode"] = "VERTICES"; }),
        "bufferViews[0].extensions.EXT_meshopt_compression.mode: 'VERTICES' is not ATTRIBUTES, "
        "TRIANGLES or INDICES");
    EXPECT_CONTAINS_ALL(
        edited([&](json& d) { ext(d, 3)["filter"] = "OCTAHEDRAL"; }),
        "bufferViews[3].extensions.EXT_meshopt_compression.filter: must be NONE in mode TRIANGLES");
    EXPECT_CONTAINS_ALL(edited([&](json& d) { ext(d, 0)["byteStride"] = 16; }),
                        "bufferViews[0].extensions.EXT_meshopt_compression.byteStride: 16 differs from the "
                        "view's byteStride 12");
    EXPECT_CONTAINS_ALL(edited([&](json& d) { ext(d, 0)["buffer"] = 1; }),
                        "bufferViews[0].extensions.EXT_meshopt_compression.buffer: buffers[1] has no uri, so "
                        "holds no compressed data");
    EXPECT_CONTAINS_ALL(edited([&](json& d) { ext(d, 0).erase("mode"); }),
                        "bufferViews[0].extensions.EXT_meshopt_compression: missing \"mode\"");
    EXPECT_CONTAINS_ALL(edited([&](json& d) { ext(d, 0).erase("count"); }),
                        "bufferViews[0].extensions.EXT_meshopt_compression: missing \"count\"");
    EXPECT_CONTAINS_ALL(edited([&](json& d) { ext(d, 0)["byteLength"] = 2; }),
                        "bufferViews[0].extensions.EXT_meshopt_compression: its 2 compressed bytes cannot "
                        "decode to the 192 of the view");
    // Only compressed views may use the fallback buffer, which has no data.
    EXPECT_CONTAINS_ALL(edited([&](json& d) { d["bufferViews"][0].erase("extensions"); }),
                        "bad.gltf: bufferViews[0]: refers to buffers[1], which has no uri");
    // Without the extension declared, a buffer without a uri is the old error.
    EXPECT_CONTAINS_ALL(edited([&](json& d) {
                            d.erase("extensionsUsed");
                            d.erase("extensionsRequired");
                        }),
                        "bad.gltf: buffers[1]: has no uri");
}

// ---- KHR_draco_mesh_compression

// The grid as a Draco mesh, encoded with Draco's default (edgebreaker) method.
std::string dracoGrid(const Grid& g) {
    draco::Mesh mesh;
    size_t n = g.positions.size();
    mesh.set_num_points(uint32_t(n));
    auto add = [&](draco::GeometryAttribute::Type type, int components, const float* values) {
        draco::GeometryAttribute attribute;
        attribute.Init(type, nullptr, uint8_t(components), draco::DT_FLOAT32, false,
                       int64_t(sizeof(float)) * components, 0);
        int id = mesh.AddAttribute(attribute, true, uint32_t(n));
        for (size_t i = 0; i < n; ++i)
            mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(uint32_t(i)),
                                                  values + i * size_t(components));
        return id;
    };
    add(draco::GeometryAttribute::POSITION, 3, &g.positions[0].x);
    add(draco::GeometryAttribute::NORMAL, 3, &g.normals[0].x);
    add(draco::GeometryAttribute::TEX_COORD, 2, &g.uv[0].x);
    for (size_t t = 0; t < g.indices.size(); t += 3)
        mesh.AddFace({draco::PointIndex(g.indices[t]), draco::PointIndex(g.indices[t + 1]),
                      draco::PointIndex(g.indices[t + 2])});
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
    draco::EncoderBuffer out;
    draco::Status status = encoder.EncodeMeshToBuffer(mesh, &out);
    EXPECT_TRUE(status.ok()) << status.error_msg_string();
    return std::string(out.data(), out.size());
}

// A glTF of one primitive whose data is `stream` (attribute ids 0 POSITION, 1 NORMAL, 2 TEXCOORD_0):
// accessors without buffer views, their counts the decoded mesh's.
test::GltfBuilder dracoFile(const std::string& stream) {
    draco::DecoderBuffer buffer;
    buffer.Init(stream.data(), stream.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    EXPECT_TRUE(decoded.ok());
    size_t points = decoded.ok() ? decoded.value()->num_points() : 1;
    size_t faces = decoded.ok() ? decoded.value()->num_faces() : 1;
    test::GltfBuilder b;
    int view = b.view(stream);
    auto accessor = [&](int componentType, size_t count, const char* type) {
        return b.push("accessors", {{"componentType", componentType}, {"count", count}, {"type", type}});
    };
    json attributes = {{"POSITION", accessor(test::GltfBuilder::kFloat, points, "VEC3")},
                       {"NORMAL", accessor(test::GltfBuilder::kFloat, points, "VEC3")},
                       {"TEXCOORD_0", accessor(test::GltfBuilder::kFloat, points, "VEC2")}};
    json extension = {{"bufferView", view},
                      {"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}}};
    b.mesh(json::array({{{"attributes", attributes},
                         {"indices", accessor(test::GltfBuilder::kUnsignedShort, 3 * faces, "SCALAR")},
                         {"extensions", {{"KHR_draco_mesh_compression", extension}}}}}));
    b.node({{"mesh", 0}});
    b.scene({0});
    requireExtensions(b, {"KHR_draco_mesh_compression"});
    return b;
}

TEST(GltfDraco, CompressedGridLoadsAsThePlainOne) {
    Grid g = bumpyGrid();
    Scene plain = loadBytes("plain.gltf", plainGrid(g).gltf());
    test::GltfBuilder b = dracoFile(dracoGrid(g));
    for (bool glb : {false, true}) {
        SCOPED_TRACE(glb ? ".glb" : ".gltf");
        Scene compressed = loadBytes(glb ? "grid.glb" : "grid.gltf", glb ? b.glb() : b.gltf());
        // Quantized over the attributes' ranges: positions (range 1) in 2^14 steps, texture coordinates
        // (range 1) in 2^12, each within half a step; normals in Draco's 10-bit octahedral coordinates
        // (steps of about 2^-9 of the octahedron's side, allowed twice that per coordinate).
        expectSameTriangles(compressed, plain,
                            {std::ldexp(1.0f, -14), std::ldexp(1.0f, -8), std::ldexp(1.0f, -12)});
    }
}

TEST(GltfDraco, BadDataIsAnErrorNamingThePrimitive) {
    Grid g = bumpyGrid();
    std::string stream = dracoGrid(g);
    auto edited = [&](const std::function<void(test::GltfBuilder&)>& edit, const std::string& data) {
        test::GltfBuilder b = dracoFile(stream);
        if (data != stream) {  // the same JSON over other data
            b.bin = data;
            b.doc["bufferViews"][0]["byteLength"] = data.size();
        }
        edit(b);
        return rejected("bad.gltf", b.gltf());
    };
    auto none = [](test::GltfBuilder&) {};
    auto ext = [](test::GltfBuilder& b) -> json& {
        return b.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"];
    };
    const std::string where = "bad.gltf: meshes[0].primitives[0] (KHR_draco_mesh_compression): ";
    EXPECT_CONTAINS_ALL(edited(none, stream.substr(0, stream.size() / 2)),
                        where + "bufferViews[0] does not decode (Draco: ");
    EXPECT_CONTAINS_ALL(edited(none, "DRACO but not really"), where + "bufferViews[0] ");
    EXPECT_CONTAINS_ALL(edited(none, std::string(64, '\x7f')), where + "bufferViews[0] is not Draco data");
    EXPECT_CONTAINS_ALL(edited([&](test::GltfBuilder& b) { ext(b)["attributes"]["NORMAL"] = 7; }, stream),
                        where + "attribute id 7 (NORMAL) is not in the Draco data (which has 3 attributes)");
    EXPECT_CONTAINS_ALL(edited([](test::GltfBuilder& b) { b.doc["accessors"][1]["count"] = 5; }, stream),
                        where + "accessors[1] (NORMAL) has 5 elements, but the Draco data has ");
    EXPECT_CONTAINS_ALL(edited([](test::GltfBuilder& b) { b.doc["accessors"][3]["count"] = 6; }, stream),
                        where + "accessors[3] (indices) has 6 elements, but the Draco data has 18 triangles");
    EXPECT_CONTAINS_ALL(edited([](test::GltfBuilder& b) { b.doc["accessors"][2]["type"] = "VEC3"; }, stream),
                        where + "accessors[2] (TEXCOORD_0) has 3 components, but Draco attribute 2 has 2");
    EXPECT_CONTAINS_ALL(
        edited([](test::GltfBuilder& b) { b.doc["meshes"][0]["primitives"][0]["mode"] = 1; }, stream),
        where + "mode 1 is not TRIANGLES or TRIANGLE_STRIP");
    // The schema check: the extension's own properties.
    EXPECT_CONTAINS_ALL(
        edited([&](test::GltfBuilder& b) { ext(b)["attributes"]["NORMAL"] = -1; }, stream),
        "bad.gltf: meshes[0].primitives[0].extensions.KHR_draco_mesh_compression.attributes.NORMAL: "
        "must be in [0, 2147483647], got -1");
    EXPECT_CONTAINS_ALL(edited([&](test::GltfBuilder& b) { ext(b)["bufferView"] = 4; }, stream),
                        "bad.gltf: meshes[0].primitives[0].extensions.KHR_draco_mesh_compression.bufferView: "
                        "bufferViews[4] does not exist");
    // An attribute the extension does not name is read as usual: here it has no data.
    EXPECT_CONTAINS_ALL(edited([&](test::GltfBuilder& b) { ext(b)["attributes"].erase("NORMAL"); }, stream),
                        "bad.gltf: accessors[1] (NORMAL of meshes[0].primitives[0]) has no bufferView");
}

// ---- robustness

// Loads the .glb; true if it loaded, false if it was refused with an fp::Error (anything else, or a
// crash, fails the test).
bool loadsOrIsRefused(const std::string& glb, const std::string& what) {
    try {
        WarningCapture quiet;
        fp::Scene scene = parseGltf(glb, "mutated.glb", [](const std::string&) { return std::nullopt; });
        for (const Triangle& t : scene.triangles)
            for (const glm::vec3& p : t.p)
                EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << what;
        return true;
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("mutated.glb: "), std::string::npos) << what << ": " << e.what();
        return false;
    }
}

// Every truncation of the Draco stream, and every byte of it and of the meshopt streams inverted, loads or
// is an fp::Error: a deterministic sweep of what the fuzzer tries at random (run under AddressSanitizer
// by `make sanitize`).
TEST(GltfCompressedRobustness, EveryTruncationAndInvertedByteLoadsOrIsAnError) {
    Grid g = bumpyGrid();
    const test::GltfBuilder draco = dracoFile(dracoGrid(g));
    size_t refused = 0, tried = 0;
    for (size_t n = 0; n < draco.bin.size(); ++n) {
        test::GltfBuilder b = draco;
        b.bin.resize(n == 0 ? 1 : n);
        b.doc["bufferViews"][0]["byteLength"] = b.bin.size();
        refused += !loadsOrIsRefused(b.glb(), "Draco stream cut to " + std::to_string(n) + " bytes");
        ++tried;
    }
    for (size_t i = 0; i < draco.bin.size(); ++i) {
        test::GltfBuilder b = draco;
        b.bin[i] = char(~b.bin[i]);
        refused += !loadsOrIsRefused(b.glb(), "Draco byte " + std::to_string(i) + " inverted");
        ++tried;
    }
    MeshoptFile meshopt = meshoptGrid(g, "TRIANGLES");
    std::string glb = meshopt.bytes(true);
    // The BIN chunk's payload ends the file, padded to 4 bytes.
    size_t bin = glb.size() - (meshopt.b.bin.size() + 3) / 4 * 4;
    for (size_t i = bin; i < glb.size(); ++i) {
        std::string mutated = glb;
        mutated[i] = char(~mutated[i]);
        refused += !loadsOrIsRefused(mutated, "meshopt byte " + std::to_string(i - bin) + " inverted");
        ++tried;
    }
    // Most of them are caught: the truncations all are.
    EXPECT_GE(refused, draco.bin.size()) << refused << " of " << tried << " refused";
    std::printf("%zu of %zu mutated files refused, the others loaded\n", refused, tried);
}

}  // namespace
}  // namespace fp
