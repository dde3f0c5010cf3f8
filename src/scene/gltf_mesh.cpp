// glTF primitives to world-space triangles (gltf_internal.h).
#include <cmath>

#include "core/error.h"
#include "scene/gltf_internal.h"
#include "scene/obj_mesh.h"  // kMaxCoordinate
#include "scene/triangulate.h"

namespace fp::gltf {

namespace {

bool isTriangleMode(int mode) {
    return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
           mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

uint64_t trianglesOf(int mode, uint64_t n) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return n / 3;
    return n >= 3 ? n - 2 : 0;
}

// The component types KHR_mesh_quantization allows besides FLOAT: for positions and texture coordinates
// (normalized or not; the node's transform or KHR_texture_transform dequantizes), and for normals and
// tangents (normalized only).
constexpr std::initializer_list<int> kQuantizedTypes = {
    TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
constexpr std::initializer_list<int> kSignedTypes = {TINYGLTF_COMPONENT_TYPE_BYTE,
                                                     TINYGLTF_COMPONENT_TYPE_SHORT};

std::string primitiveName(int mesh, size_t primitive) {
    return "meshes[" + std::to_string(mesh) + "].primitives[" + std::to_string(primitive) + "]";
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

uint64_t triangleBound(const tinygltf::Model& model, int mesh, size_t p, const std::string& name) {
    const tinygltf::Primitive& primitive = model.meshes[size_t(mesh)].primitives[p];
    if (!isTriangleMode(primitive.mode)) return 0;
    std::string where = primitiveName(mesh, p);
    if (primitive.indices >= 0)
        return trianglesOf(primitive.mode,
                           AccessorData(model, primitive.indices, "indices of " + where, name).count());
    auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) return 0;
    return trianglesOf(primitive.mode,
                       AccessorData(model, position->second, "POSITION of " + where, name).count());
}

void appendPrimitive(const tinygltf::Model& model, const MeshInstance& instance, size_t p,
                     MaterialTable& materials, const std::string& name, Scene* scene, MeshTallies* tallies) {
    const tinygltf::Primitive& primitive = model.meshes[size_t(instance.mesh)].primitives[p];
    std::string where = primitiveName(instance.mesh, p);
    if (!isTriangleMode(primitive.mode)) {
        ++tallies->notTriangles;
        return;
    }
    auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) {
        ++tallies->noPositions;
        return;
    }
    if (!primitive.targets.empty()) ++tallies->morphTargets;

    AccessorData positions(model, position->second, "POSITION of " + where, name);
    positions.requireQuantized(TINYGLTF_TYPE_VEC3, kQuantizedTypes, kQuantizedTypes,
                               "VEC3 of FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT");
    size_t vertexCount = positions.count();
    auto sameCount = [&](const AccessorData& a) {
        if (a.count() != vertexCount)
            throw Error(name + ": " + a.label() + " has " + std::to_string(a.count()) +
                        " elements, but POSITION has " + std::to_string(vertexCount) +
                        " (all attributes of a primitive have one per vertex)");
    };

    // The vertices in world space, in double, then stored as the renderer will keep them (float).
    const glm::dmat4& world = instance.world;
    glm::dmat3 linear(world);
    glm::dmat3 normalMatrix = glm::transpose(glm::inverse(linear));
    bool flip = glm::determinant(linear) < 0.0;  // a mirroring transform turns front faces into back faces
    std::vector<glm::vec3> p3(vertexCount);
    for (size_t i = 0; i < vertexCount; ++i) {
        glm::dvec3 local(positions.real(i, 0), positions.real(i, 1), positions.real(i, 2));
        if (!finite(local))
            throw Error(name + ": " + positions.label() + " holds a non-finite value (element " +
                        std::to_string(i) + ")");
        glm::dvec3 w(world * glm::dvec4(local, 1.0));
        glm::vec3 stored(w);
        glm::dvec3 back(stored);
        if (!finite(back) ||
            std::max({std::abs(back.x), std::abs(back.y), std::abs(back.z)}) > kMaxCoordinate)
            throw Error(name + ": vertex " + std::to_string(i) + " of " + where +
                        " lies beyond +-1e18 (or at infinity) "
                        "once placed by nodes[" +
                        std::to_string(instance.node) + "]");
        p3[i] = stored;
    }

    std::vector<glm::vec3> normals;
    auto normal = primitive.attributes.find("NORMAL");
    if (normal != primitive.attributes.end()) {
        AccessorData data(model, normal->second, "NORMAL of " + where, name);
        data.requireQuantized(TINYGLTF_TYPE_VEC3, kSignedTypes, {},
                              "VEC3 of FLOAT, or of normalized BYTE or SHORT");
        sameCount(data);
        normals.resize(vertexCount);
        for (size_t i = 0; i < vertexCount; ++i) {
            glm::dvec3 n(data.real(i, 0), data.real(i, 1), data.real(i, 2));
            if (!finite(n))
                throw Error(name + ": " + data.label() + " holds a non-finite value (element " +
                            std::to_string(i) + ")");
            if (!unitVector(normalMatrix * n, &normals[i]))
                normals[i] = glm::vec3(0.0f);  // replaced per triangle
        }
    }

    // Each uv slot of the material (at most two: Texture::uvSlot): its TEXCOORD set through its
    // KHR_texture_transform.
    const std::vector<MaterialTable::UvSlot>& slots = materials.uvSlots(primitive.material);
    std::vector<glm::vec2> uv[2];
    bool hasTexcoords = true;
    for (size_t k = 0; k < slots.size(); ++k) {
        std::string set = "TEXCOORD_" + std::to_string(slots[k].set);
        auto texcoord = primitive.attributes.find(set);
        if (texcoord == primitive.attributes.end()) {
            hasTexcoords = false;
            continue;
        }
        AccessorData data(model, texcoord->second, set + " of " + where, name);
        data.requireQuantized(TINYGLTF_TYPE_VEC2, kQuantizedTypes, kQuantizedTypes,
                              "VEC2 of FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT");
        sameCount(data);
        uv[k].resize(vertexCount);
        for (size_t i = 0; i < vertexCount; ++i) {
            float u = data.real(i, 0), v = data.real(i, 1);
            if (!std::isfinite(u) || !std::isfinite(v))
                throw Error(name + ": " + data.label() + " holds a non-finite value (element " +
                            std::to_string(i) + ")");
            glm::vec3 t = slots[k].transform * glm::vec3(u, v, 1.0f);
            if (!std::isfinite(t.x) || !std::isfinite(t.y))
                throw Error(name + ": " + data.label() + " element " + std::to_string(i) +
                            " leaves the float range through its material's KHR_texture_transform");
            // glTF's v = 0 is the top row of the image, ours the bottom.
            uv[k][i] = glm::vec2(t.x, 1.0f - t.y);
        }
    }
    if (!hasTexcoords) {  // the material's copy without maps (MaterialTable::use) needs none
        uv[0].clear();
        uv[1].clear();
    }
    uint32_t material = materials.use(primitive.material, hasTexcoords);

    // COLOR_0 multiplies the base colour and alpha (glTF 2.0, 3.7.2.1): RGB (alpha 1) or RGBA, of float or
    // normalized unsigned byte or short.
    std::vector<glm::vec4> colors;
    auto color = primitive.attributes.find("COLOR_0");
    if (color != primitive.attributes.end()) {
        AccessorData data(model, color->second, "COLOR_0 of " + where, name);
        data.require(data.components() == 4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3,
                     {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                     true, "VEC3 or VEC4 of FLOAT, or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT");
        sameCount(data);
        colors.resize(vertexCount);
        const bool rgba = data.components() == 4;  // VEC3: alpha 1
        for (size_t i = 0; i < vertexCount; ++i) {
            glm::vec4 c(data.real(i, 0), data.real(i, 1), data.real(i, 2), rgba ? data.real(i, 3) : 1.0);
            if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) || !std::isfinite(c.w))
                throw Error(name + ": " + data.label() + " holds a non-finite value (element " +
                            std::to_string(i) + ")");
            colors[i] = glm::clamp(c, glm::vec4(0.0f), glm::vec4(1.0f));
        }
    }

    // TANGENT (xyz the direction of increasing u, w the bitangent's sign), for a normal map: in world
    // space by the linear part, w turned with a mirroring transform (cross(M n, M t) = det(M) M cross(n,
    // t) for orthogonal M). glTF's bitangent points up the image, as ours (increasing v once flipped)
    // does, so w is taken as it is. Without it, or with a zero-length or non-finite one, the packer
    // computes each triangle's own.
    std::vector<glm::vec4> tangents;
    auto tangent = primitive.attributes.find("TANGENT");
    if (tangent != primitive.attributes.end() && scene->materials[material].normalTexture >= 0) {
        AccessorData data(model, tangent->second, "TANGENT of " + where, name);
        data.requireQuantized(TINYGLTF_TYPE_VEC4, kSignedTypes, {},
                              "VEC4 of FLOAT, or of normalized BYTE or SHORT");
        sameCount(data);
        tangents.resize(vertexCount);
        for (size_t i = 0; i < vertexCount; ++i) {
            glm::dvec3 t(data.real(i, 0), data.real(i, 1), data.real(i, 2));
            double w = data.real(i, 3);
            glm::vec3 unit;
            if (finite(t) && std::isfinite(w) && unitVector(linear * t, &unit))
                tangents[i] = glm::vec4(unit, (w < 0.0) != flip ? -1.0f : 1.0f);
        }
    }

    std::optional<AccessorData> indices;
    if (primitive.indices >= 0) {
        indices.emplace(model, primitive.indices, "indices of " + where, name);
        indices->require(TINYGLTF_TYPE_SCALAR,
                         {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                         false, "SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    }
    size_t n = indices ? indices->count() : vertexCount;
    auto vertex = [&](size_t k) -> size_t {
        if (!indices) return k;
        uint32_t v = indices->index(k);
        if (v >= vertexCount)
            throw Error(name + ": " + indices->label() + " holds index " + std::to_string(v) + " (element " +
                        std::to_string(k) + "), beyond the " + std::to_string(vertexCount) +
                        " vertices of POSITION");
        return v;
    };
    if (primitive.mode == TINYGLTF_MODE_TRIANGLES && n % 3 != 0) ++tallies->trailingVertices;

    uint64_t count = trianglesOf(primitive.mode, n);
    for (uint64_t t = 0; t < count; ++t) {
        size_t corner[3];
        if (primitive.mode == TINYGLTF_MODE_TRIANGLES) {
            for (int k = 0; k < 3; ++k) corner[k] = vertex(size_t(3 * t) + size_t(k));
        } else if (primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // The glTF specification's order, which keeps every triangle's winding the strip's.
            corner[0] = vertex(size_t(t));
            corner[1] = vertex(size_t(t + 1 + t % 2));
            corner[2] = vertex(size_t(t + 2 - t % 2));
        } else {  // fan
            corner[0] = vertex(size_t(t + 1));
            corner[1] = vertex(size_t(t + 2));
            corner[2] = vertex(0);
        }
        // Repeated vertices join strips and fans on purpose: not worth a warning.
        if (primitive.mode != TINYGLTF_MODE_TRIANGLES &&
            (corner[0] == corner[1] || corner[1] == corner[2] || corner[0] == corner[2]))
            continue;
        if (flip) std::swap(corner[1], corner[2]);

        Triangle tri;
        for (int k = 0; k < 3; ++k) tri.p[k] = p3[corner[k]];
        glm::dvec3 q0(tri.p[0]), q1(tri.p[1]), q2(tri.p[2]);
        glm::vec3 geometric;
        if (isDegenerate(q0, q1, q2) || !unitVector(glm::cross(q1 - q0, q2 - q0), &geometric)) {
            ++tallies->degenerate;
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            tri.n[k] = geometric;  // without normals: the geometric normal
            if (!normals.empty()) {
                if (normals[corner[k]] == glm::vec3(0.0f))
                    ++tallies->badNormals;
                else
                    tri.n[k] = normals[corner[k]];
            }
            if (!uv[0].empty()) tri.uv[k] = uv[0][corner[k]];
        }
        tri.material = material;
        if (!tangents.empty()) {
            // Earlier triangles without tangents get triples of w = 0: computed when packing.
            scene->tangents.resize(scene->triangles.size());
            scene->tangents.push_back({tangents[corner[0]], tangents[corner[1]], tangents[corner[2]]});
        } else if (!scene->tangents.empty()) {
            scene->tangents.emplace_back();
        }
        // The optional per-triangle arrays: earlier triangles get the neutral value (scene.h).
        auto extra = [&](auto& perTriangle, const auto& perVertex, auto neutral) {
            if (perVertex.empty() && perTriangle.empty()) return;
            perTriangle.resize(scene->triangles.size(), {neutral, neutral, neutral});
            if (perVertex.empty())
                perTriangle.push_back({neutral, neutral, neutral});
            else
                perTriangle.push_back({perVertex[corner[0]], perVertex[corner[1]], perVertex[corner[2]]});
        };
        extra(scene->texcoords1, uv[1], glm::vec2(0.0f));
        extra(scene->colors, colors, glm::vec4(1.0f));
        scene->triangles.push_back(tri);
    }
}

}  // namespace fp::gltf
