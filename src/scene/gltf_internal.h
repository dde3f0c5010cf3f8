#pragma once
// The glTF loader's parts (src/scene/gltf_*.cpp), in the order they run:
//   1. gltf_preflight.cpp: the GLB container and a schema check of the raw JSON, so that tinygltf only
//      ever sees files whose indices, types and byte ranges it can follow without reading out of bounds
//      (tinygltf 2.7 reads an image's bufferView unchecked, silently ignores wrongly typed optional
//      properties and wraps indices beyond 2^31) and every message names the property ("nodes[3].mesh").
//   2. gltf_loader.cpp: tinygltf itself, with our file access and image callbacks; the conversion.
//      Around it, for compressed meshes: gltf_meshopt.cpp checks EXT_meshopt_compression's views,
//      gltf_tinygltf_input.cpp rewrites what tinygltf 2.7 would refuse (placeholder buffers, Draco's
//      indices without a buffer view), then gltf_meshopt.cpp and gltf_draco.cpp decode into the model.
//   3. gltf_nodes.cpp: the node forest (trees, no cycles), world transforms, the camera.
//   4. gltf_accessor.cpp: bounds-checked reading of accessors.
//   5. gltf_mesh.cpp: primitives to world-space triangles.
//   6. gltf_material.cpp: glTF materials onto fragpath's models, and their textures.
//
// Every translation unit that includes tiny_gltf.h must see the same configuration (it changes the
// TinyGLTF class's default members), so they all include it through this header.
// Images are decoded by fp::decodeRgba8 (as OBJ textures are), and only when a material uses them; image
// files are read through our lookup, only then too; we never write glTF.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <cstdint>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include "scene/gltf.h"

namespace fp::gltf {

// The renderer's limit on triangles (pack/layout.h kMaxFloatIndex: triangle indices are exact floats
// below 2^24); a file that would flatten into more (instancing multiplies) is refused before allocating.
constexpr uint64_t kMaxTriangles = (uint64_t(1) << 24) - 1;

// Nesting deeper than this in the JSON is refused (tinygltf copies extras and extensions recursively).
constexpr int kMaxJsonDepth = 64;

// ---- gltf_preflight.cpp

// What the file holds: the JSON text (a view into the file's bytes) and, for a .glb, its BIN chunk.
struct Container {
    std::string_view json;
    bool binary = false;
    bool hasBin = false;
    uint64_t binSize = 0;
};

// Splits a .glb into its chunks, or checks that a .gltf is text; throws fp::Error naming `name`.
Container readContainer(std::string_view bytes, const std::string& name);

// Parses the JSON (refusing nesting deeper than kMaxJsonDepth first); throws fp::Error with the position.
nlohmann::json parseJson(std::string_view text, const std::string& name);

// The schema check of everything the loader reads (see the top of this file); throws fp::Error
// "<name>: <json path>: <problem>".
void checkSchema(const nlohmann::json& root, const Container& container, const std::string& name);

// A JSON value as messages quote it: at most 60 characters.
std::string shown(const nlohmann::json& value);

// The extensions the loader implements (the others in extensionsUsed are ignored with a warning).
bool isImplementedExtension(const std::string& extension);

// `uri` with %XX escapes decoded, as a file path.
std::string percentDecoded(const std::string& uri);

// ---- gltf_meshopt.cpp (EXT_meshopt_compression)

// A buffer view whose bytes are decoded from meshoptimizer's stream in another buffer.
struct MeshoptView {
    size_t view = 0, buffer = 0;  // the view, and the buffer of the compressed stream
    uint64_t byteOffset = 0, byteLength = 0, byteStride = 0, count = 0;
    std::string mode,
        filter;  // ATTRIBUTES, TRIANGLES or INDICES; NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL
};

// Whether buffers[buffer] holds no data of its own: a fallback for compressed views, without a uri
// (and not a .glb's BIN chunk).
bool isPlaceholderBuffer(const nlohmann::json& root, const Container& container, size_t buffer);

// The views compressed with EXT_meshopt_compression, after the schema check, each checked against the
// extension's rules (and a view that refers to a placeholder buffer without it refused); throws fp::Error
// "<name>: bufferViews[i].extensions.EXT_meshopt_compression...: <problem>".
std::vector<MeshoptView> meshoptViews(const nlohmann::json& root, const Container& container,
                                      const std::string& name);

// Decodes each view into a buffer of its own, appended to the model, and points the view at it, so that
// accessors and images read the decoded bytes; throws fp::Error naming the view for data that does not
// decode to the view's count and stride.
void decodeMeshoptViews(const std::vector<MeshoptView>& views, tinygltf::Model* model,
                        const std::string& name);

// ---- gltf_tinygltf_input.cpp

// The file as tinygltf 2.7 can read it, and what was taken out of it for that.
struct TinygltfInput {
    std::string bytes;  // the file rewritten, or empty if it is read as it is
    // Each KHR_draco_mesh_compression primitive's indices accessor by (mesh, primitive), taken out of the
    // JSON: tinygltf refuses an indices accessor without a buffer view, as Draco's are.
    std::map<std::pair<size_t, size_t>, int> dracoIndices;
};

// After the schema check: EXT_meshopt_compression's placeholder buffers become one byte in a data URI
// (tinygltf would look for a file, or copy the BIN chunk), and Draco primitives lose their indices.
TinygltfInput tinygltfInput(std::string_view bytes, const Container& container, nlohmann::json root);

// ---- gltf_draco.cpp (KHR_draco_mesh_compression)

// Decodes every primitive with the extension (after meshopt decoding) into accessors of their own, which
// the primitive then names instead (its indices a triangle list of UNSIGNED_INT, each attribute in its
// accessor's component type), and drops the extension from it. `indices` are the primitives' indices
// accessors (TinygltfInput), whose counts must agree. Throws fp::Error naming the primitive for data that
// does not decode or disagrees with the accessors (counts, components, attribute ids missing from the
// Draco data).
void decodeDracoPrimitives(tinygltf::Model* model, const std::map<std::pair<size_t, size_t>, int>& indices,
                           const std::string& name);

// ---- gltf_accessor.cpp

// The number of components of an accessor type (TINYGLTF_TYPE_*): 1 to 4, 4, 9 or 16; 0 if unknown.
int componentCount(int type);

// An accessor's elements, after checking that all of them lie inside its buffer view and buffer.
class AccessorData {
  public:
    // `role` says what the accessor is for, for messages ("POSITION of meshes[0].primitives[1]").
    AccessorData(const tinygltf::Model& model, int accessor, const std::string& role,
                 const std::string& name);

    size_t count() const { return count_; }
    int componentType() const { return componentType_; }
    int components() const { return components_; }
    bool normalized() const { return normalized_; }
    // "accessors[3] (POSITION of meshes[0].primitives[1])", for messages.
    const std::string& label() const { return label_; }

    // Component c of element i as a float: float components as they are, normalized integers as
    // the glTF specification maps them onto [0, 1] or [-1, 1], other integers (KHR_mesh_quantization's
    // positions and texture coordinates) as their value.
    float real(size_t i, int c) const;
    // Element i of an unsigned integer scalar accessor (indices).
    uint32_t index(size_t i) const;

    // Throws fp::Error unless the accessor has this element type and one of these component types.
    void require(int type, std::initializer_list<int> componentTypes, bool normalized,
                 const std::string& what) const;
    // Throws fp::Error unless the accessor has this element type and FLOAT components, or components of
    // one of `normalizedTypes` that are normalized, or of one of `integerTypes` that are not: the
    // choices KHR_mesh_quantization adds for vertex attributes.
    void requireQuantized(int type, std::initializer_list<int> normalizedTypes,
                          std::initializer_list<int> integerTypes, const std::string& what) const;

  private:
    const unsigned char* element(size_t i) const { return first_ + i * stride_; }
    const unsigned char* first_ = nullptr;
    size_t count_ = 0, stride_ = 0;
    int componentType_ = 0, components_ = 0, type_ = 0;
    bool normalized_ = false;
    std::string label_, name_;
};

// The bytes of buffer view `view` (checked against its buffer), e.g. an embedded image.
std::string_view bufferViewBytes(const tinygltf::Model& model, int view, const std::string& name);

// ---- gltf_nodes.cpp

// A mesh placed by a node.
struct MeshInstance {
    int node = -1;
    int mesh = -1;
    glm::dmat4 world{1.0};
};

// What the chosen scene holds: the meshes it places and its first perspective camera's node.
struct SceneGraph {
    std::vector<MeshInstance> instances;
    int cameraNode = -1;  // the node of the first perspective camera in depth-first order, or -1
    glm::dmat4 cameraWorld{1.0};
    // Nodes with a KHR_lights_punctual light: the light's index and the node's world transform.
    std::vector<std::pair<int, glm::dmat4>> lightNodes;
    size_t skinnedNodes = 0;
    size_t orthographicCameras = 0;
};

// The default scene (or the first, or every root node if the file has no scenes), walked depth-first
// after checking that the nodes form trees: a node with two parents, a node that is its own ancestor or
// a scene root that has a parent is an fp::Error. World transforms are in double precision.
SceneGraph walkScene(const tinygltf::Model& model, const std::string& name);

// The node's own transform: its matrix, or translation * rotation * scale.
glm::dmat4 localTransform(const tinygltf::Node& node);
// The matrix of a translation, a unit quaternion (x, y, z, w; normalized if it is not) and a scale,
// applied scale first, as glTF composes a node's TRS.
glm::dmat4 trsTransform(const glm::dvec3& translation, glm::dvec4 rotation, const glm::dvec3& scale);
// EXT_mesh_gpu_instancing: the transform of each instance of node `node`'s mesh, in the node's space
// (T * R * S from its TRANSLATION, ROTATION and SCALE accessors); empty without the extension. Throws
// fp::Error for attributes of other types, different counts or non-finite values.
std::vector<glm::dmat4> gpuInstanceTransforms(const tinygltf::Model& model, int node,
                                              const std::string& name);

// The camera a perspective glTF camera on a node with world transform `world` gives: at the node's
// origin, looking along its -z with +y up, yfov in degrees; the target is on the view axis at the depth
// of `bounds`' centre (so the viewer orbits the model), or the bounds' diagonal ahead when the centre
// is not in front. Throws fp::Error for a camera that cannot form an image (a degenerate transform).
// The KHR_lights_punctual light `index` placed by a node's world transform: the position is the node's
// origin, the direction its -Z axis; colour x intensity in the renderer's units, 1:1 (scene/scene.h
// PunctualLight). Throws fp::Error naming the light for a value the renderer cannot use.
PunctualLight lightFromNode(const tinygltf::Model& model, int index, const glm::dmat4& world,
                            const std::string& name);

Camera cameraFromNode(const tinygltf::Model& model, int node, const glm::dmat4& world, const Aabb& bounds,
                      const std::string& name);

// ---- gltf_mesh.cpp

// What the primitives gave that was skipped or repaired, for one warning per kind.
struct MeshTallies {
    size_t notTriangles = 0;      // primitives of points or lines
    size_t noPositions = 0;       // primitives without POSITION
    size_t morphTargets = 0;      // primitives with morph targets (drawn in their base shape)
    size_t trailingVertices = 0;  // TRIANGLES primitives whose count is not a multiple of 3
    size_t degenerate = 0;        // zero-area triangles dropped
    size_t badNormals = 0;        // corners whose zero-length normal was replaced by the geometric one
};

// At most how many triangles primitive p of a mesh gives, from the count of its indices (or positions),
// once that accessor is known to fit in its buffer; nothing is allocated.
uint64_t triangleBound(const tinygltf::Model& model, int mesh, size_t p, const std::string& name);

class MaterialTable;

// Appends the triangles of primitive `p` of the instance's mesh to scene->triangles, in world space:
// positions transformed by the node's world matrix, normals by its inverse transpose (or the geometric
// normal where the file has none), the winding reversed under a mirroring transform, texture
// coordinates with v flipped, strips and fans as triangles. Points and lines are tallied and skipped.
void appendPrimitive(const tinygltf::Model& model, const MeshInstance& instance, size_t p,
                     MaterialTable& materials, const std::string& name, Scene* scene, MeshTallies* tallies);

// ---- gltf_material.cpp

// The glTF factors a material is mapped from (docs/materials.md, the material table).
struct PbrFactors {
    glm::vec4 baseColor{1.0f};  // rgb: base colour; a: alpha
    float metallic = 1.0f, roughness = 1.0f;
    glm::vec3 emission{0.0f};   // emissiveFactor times KHR_materials_emissive_strength
    float transmission = 0.0f;  // KHR_materials_transmission, times its texture's mean
    std::optional<float> ior;   // KHR_materials_ior
    // KHR_materials_specular: specularFactor * specularColorFactor (times their textures' means).
    glm::vec3 specularColor{1.0f};
    // KHR_materials_volume: -ln(attenuationColor) / attenuationDistance (0: no absorption).
    glm::vec3 absorption{0.0f};
    bool unlit = false;  // KHR_materials_unlit
    // KHR_materials_clearcoat: clearcoatFactor, clearcoatRoughnessFactor (times their textures' means).
    float clearcoat = 0.0f, clearcoatRoughness = 0.0f;
    // KHR_materials_sheen: sheenColorFactor, sheenRoughnessFactor (times their textures' means).
    glm::vec3 sheenColor{0.0f};
    float sheenRoughness = 0.0f;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;  // glTF's default
};

// The mapping rules of the material table (docs/materials.md): Unlit with KHR_materials_unlit, glass
// (Dielectric) where transmission is above 1/2, else the metallic-roughness model; maps are added by
// MaterialTable.
Material materialFromPbr(const PbrFactors& factors, const std::string& name);

// Turns glTF materials into fragpath's, on demand: the first time a primitive uses a material, its
// textures are loaded, it is mapped, and what is ignored is tallied for one warning per kind.
class MaterialTable {
  public:
    MaterialTable(const tinygltf::Model& model, const std::string& name, const GltfLookup& lookup,
                  Scene* scene);
    ~MaterialTable();
    MaterialTable(const MaterialTable&) = delete;
    MaterialTable& operator=(const MaterialTable&) = delete;

    // A texture coordinate slot of a material's maps (Texture::uvSlot): the TEXCOORD set it reads and
    // the KHR_texture_transform its coordinates go through (identity without), in glTF's uv.
    struct UvSlot {
        int set = 0;
        glm::mat3 transform{1.0f};
    };
    // The slots the maps of material `gltfMaterial` (-1: the default material) read: none without
    // maps, at most two (slot k is Texture::uvSlot k).
    const std::vector<UvSlot>& uvSlots(int gltfMaterial);
    // The Scene material for a primitive using `gltfMaterial`; `hasTexcoords` says whether it has every
    // set uvSlots asked for (without, a textured material becomes a copy with its maps' means).
    uint32_t use(int gltfMaterial, bool hasTexcoords);
    // Warns once per kind of what was ignored.
    void reportIgnored() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace fp::gltf
