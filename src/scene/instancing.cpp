#include "scene/instancing.h"

#include <cmath>

#include "core/error.h"

namespace fp {

Triangle placedTriangle(const Triangle& t, const glm::mat4& objectToWorld) {
    const glm::mat3 linear(objectToWorld);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
    Triangle out = t;
    for (int k = 0; k < 3; ++k) {
        out.p[k] = glm::vec3(objectToWorld * glm::vec4(t.p[k], 1.0f));
        out.n[k] = glm::normalize(normalMatrix * t.n[k]);
    }
    return out;
}

Aabb meshBounds(const InstancedMesh& mesh) {
    Aabb local;
    for (const Triangle& t : mesh.triangles) local.grow(t.bounds());
    return local;
}

Aabb instanceBounds(const Aabb& local, const glm::mat4& objectToWorld) {
    Aabb world;
    for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 p((corner & 1) ? local.hi.x : local.lo.x, (corner & 2) ? local.hi.y : local.lo.y,
                    (corner & 4) ? local.hi.z : local.lo.z);
        world.grow(glm::vec3(objectToWorld * glm::vec4(p, 1.0f)));
    }
    return world;
}

Scene flattenInstances(Scene scene) {
    bool tangents = !scene.tangents.empty();
    for (const InstancedMesh& mesh : scene.meshes) tangents = tangents || !mesh.tangents.empty();
    if (tangents) scene.tangents.resize(scene.triangles.size());  // w = 0: computed when packing
    // The second uv slot and colours are copied as they are (neutral where a mesh has none: scene.h).
    // (Before the loop below, which appends the instances' triangles in the same order.)
    auto copyExtras = [&scene](auto& placed, auto meshMember, auto neutral) {
        bool any = !placed.empty();
        for (const InstancedMesh& mesh : scene.meshes) any = any || !(mesh.*meshMember).empty();
        if (!any) return;
        placed.resize(scene.triangles.size(), {neutral, neutral, neutral});
        for (const Instance& instance : scene.instances) {
            const auto& own = scene.meshes[instance.mesh].*meshMember;
            if (own.empty())
                placed.resize(placed.size() + scene.meshes[instance.mesh].triangles.size(),
                              {neutral, neutral, neutral});
            else
                placed.insert(placed.end(), own.begin(), own.end());
        }
    };
    copyExtras(scene.texcoords1, &InstancedMesh::texcoords1, glm::vec2(0.0f));
    copyExtras(scene.colors, &InstancedMesh::colors, glm::vec4(1.0f));
    for (const Instance& instance : scene.instances) {
        const InstancedMesh& mesh = scene.meshes[instance.mesh];
        const glm::mat3 linear(instance.objectToWorld);
        for (size_t i = 0; i < mesh.triangles.size(); ++i) {
            scene.triangles.push_back(placedTriangle(mesh.triangles[i], instance.objectToWorld));
            if (!tangents) continue;
            std::array<glm::vec4, 3> t{};
            if (!mesh.tangents.empty())
                for (int k = 0; k < 3; ++k) {
                    const glm::vec4& given = mesh.tangents[i][size_t(k)];
                    if (given.w != 0.0f)
                        t[size_t(k)] = glm::vec4(glm::normalize(linear * glm::vec3(given)), given.w);
                }
            scene.tangents.push_back(t);
        }
    }
    scene.meshes.clear();
    scene.instances.clear();
    return scene;
}

void validateInstances(const Scene& scene) {
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const InstancedMesh& mesh = scene.meshes[m];
        std::string what = scene.source + ": instanced mesh " + std::to_string(m) + " ('" + mesh.name + "')";
        if (mesh.triangles.empty()) throw Error(what + " has no triangles");
        if (!mesh.tangents.empty() && mesh.tangents.size() != mesh.triangles.size())
            throw Error("internal: " + what + " has tangents for some triangles only");
        for (const Triangle& t : mesh.triangles) {
            if (t.material >= scene.materials.size()) throw Error("internal: " + what + " names no material");
            if (scene.materials[t.material].isEmissive())
                throw Error("internal: " + what + " emits light (emitters must be world triangles)");
        }
    }
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        std::string what = scene.source + ": instance " + std::to_string(i);
        if (instance.mesh >= scene.meshes.size()) throw Error("internal: " + what + " names no mesh");
        const glm::mat4& m = instance.objectToWorld;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(m[c][r])) throw Error(what + " has a non-finite transform");
        if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)
            throw Error(what + " has a projective transform");
        if (!(glm::determinant(glm::mat3(m)) > 0.0f))
            throw Error("internal: " + what + " mirrors or collapses its mesh (determinant <= 0)");
    }
}

Aabb Scene::bounds() const {
    Aabb b;
    for (const Triangle& t : triangles) b.grow(t.bounds());
    std::vector<Aabb> local;
    for (const InstancedMesh& mesh : meshes) local.push_back(meshBounds(mesh));
    for (const Instance& instance : instances)
        b.grow(instanceBounds(local[instance.mesh], instance.objectToWorld));
    return b;
}

size_t Scene::triangleCount() const {
    size_t n = triangles.size();
    for (const Instance& instance : instances) n += meshes[instance.mesh].triangles.size();
    return n;
}

}  // namespace fp
