// The glTF node forest: checks, world transforms, the camera (gltf_internal.h).
#include <algorithm>
#include <cmath>
#include <optional>

#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/log.h"
#include "scene/gltf_internal.h"
#include "scene/punctual_light.h"

namespace fp::gltf {

namespace {

std::string nodeName(int i) {
    return "nodes[" + std::to_string(i) + "]";
}

bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// Each node's parent (-1 for roots), after checking that the children lists form trees: no node is a
// child twice, none is its own ancestor.
std::vector<int> parents(const tinygltf::Model& model, const std::string& name) {
    size_t n = model.nodes.size();
    std::vector<int> parent(n, -1);
    for (size_t i = 0; i < n; ++i)
        for (int c : model.nodes[i].children) {
            if (c < 0 || size_t(c) >= n)
                throw Error(name + ": " + nodeName(int(i)) + " has a child " + nodeName(c) +
                            ", which does not exist");
            if (size_t(c) == i)
                throw Error(name + ": " + nodeName(c) +
                            " is its own ancestor (it lists itself among its children)");
            if (parent[size_t(c)] >= 0)
                throw Error(name + ": " + nodeName(c) + " is a child of both " + nodeName(parent[size_t(c)]) +
                            " and " + nodeName(int(i)) + " (glTF nodes form trees: one parent each)");
            parent[size_t(c)] = int(i);
        }
    // With one parent each, a cycle is a parent chain that comes back to itself. Each node is walked
    // once: 1 marks the chain being walked, 2 nodes already known to lead to a root.
    std::vector<uint8_t> state(n, 0);
    std::vector<int> chain;
    for (size_t i = 0; i < n; ++i) {
        chain.clear();
        int j = int(i);
        while (j >= 0 && state[size_t(j)] == 0) {
            state[size_t(j)] = 1;
            chain.push_back(j);
            j = parent[size_t(j)];
        }
        if (j >= 0 && state[size_t(j)] == 1) {
            auto start = std::find(chain.begin(), chain.end(), j);
            std::string cycle;
            size_t shown = 0;
            for (auto it = start; it != chain.end() && shown < 8; ++it, ++shown)
                cycle += std::to_string(*it) + " -> ";
            if (size_t(chain.end() - start) > shown) cycle += "... -> ";
            throw Error(name + ": " + nodeName(j) + " is its own ancestor (parent chain " + cycle +
                        std::to_string(j) + "); glTF nodes form trees");
        }
        for (int c : chain) state[size_t(c)] = 2;
    }
    return parent;
}

}  // namespace

glm::dmat4 trsTransform(const glm::dvec3& translation, glm::dvec4 rotation, const glm::dvec3& scale) {
    glm::dmat4 t(1.0), r(1.0);
    t[3] = glm::dvec4(translation, 1.0);
    // The unit quaternion (x, y, z, w) as a rotation matrix (m[column][row]).
    double length = glm::length(rotation);
    if (length != 1.0) rotation /= length;
    double x = rotation.x, y = rotation.y, z = rotation.z, w = rotation.w;
    r[0] = glm::dvec4(1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0);
    r[1] = glm::dvec4(2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0);
    r[2] = glm::dvec4(2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0);
    return t * r * glm::scale(glm::dmat4(1.0), scale);
}

glm::dmat4 localTransform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glm
    glm::dvec3 t(0.0), s(1.0);
    glm::dvec4 q(0.0, 0.0, 0.0, 1.0);
    if (node.translation.size() == 3)
        t = glm::dvec3(node.translation[0], node.translation[1], node.translation[2]);
    if (node.rotation.size() == 4)
        q = glm::dvec4(node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]);
    if (node.scale.size() == 3) s = glm::dvec3(node.scale[0], node.scale[1], node.scale[2]);
    return trsTransform(t, q, s);
}

std::vector<glm::dmat4> gpuInstanceTransforms(const tinygltf::Model& model, int node,
                                              const std::string& name) {
    auto it = model.nodes[size_t(node)].extensions.find("EXT_mesh_gpu_instancing");
    if (it == model.nodes[size_t(node)].extensions.end()) return {};
    const std::string where = nodeName(node) + ".extensions.EXT_mesh_gpu_instancing";
    if (!it->second.IsObject() || !it->second.Has("attributes") || !it->second.Get("attributes").IsObject())
        throw Error(name + ": " + where + " names none of TRANSLATION, ROTATION and SCALE in its attributes");
    const tinygltf::Value& attributes = it->second.Get("attributes");
    // The extension's three attributes, each optional; every one present has one element per instance.
    struct Attribute {
        const char* key;
        int type;
        std::optional<AccessorData> data;
    } trs[3] = {{"TRANSLATION", TINYGLTF_TYPE_VEC3, {}},
                {"ROTATION", TINYGLTF_TYPE_VEC4, {}},
                {"SCALE", TINYGLTF_TYPE_VEC3, {}}};
    std::optional<size_t> count;
    for (Attribute& a : trs) {
        if (!attributes.Has(a.key)) continue;
        const tinygltf::Value& index = attributes.Get(a.key);
        if (!index.IsInt())
            throw Error(name + ": " + where + ".attributes." + a.key + " must be an accessor index");
        a.data.emplace(model, index.GetNumberAsInt(), std::string(a.key) + " of " + where, name);
        // The extension's component types: floats, and for ROTATION normalized BYTE or SHORT too.
        if (a.type == TINYGLTF_TYPE_VEC4)
            a.data->requireQuantized(a.type, {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT},
                                     {}, "VEC4 of FLOAT, or of normalized BYTE or SHORT");
        else
            a.data->require(a.type, {TINYGLTF_COMPONENT_TYPE_FLOAT}, false, "VEC3 of FLOAT");
        if (count && *count != a.data->count())
            throw Error(name + ": " + where + "'s attributes hold different numbers of instances (" +
                        std::to_string(*count) + " and " + std::to_string(a.data->count()) + ")");
        count = a.data->count();
    }
    if (!count)
        throw Error(name + ": " + where + " names none of TRANSLATION, ROTATION and SCALE in its attributes");
    std::vector<glm::dmat4> transforms(*count);
    for (size_t i = 0; i < *count; ++i) {
        auto vec = [&](const Attribute& a, glm::dvec4 fallback) {
            if (!a.data) return fallback;
            for (int c = 0; c < a.data->components(); ++c) fallback[c] = a.data->real(i, c);
            return fallback;
        };
        glm::dvec4 t = vec(trs[0], glm::dvec4(0.0)), q = vec(trs[1], glm::dvec4(0.0, 0.0, 0.0, 1.0)),
                   s = vec(trs[2], glm::dvec4(1.0));
        transforms[i] = trsTransform(glm::dvec3(t), q, glm::dvec3(s));
        if (!finite(transforms[i]))
            throw Error(name + ": " + where + " instance " + std::to_string(i) +
                        " has a non-finite transform");
    }
    return transforms;
}

SceneGraph walkScene(const tinygltf::Model& model, const std::string& name) {
    std::vector<int> parent = parents(model, name);
    std::vector<int> roots;
    std::string listedBy;
    if (!model.scenes.empty()) {
        int chosen = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (size_t(chosen) >= model.scenes.size())
            throw Error(name + ": scene " + std::to_string(chosen) + " does not exist");
        roots = model.scenes[size_t(chosen)].nodes;
        listedBy = "scenes[" + std::to_string(chosen) + "].nodes";
    } else {
        for (size_t i = 0; i < parent.size(); ++i)
            if (parent[i] < 0) roots.push_back(int(i));
        if (!roots.empty())
            warn(name + ": no scenes; rendering all " + std::to_string(roots.size()) + " root nodes");
    }
    for (int r : roots) {
        if (r < 0 || size_t(r) >= parent.size())
            throw Error(name + ": " + listedBy + " lists " + nodeName(r) + ", which does not exist");
        if (parent[size_t(r)] >= 0)
            throw Error(name + ": " + listedBy + " lists " + nodeName(r) + ", which is a child of " +
                        nodeName(parent[size_t(r)]) + " (a scene lists root nodes)");
    }

    SceneGraph graph;
    std::vector<uint8_t> visited(parent.size(), 0);
    std::vector<std::pair<int, glm::dmat4>> stack;  // depth-first, children in their listed order
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, glm::dmat4(1.0));
    while (!stack.empty()) {
        auto [i, parentWorld] = stack.back();
        stack.pop_back();
        if (visited[size_t(i)]) throw Error(name + ": " + listedBy + " lists " + nodeName(i) + " twice");
        visited[size_t(i)] = 1;
        const tinygltf::Node& node = model.nodes[size_t(i)];
        glm::dmat4 world = parentWorld * localTransform(node);
        if (!finite(world))
            throw Error(name + ": the transform of " + nodeName(i) + " (with its ancestors') is not finite");
        if (node.mesh >= 0) {
            // EXT_mesh_gpu_instancing: the mesh once for each instance, each transform in the node's
            // space (the node's own placement is then not drawn by itself).
            std::vector<glm::dmat4> instances = gpuInstanceTransforms(model, i, name);
            if (instances.empty()) graph.instances.push_back({i, node.mesh, world});
            for (const glm::dmat4& instance : instances)
                graph.instances.push_back({i, node.mesh, world * instance});
        }
        if (node.camera >= 0 && size_t(node.camera) < model.cameras.size()) {
            if (model.cameras[size_t(node.camera)].type == "perspective") {
                if (graph.cameraNode < 0) {
                    graph.cameraNode = i;
                    graph.cameraWorld = world;
                }
            } else {
                ++graph.orthographicCameras;
            }
        }
        if (node.skin >= 0) ++graph.skinnedNodes;
        auto light = node.extensions.find("KHR_lights_punctual");
        if (light != node.extensions.end() && light->second.Has("light"))
            graph.lightNodes.emplace_back(light->second.Get("light").GetNumberAsInt(), world);
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) stack.emplace_back(*c, world);
    }
    return graph;
}

PunctualLight lightFromNode(const tinygltf::Model& model, int index, const glm::dmat4& world,
                            const std::string& name) {
    const std::string where = name + ": KHR_lights_punctual light " + std::to_string(index);
    if (index < 0 || size_t(index) >= model.lights.size()) throw Error(where + " does not exist");
    const tinygltf::Light& gl = model.lights[size_t(index)];
    PunctualLight light;
    light.name = gl.name;
    if (gl.type == "point") {
        light.type = PunctualLightType::Point;
    } else if (gl.type == "spot") {
        light.type = PunctualLightType::Spot;
    } else if (gl.type == "directional") {
        light.type = PunctualLightType::Directional;
    } else {
        throw Error(where + ": unknown type '" + gl.type + "' (point, spot or directional)");
    }
    glm::dvec3 color(1.0);
    if (gl.color.size() == 3) color = glm::dvec3(gl.color[0], gl.color[1], gl.color[2]);
    light.intensity = glm::vec3(color * gl.intensity);
    light.position = glm::vec3(world[3]);
    glm::dvec3 direction = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0);
    double length = glm::length(direction);
    if (!(length > 0.0) || !std::isfinite(length))
        throw Error(where + ": its node's transform collapses the light's direction (a zero scale?)");
    light.direction = glm::vec3(direction / length);
    light.innerConeAngle = float(gl.spot.innerConeAngle);
    light.outerConeAngle = float(gl.spot.outerConeAngle);
    validatePunctualLight(light, where);
    return light;
}

Camera cameraFromNode(const tinygltf::Model& model, int node, const glm::dmat4& world, const Aabb& bounds,
                      const std::string& name) {
    int index = model.nodes[size_t(node)].camera;
    const tinygltf::Camera& glCamera = model.cameras[size_t(index)];
    std::string where =
        name + ": the camera of " + nodeName(node) + " (cameras[" + std::to_string(index) + "])";
    double yfov = glCamera.perspective.yfov;
    constexpr double kPi = 3.14159265358979323846;
    if (!(yfov > 0.0 && yfov < kPi))
        throw Error(where + ": yfov must be in (0, pi) radians, got " + std::to_string(yfov));
    glm::dvec3 eye(world[3]);
    glm::dmat3 basis(world);
    glm::dvec3 forward = basis * glm::dvec3(0.0, 0.0, -1.0), up = basis * glm::dvec3(0.0, 1.0, 0.0);
    double forwardLength = glm::length(forward), upLength = glm::length(up);
    if (!(forwardLength > 0.0) || !(upLength > 0.0) || !std::isfinite(forwardLength) ||
        !std::isfinite(upLength))
        throw Error(where + ": its node's transform collapses the view direction (a zero scale?)");
    forward /= forwardLength;
    up /= upLength;

    // The target only sets the view direction for rendering, but the viewer orbits around it.
    double distance = 1.0;
    if (!bounds.empty()) {
        glm::dvec3 center(bounds.center());
        double diagonal = glm::length(glm::dvec3(bounds.extent()));
        double depth = glm::dot(center - eye, forward);
        distance = depth > 1e-3 * diagonal && depth > 0.0 ? depth : std::max(diagonal, 1.0);
    }
    Camera camera;
    camera.eye = glm::vec3(eye);
    camera.target = glm::vec3(eye + forward * distance);
    camera.up = glm::vec3(up);
    camera.fovY = float(yfov * (180.0 / kPi));
    try {
        validateCamera(camera, "camera");
    } catch (const Error& e) {
        throw Error(where + ": " + e.what());
    }
    return camera;
}

}  // namespace fp::gltf
