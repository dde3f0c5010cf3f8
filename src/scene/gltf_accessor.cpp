// Bounds-checked reading of glTF accessors (gltf_internal.h). Every byte range is checked against the
// data tinygltf actually holds before anything is read or allocated, with overflow-free arithmetic: a
// count of 2^60 elements is refused here, not by the allocator.
#include <algorithm>
#include <cstring>

#include "core/error.h"
#include "scene/gltf_internal.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "glTF data is little-endian and read as it is");

namespace fp::gltf {

namespace {

int componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

const char* componentName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return "FLOAT";
        default:
            return "an unknown component type";
    }
}

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        case TINYGLTF_TYPE_MAT2:
            return "MAT2";
        case TINYGLTF_TYPE_MAT3:
            return "MAT3";
        case TINYGLTF_TYPE_MAT4:
            return "MAT4";
        default:
            return "an unknown type";
    }
}

// A BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT or UNSIGNED_INT component's value.
int64_t integer(const unsigned char* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return int8_t(*p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return *p;
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t s;
            std::memcpy(&s, p, 2);
            return s;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t u;
            std::memcpy(&u, p, 2);
            return u;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t u;
            std::memcpy(&u, p, 4);
            return u;
        }
        default:
            return 0;
    }
}

// The buffer view's bytes, checked against the buffer tinygltf loaded.
const tinygltf::BufferView& checkedView(const tinygltf::Model& model, int view, const std::string& who,
                                        const std::string& name) {
    if (view < 0 || size_t(view) >= model.bufferViews.size())
        throw Error(name + ": " + who + " refers to bufferViews[" + std::to_string(view) +
                    "], which does not exist");
    const tinygltf::BufferView& v = model.bufferViews[size_t(view)];
    if (v.buffer < 0 || size_t(v.buffer) >= model.buffers.size())
        throw Error(name + ": bufferViews[" + std::to_string(view) + "] refers to buffers[" +
                    std::to_string(v.buffer) + "], which does not exist");
    size_t size = model.buffers[size_t(v.buffer)].data.size();
    if (v.byteOffset > size || v.byteLength > size - v.byteOffset)
        throw Error(name + ": bufferViews[" + std::to_string(view) + "] (bytes " +
                    std::to_string(v.byteOffset) + " and " + std::to_string(v.byteLength) +
                    " more) lies beyond the end of buffers[" + std::to_string(v.buffer) + "] (" +
                    std::to_string(size) + " bytes)");
    return v;
}

}  // namespace

int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        case TINYGLTF_TYPE_MAT2:
            return 4;
        case TINYGLTF_TYPE_MAT3:
            return 9;
        case TINYGLTF_TYPE_MAT4:
            return 16;
        default:
            return 0;
    }
}

AccessorData::AccessorData(const tinygltf::Model& model, int accessor, const std::string& role,
                           const std::string& name) {
    label_ = "accessors[" + std::to_string(accessor) + "] (" + role + ")";
    name_ = name;
    auto fail = [&](const std::string& problem) { throw Error(name + ": " + label_ + " " + problem); };
    if (accessor < 0 || size_t(accessor) >= model.accessors.size()) fail("does not exist");
    const tinygltf::Accessor& a = model.accessors[size_t(accessor)];
    if (a.sparse.isSparse) fail("is sparse; sparse accessors are not supported");
    if (a.bufferView < 0)
        fail(
            "has no bufferView (its data would be all zeros, or come from an extension fragpath does not "
            "read)");
    components_ = componentCount(a.type);
    int size = componentSize(a.componentType);
    if (components_ == 0 || size == 0) fail("has an unsupported type or component type");
    componentType_ = a.componentType;
    type_ = a.type;
    normalized_ = a.normalized;
    count_ = a.count;
    if (count_ == 0) fail("has no elements");

    const tinygltf::BufferView& view = checkedView(model, a.bufferView, label_, name);
    size_t elementSize = size_t(components_) * size_t(size);
    stride_ = view.byteStride ? view.byteStride : elementSize;
    if (stride_ < elementSize)
        fail("has elements of " + std::to_string(elementSize) +
             " bytes, more than its buffer view's byteStride " + std::to_string(stride_));
    // Element i occupies [byteOffset + i * stride, + elementSize) inside the view: check the last one
    // without forming count * stride, which can overflow.
    bool fits = a.byteOffset <= view.byteLength && elementSize <= view.byteLength - a.byteOffset &&
                count_ - 1 <= (view.byteLength - a.byteOffset - elementSize) / stride_;
    if (!fits)
        fail("needs " + std::to_string(count_) + " elements of " + std::to_string(elementSize) +
             " bytes, every " + std::to_string(stride_) + " bytes from byte " + std::to_string(a.byteOffset) +
             ", more than the " + std::to_string(view.byteLength) + " bytes of bufferViews[" +
             std::to_string(a.bufferView) + "]");
    first_ = model.buffers[size_t(view.buffer)].data.data() + view.byteOffset + a.byteOffset;
}

void AccessorData::require(int type, std::initializer_list<int> componentTypes, bool normalized,
                           const std::string& what) const {
    bool typeOk = type_ == type;
    bool componentOk = false;
    for (int ct : componentTypes) componentOk = componentOk || ct == componentType_;
    // Floats are never "normalized"; integers must be when they stand for fractions.
    bool normalizedOk =
        componentType_ == TINYGLTF_COMPONENT_TYPE_FLOAT ? !normalized_ : normalized_ == normalized;
    if (!typeOk || !componentOk || !normalizedOk)
        throw Error(name_ + ": " + label_ + " must be " + what + ", got " + typeName(type_) + " of " +
                    (normalized_ ? "normalized " : "") + componentName(componentType_));
}

void AccessorData::requireQuantized(int type, std::initializer_list<int> normalizedTypes,
                                    std::initializer_list<int> integerTypes, const std::string& what) const {
    bool componentOk = componentType_ == TINYGLTF_COMPONENT_TYPE_FLOAT && !normalized_;
    for (int ct : normalized_ ? normalizedTypes : integerTypes)
        componentOk = componentOk || ct == componentType_;
    if (type_ != type || !componentOk)
        throw Error(name_ + ": " + label_ + " must be " + what + ", got " + typeName(type_) + " of " +
                    (normalized_ ? "normalized " : "") + componentName(componentType_));
}

float AccessorData::real(size_t i, int c) const {
    const unsigned char* p = element(i) + size_t(c) * size_t(componentSize(componentType_));
    if (componentType_ == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        float f;
        std::memcpy(&f, p, 4);
        return f;
    }
    float value = float(integer(p, componentType_));
    if (!normalized_) return value;
    switch (componentType_) {  // the glTF specification's mapping of normalized integers
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return value / 255.0f;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return value / 65535.0f;
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return std::max(value / 127.0f, -1.0f);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return std::max(value / 32767.0f, -1.0f);
        default:
            return 0.0f;  // unsigned int is never a fraction; require() refuses it first
    }
}

uint32_t AccessorData::index(size_t i) const {
    return uint32_t(integer(element(i), componentType_));  // require() admits unsigned types only
}

std::string_view bufferViewBytes(const tinygltf::Model& model, int view, const std::string& name) {
    const tinygltf::BufferView& v = checkedView(model, view, "an image", name);
    const std::vector<unsigned char>& data = model.buffers[size_t(v.buffer)].data;
    return std::string_view(reinterpret_cast<const char*>(data.data()) + v.byteOffset, v.byteLength);
}

}  // namespace fp::gltf
