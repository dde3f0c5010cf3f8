// glTF files to Scenes: the preflight, tinygltf with our file access, and the conversion (gltf.h).
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/file.h"
#include "core/log.h"
#include "scene/gltf_internal.h"
#include "scene/load.h"

namespace fp {

namespace {

namespace fs = std::filesystem;
using namespace gltf;

// tinygltf reads buffer files only through these callbacks, and so only through the lookup: nothing is
// searched for in the current directory, and a missing file can be named in our message.
struct FileAccess {
    const GltfLookup& lookup;
    std::map<std::string, std::optional<LibraryFile>> files;
    std::string missing;  // the first file asked for that was not there

    std::optional<LibraryFile>& find(const std::string& path) {
        std::string key = fs::path(path).lexically_normal().string();
        auto it = files.find(key);
        if (it == files.end()) it = files.emplace(key, lookup(key)).first;
        return it->second;
    }
};

bool fileExists(const std::string& path, void* user) {
    FileAccess* access = static_cast<FileAccess*>(user);
    bool found = access->find(path).has_value();
    if (!found && access->missing.empty()) access->missing = fs::path(path).lexically_normal().string();
    return found;
}

std::string expandFilePath(const std::string& path, void*) {
    return path;  // no ~ or $VAR expansion: a URI is a path
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    std::optional<LibraryFile>& file = static_cast<FileAccess*>(user)->find(path);
    if (!file) {
        if (err) *err += "cannot read " + path + "\n";
        return false;
    }
    out->assign(file->bytes.begin(), file->bytes.end());  // kept: two buffers may name the same file
    return true;
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not supported\n";
    return false;
}

// Images stay encoded until a material uses them (gltf_material.cpp decodes them with decodeRgba8); the
// ones in buffer views are read from there, so only data URIs (decoded by tinygltf) are kept here.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
    return true;
}

// The first line of tinygltf's message, shortened: its messages may quote a whole data URI.
std::string firstLine(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    return line.size() > 200 ? line.substr(0, 197) + "..." : line;
}

tinygltf::Model readModel(std::string_view bytes, const Container& container, const std::string& name,
                          const GltfLookup& lookup) {
    FileAccess access{lookup, {}, {}};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile, &access});
    loader.SetImageLoader(&keepEncodedImage, nullptr);
    tinygltf::Model model;
    std::string err, warning;
    unsigned size = static_cast<unsigned>(bytes.size());
    bool ok = container.binary ? loader.LoadBinaryFromMemory(
                                     &model, &err, &warning,
                                     reinterpret_cast<const unsigned char*>(bytes.data()), size, "")
                               : loader.LoadASCIIFromString(&model, &err, &warning, bytes.data(), size, "");
    if (!access.missing.empty()) {
        std::string directory = name.substr(0, name.find_last_of('/') + 1);
        std::string looked = access.missing[0] == '/' ? access.missing : directory + access.missing;
        throw Error(name + ": buffer file '" + access.missing + "' not found or unreadable (looked for " +
                    looked + ")");
    }
    // tinygltf reports some problems without failing (a GLB chunk out of alignment): they count too.
    if (!ok || !err.empty())
        throw Error(name + ": " + firstLine(err.empty() ? "tinygltf could not read it" : err));
    if (!warning.empty()) warn(name + ": " + firstLine(warning));
    return model;
}

std::string plural(size_t n, const std::string& noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

void reportTallies(const MeshTallies& t, const std::string& name) {
    if (t.notTriangles)
        warn(name + ": skipped " + plural(t.notTriangles, "primitive") +
             " of points or lines (only triangles are drawn)");
    if (t.noPositions) warn(name + ": skipped " + plural(t.noPositions, "primitive") + " without POSITION");
    if (t.morphTargets)
        warn(name + ": morph targets not supported: " + plural(t.morphTargets, "primitive") +
             " drawn in their base shape");
    if (t.trailingVertices)
        warn(name + ": ignored the last vertices of " + plural(t.trailingVertices, "TRIANGLES primitive") +
             " whose vertex count is not a multiple of 3");
    if (t.degenerate) warn(name + ": dropped " + plural(t.degenerate, "degenerate (zero-area) triangle"));
    if (t.badNormals)
        warn(name + ": used the geometric normal at " + plural(t.badNormals, "triangle corner") +
             " with a zero-length NORMAL");
}

// Whether a node can place its mesh as an instance: without mirroring it (an instance must keep its
// triangles' winding: instancing.h), and with a transform whose every entry is a float of magnitude
// under 1e18 (others are flattened, where each vertex gets the loader's range check and message).
bool keepsWinding(const MeshInstance& instance) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!(std::abs(instance.world[c][r]) < 1e18)) return false;
    return glm::determinant(glm::dmat3(instance.world)) > 0.0;
}

// Mesh `mesh`'s triangles in its own space, appended to scene->meshes as an InstancedMesh; its index,
// or -1 (and nothing kept) if it has no triangle or one that emits light (emitters stay world triangles).
int storeInstancedMesh(const tinygltf::Model& model, int mesh, int node, MaterialTable& materials,
                       const std::string& name, Scene* scene, MeshTallies* tallies) {
    // The world's triangles and their per-triangle arrays are set aside while the mesh's are made.
    InstancedMesh world;
    auto swapTriangles = [scene](InstancedMesh& m) {
        std::swap(m.triangles, scene->triangles);
        std::swap(m.tangents, scene->tangents);
        std::swap(m.texcoords1, scene->texcoords1);
        std::swap(m.colors, scene->colors);
    };
    swapTriangles(world);
    MeshTallies own;
    MeshInstance local{node, mesh, glm::dmat4(1.0)};
    for (size_t p = 0; p < model.meshes[size_t(mesh)].primitives.size(); ++p)
        appendPrimitive(model, local, p, materials, name, scene, &own);
    InstancedMesh stored;
    stored.name = model.meshes[size_t(mesh)].name.empty() ? "meshes[" + std::to_string(mesh) + "]"
                                                          : model.meshes[size_t(mesh)].name;
    swapTriangles(stored);
    swapTriangles(world);
    for (const Triangle& t : stored.triangles)
        if (scene->materials[t.material].isEmissive()) return -1;
    if (stored.triangles.empty()) return -1;
    tallies->notTriangles += own.notTriangles;
    tallies->noPositions += own.noPositions;
    tallies->morphTargets += own.morphTargets;
    tallies->trailingVertices += own.trailingVertices;
    tallies->degenerate += own.degenerate;
    tallies->badNormals += own.badNormals;
    scene->meshes.push_back(std::move(stored));
    return int(scene->meshes.size()) - 1;
}

Scene buildScene(const tinygltf::Model& model, const std::string& name, const GltfLookup& lookup) {
    SceneGraph graph = walkScene(model, name);
    // A mesh that two or more nodes place without mirroring it is stored once and instanced
    // (scene/instancing.h); every other placement is flattened into world triangles.
    std::map<int, int> uses;
    for (const MeshInstance& instance : graph.instances) {
        if (instance.mesh < 0 || size_t(instance.mesh) >= model.meshes.size())
            throw Error(name + ": nodes[" + std::to_string(instance.node) + "] refers to meshes[" +
                        std::to_string(instance.mesh) + "], which does not exist");
        if (keepsWinding(instance)) ++uses[instance.mesh];
    }
    auto instanceable = [&](const MeshInstance& instance) {
        return keepsWinding(instance) && uses[instance.mesh] >= 2;
    };
    // Flattening repeats a mesh for every node that uses it: refuse a scene whose stored triangles would
    // not fit before allocating them.
    uint64_t bound = 0;
    std::set<int> counted;
    for (const MeshInstance& instance : graph.instances) {
        if (instanceable(instance) && !counted.insert(instance.mesh).second) continue;
        for (size_t p = 0; p < model.meshes[size_t(instance.mesh)].primitives.size(); ++p) {
            bound += std::min(triangleBound(model, instance.mesh, p, name), kMaxTriangles + 1);
            if (bound > kMaxTriangles)
                throw Error(name + ": more than " + std::to_string(kMaxTriangles) + " triangles once its " +
                            std::to_string(graph.instances.size()) +
                            " mesh instances are flattened, more than the renderer takes");
        }
    }

    Scene scene;
    scene.source = name;
    MaterialTable materials(model, name, lookup, &scene);
    MeshTallies tallies;
    std::map<int, int> stored;  // glTF mesh -> Scene::meshes index, -1: flattened after all
    for (const MeshInstance& instance : graph.instances) {
        if (instanceable(instance)) {
            auto it = stored.find(instance.mesh);
            if (it == stored.end())
                it = stored
                         .emplace(instance.mesh, storeInstancedMesh(model, instance.mesh, instance.node,
                                                                    materials, name, &scene, &tallies))
                         .first;
            if (it->second >= 0) {
                scene.instances.push_back({uint32_t(it->second), glm::mat4(instance.world)});
                continue;
            }
        }
        for (size_t p = 0; p < model.meshes[size_t(instance.mesh)].primitives.size(); ++p)
            appendPrimitive(model, instance, p, materials, name, &scene, &tallies);
    }
    if (scene.triangleCount() == 0)
        throw Error(name + ": no triangles to render (" +
                    (graph.instances.empty()
                         ? std::string("the scene places no mesh")
                         : plural(tallies.degenerate, "degenerate triangle") + " dropped, " +
                               plural(tallies.notTriangles, "primitive") + " of points or lines") +
                    ")");
    if (graph.cameraNode >= 0)
        scene.camera = cameraFromNode(model, graph.cameraNode, graph.cameraWorld, scene.bounds(), name);

    materials.reportIgnored();
    reportTallies(tallies, name);
    if (graph.cameraNode < 0 && graph.orthographicCameras)
        warn(name + ": orthographic cameras not supported, ignored (the default camera frames the scene)");
    for (const auto& [light, world] : graph.lightNodes)
        scene.punctualLights.push_back(lightFromNode(model, light, world, name));
    if (!model.animations.empty())
        warn(name + ": animations not supported: the nodes are drawn with their own transforms");
    if (graph.skinnedNodes)
        warn(name + ": skins not supported: " + plural(graph.skinnedNodes, "skinned mesh") +
             " drawn with their nodes' transforms");
    std::string ignored;
    for (const std::string& extension : model.extensionsUsed)
        if (!isImplementedExtension(extension)) ignored += (ignored.empty() ? "" : ", ") + extension;
    if (!ignored.empty()) warn(name + ": ignoring extensions fragpath does not implement: " + ignored);
    return scene;
}

}  // namespace

Scene parseGltf(std::string_view bytes, const std::string& name, const GltfLookup& lookup) {
    if (bytes.empty()) throw Error(name + ": file is empty");
    if (bytes.size() > std::numeric_limits<unsigned>::max())
        throw Error(name + ": larger than 4 GiB, more than tinygltf reads");
    Container container = readContainer(bytes, name);
    std::vector<MeshoptView> meshopt;
    TinygltfInput input;
    {
        nlohmann::json root = parseJson(container.json, name);
        checkSchema(root, container, name);
        meshopt = meshoptViews(root, container, name);
        input = tinygltfInput(bytes, container, std::move(root));
    }
    if (!input.bytes.empty()) {
        bytes = input.bytes;
        container = readContainer(bytes, name);
    }
    tinygltf::Model model = readModel(bytes, container, name, lookup);
    decodeMeshoptViews(meshopt, &model, name);
    decodeDracoPrimitives(&model, input.dracoIndices, name);
    return buildScene(model, name, lookup);
}

Scene loadGltf(const std::string& path) {
    std::string bytes = readFileBytes(path);
    fs::path directory = fs::path(path).parent_path();
    GltfLookup lookup = [directory](const std::string& file) -> std::optional<LibraryFile> {
        fs::path found = fs::path(file).is_absolute() ? fs::path(file) : directory / file;
        std::error_code ec;
        if (!fs::is_regular_file(found, ec)) return std::nullopt;
        try {
            return LibraryFile{found.string(), readFileBytes(found.string())};
        } catch (const Error&) {
            return std::nullopt;  // unreadable: treated like missing
        }
    };
    return parseGltf(bytes, path, lookup);
}

}  // namespace fp
