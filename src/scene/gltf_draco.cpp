// KHR_draco_mesh_compression: primitives whose attributes and indices are a Draco mesh in a buffer view,
// decoded by libdraco (Debian's, 1.5.5) into plain accessors before the meshes are read
// (gltf_internal.h).
#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include "core/error.h"
#include "scene/gltf_internal.h"

namespace fp::gltf {

namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";

// The new buffer the decoded arrays go to, with a view and an accessor each.
class DecodedArrays {
  public:
    explicit DecodedArrays(tinygltf::Model* model) : model_(model) {}

    // An accessor like `like` (its type, component type and normalization) over `bytes`.
    int add(const std::vector<unsigned char>& bytes, tinygltf::Accessor like, size_t count) {
        while (data_.size() % 4) data_.push_back(0);
        tinygltf::BufferView view;
        view.buffer = int(model_->buffers.size());  // the buffer finish() appends
        view.byteOffset = data_.size();
        view.byteLength = bytes.size();
        data_.insert(data_.end(), bytes.begin(), bytes.end());
        model_->bufferViews.push_back(view);
        like.bufferView = int(model_->bufferViews.size()) - 1;
        like.byteOffset = 0;
        like.count = count;
        like.sparse = {};
        model_->accessors.push_back(like);
        return int(model_->accessors.size()) - 1;
    }

    void finish() {
        tinygltf::Buffer buffer;
        buffer.data = std::move(data_);
        model_->buffers.push_back(std::move(buffer));
    }

  private:
    tinygltf::Model* model_;
    std::vector<unsigned char> data_;
};

// Point i's components of `attribute` converted to T (Draco maps normalized integers onto floats as glTF
// does), as bytes.
template <typename T>
bool convert(const draco::PointAttribute& attribute, size_t points, int components,
             std::vector<unsigned char>* out) {
    out->resize(points * size_t(components) * sizeof(T));
    T* values = reinterpret_cast<T*>(out->data());
    for (size_t i = 0; i < points; ++i) {
        draco::AttributeValueIndex value = attribute.mapped_index(draco::PointIndex(uint32_t(i)));
        if (value.value() >= attribute.size() ||
            !attribute.ConvertValue<T>(value, int8_t(components), values + i * size_t(components)))
            return false;
    }
    return true;
}

bool convertTo(int componentType, const draco::PointAttribute& attribute, size_t points, int components,
               std::vector<unsigned char>* out) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return convert<float>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return convert<int8_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return convert<uint8_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return convert<int16_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return convert<uint16_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return convert<uint32_t>(attribute, points, components, out);
        default:
            return false;
    }
}

void decodePrimitive(tinygltf::Model* model, int meshIndex, size_t p, int indicesAccessor,
                     const std::string& name) {
    tinygltf::Primitive& primitive = model->meshes[size_t(meshIndex)].primitives[p];
    const tinygltf::Value& extension = primitive.extensions.at(kExtension);
    std::string where = "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(p) + "] (" +
                        kExtension + ")";
    auto fail = [&](const std::string& problem) { throw Error(name + ": " + where + ": " + problem); };
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP)
        fail("mode " + std::to_string(primitive.mode) +
             " is not TRIANGLES or TRIANGLE_STRIP, which Draco requires");
    int view = extension.Get("bufferView").GetNumberAsInt();  // checked by the schema check
    std::string_view bytes = bufferViewBytes(*model, view, name);

    draco::DecoderBuffer buffer;
    buffer.Init(bytes.data(), bytes.size());
    auto geometry = draco::Decoder::GetEncodedGeometryType(&buffer);
    if (!geometry.ok())
        fail("bufferViews[" + std::to_string(view) + "] is not Draco data (" +
             geometry.status().error_msg_string() + ")");
    if (geometry.value() != draco::TRIANGULAR_MESH)
        fail("bufferViews[" + std::to_string(view) + "] holds a Draco point cloud, not a triangle mesh");
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok())
        fail("bufferViews[" + std::to_string(view) +
             "] does not decode (Draco: " + decoded.status().error_msg_string() + ")");
    const draco::Mesh& mesh = *decoded.value();
    size_t points = mesh.num_points(), faces = mesh.num_faces();
    if (faces == 0) fail("the Draco data in bufferViews[" + std::to_string(view) + "] has no triangles");
    if (faces > kMaxTriangles)
        fail("its " + std::to_string(faces) + " triangles are more than the renderer takes");

    DecodedArrays arrays(model);
    const tinygltf::Value& ids = extension.Get("attributes");
    for (const std::string& semantic : ids.Keys()) {
        auto used = primitive.attributes.find(semantic);
        if (used == primitive.attributes.end()) continue;  // the extension's attributes must be a subset
        int id = ids.Get(semantic).GetNumberAsInt();       // in [0, 2^31) by the schema check
        const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(uint32_t(id));
        if (!attribute)
            fail("attribute id " + std::to_string(id) + " (" + semantic +
                 ") is not in the Draco data (which has " + std::to_string(mesh.num_attributes()) +
                 " attributes)");
        const tinygltf::Accessor& accessor = model->accessors.at(size_t(used->second));
        std::string label = "accessors[" + std::to_string(used->second) + "] (" + semantic + ")";
        if (accessor.count != points)
            fail(label + " has " + std::to_string(accessor.count) + " elements, but the Draco data has " +
                 std::to_string(points) + " points");
        int components = componentCount(accessor.type);
        if (components == 0 || components != attribute->num_components())
            fail(label + " has " + std::to_string(components) + " components, but Draco attribute " +
                 std::to_string(id) + " has " + std::to_string(int(attribute->num_components())));
        if (!attribute->is_mapping_identity() && attribute->indices_map_size() < points)
            fail("Draco attribute " + std::to_string(id) + " maps fewer than its " + std::to_string(points) +
                 " points");
        std::vector<unsigned char> values;
        if (!convertTo(accessor.componentType, *attribute, points, components, &values))
            fail("Draco attribute " + std::to_string(id) + " (" + semantic +
                 ") does not convert to the component type of " + label);
        used->second = arrays.add(values, accessor, points);
    }

    // The faces, as a triangle list whatever the mode was (Draco decodes strips to triangles).
    if (primitive.mode == TINYGLTF_MODE_TRIANGLES && indicesAccessor >= 0 &&
        model->accessors.at(size_t(indicesAccessor)).count != 3 * faces)
        fail("accessors[" + std::to_string(indicesAccessor) + "] (indices) has " +
             std::to_string(model->accessors[size_t(indicesAccessor)].count) +
             " elements, but the Draco data has " + std::to_string(faces) + " triangles");
    std::vector<unsigned char> indices(3 * faces * sizeof(uint32_t));
    uint32_t* corners = reinterpret_cast<uint32_t*>(indices.data());
    for (size_t f = 0; f < faces; ++f)
        for (size_t k = 0; k < 3; ++k)
            corners[3 * f + k] = mesh.face(draco::FaceIndex(uint32_t(f)))[k].value();
    tinygltf::Accessor indexAccessor;
    indexAccessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    indexAccessor.type = TINYGLTF_TYPE_SCALAR;
    primitive.indices = arrays.add(indices, indexAccessor, 3 * faces);
    arrays.finish();
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.extensions.erase(kExtension);
}

}  // namespace

void decodeDracoPrimitives(tinygltf::Model* model, const std::map<std::pair<size_t, size_t>, int>& indices,
                           const std::string& name) {
    for (size_t m = 0; m < model->meshes.size(); ++m)
        for (size_t p = 0; p < model->meshes[m].primitives.size(); ++p)
            if (model->meshes[m].primitives[p].extensions.count(kExtension)) {
                auto it = indices.find({m, p});
                decodePrimitive(model, int(m), p, it == indices.end() ? -1 : it->second, name);
            }
}

}  // namespace fp::gltf
