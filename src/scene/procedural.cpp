#include "scene/procedural.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <nlohmann/json.hpp>

#include "core/error.h"

namespace fp {

void appendSphere(Scene& scene, const glm::vec3& center, float radius, int rings, int segments,
                  uint32_t material, bool smooth) {
    rings = std::max(rings, 2);
    segments = std::max(segments, 3);
    const float pi = 3.14159265358979f;
    // Unit direction of grid point (ring r from the north pole, segment s).
    auto direction = [&](int r, int s) {
        float theta = pi * float(r) / float(rings), phi = 2.0f * pi * float(s % segments) / float(segments);
        return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    auto add = [&](const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
        Triangle t;
        t.p = {center + radius * a, center + radius * b, center + radius * c};
        t.material = material;
        glm::vec3 n = glm::normalize(t.geometricNormal());
        t.n = smooth ? std::array<glm::vec3, 3>{a, b, c} : std::array<glm::vec3, 3>{n, n, n};
        scene.triangles.push_back(t);
    };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            glm::vec3 a = direction(r, s), b = direction(r, s + 1), c = direction(r + 1, s),
                      d = direction(r + 1, s + 1);
            // Counter-clockwise from outside; the caps have one triangle per segment, the bands two.
            if (r > 0) add(a, b, d);
            if (r < rings - 1) add(a, d, c);
        }
}

void appendQuad(Scene& scene, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
                uint32_t material) {
    for (auto corners : {std::array<glm::vec3, 3>{a, b, c}, std::array<glm::vec3, 3>{a, c, d}}) {
        Triangle t;
        t.p = corners;
        glm::vec3 n = glm::normalize(t.geometricNormal());
        t.n = {n, n, n};
        t.material = material;
        scene.triangles.push_back(t);
    }
}

Scene causticScene(float glassRoughness) {
    Scene scene;
    scene.source = "caustic scene";
    Material floor;
    floor.name = "floor";
    floor.diffuse = glm::vec3(0.6f);
    Material glass;
    glass.name = "glass";
    glass.type = MaterialType::Dielectric;
    glass.roughness = glassRoughness;
    glass.ior = 1.5f;
    Material light;
    light.name = "light";
    light.diffuse = glm::vec3(0.0f);
    light.emission = glm::vec3(100.0f);
    scene.materials = {floor, glass, light};
    appendQuad(scene, {-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, 0);  // counter-clockwise from above: up
    appendSphere(scene, {0.0f, 0.9f, 0.0f}, 0.5f, 24, 48, 1, true);
    appendQuad(scene, {-0.1f, 3, -0.1f}, {0.1f, 3, -0.1f}, {0.1f, 3, 0.1f}, {-0.1f, 3, 0.1f},
               2);  // facing down
    Camera camera;
    camera.eye = {0.0f, 1.4f, -3.2f};
    camera.target = {0.0f, 0.35f, 0.0f};
    camera.fovY = 35.0f;
    scene.camera = camera;
    return scene;
}

Scene environmentLitScene() {
    Scene scene;
    scene.source = "environment-lit scene";
    Material grey;
    grey.name = "grey";
    grey.diffuse = glm::vec3(0.6f);
    scene.materials = {grey};
    appendQuad(scene, {-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, 0);  // counter-clockwise from above: up
    appendSphere(scene, {0.0f, 1.0f, 0.0f}, 1.0f, 24, 48, 0, true);
    appendSphere(scene, {-2.2f, 0.6f, 0.8f}, 0.6f, 24, 48, 0, true);
    appendSphere(scene, {2.0f, 0.8f, -0.5f}, 0.8f, 24, 48, 0, true);
    Image sky(256, 128);
    for (int y = 0; y < sky.height; ++y)
        for (int x = 0; x < sky.width; ++x) {
            const float t = float(y) / float(sky.height);
            glm::vec3 c = y < sky.height / 2 ? glm::vec3(0.3f + 0.4f * t, 0.45f + 0.3f * t, 0.8f - 0.2f * t)
                                             : glm::vec3(0.25f, 0.2f, 0.15f);
            if (y >= 20 && y < 24 && x >= 60 && x < 64) c = {400.0f, 300.0f, 200.0f};  // the sun
            c.r *= 1.0f + 0.3f * std::sin(0.2f * float(x));  // some variation along the horizon
            sky.at(x, y) = c;
        }
    scene.environment.map = std::move(sky);
    Camera camera;
    camera.eye = {0.0f, 2.5f, -7.0f};
    camera.target = {0.0f, 0.8f, 0.0f};
    camera.fovY = 45.0f;
    scene.camera = camera;
    return scene;
}

namespace {

constexpr float kRoomSize = 2.0f;

// Appends a flat-shaded triangle; counter-clockwise seen from the side it faces.
void addTriangle(Scene& scene, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                 uint32_t material) {
    Triangle t;
    t.p = {a, b, c};
    glm::vec3 n = glm::normalize(t.geometricNormal());
    t.n = {n, n, n};
    t.material = material;
    scene.triangles.push_back(t);
}

// a, b, c, d counter-clockwise seen from the side the quad faces.
void addQuad(Scene& scene, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d,
             uint32_t material) {
    addTriangle(scene, a, b, c, material);
    addTriangle(scene, a, c, d, material);
}

Material diffuse(const char* name, const glm::vec3& reflectance) {
    Material m;
    m.name = name;
    m.diffuse = reflectance;
    return m;
}

enum RoomMaterial : uint32_t { kWhite, kRed, kGreen, kLight, kObject, kRoomMaterials };

// The lit room of procedural.h with a floor of `floorTriangles` (2 or more) triangles. Its materials are
// the first kRoomMaterials; kObject is for what stands in it.
Scene litRoom(int floorTriangles, const std::string& source) {
    Scene scene;
    scene.source = source;
    // The Cornell box's reflectances and light (assets/cornell/cornell.mtl), so that the images look alike.
    scene.materials = {diffuse("white", glm::vec3(0.73f)), diffuse("red", {0.63f, 0.065f, 0.05f}),
                       diffuse("green", {0.14f, 0.45f, 0.091f}), diffuse("light", glm::vec3(0.78f)),
                       diffuse("object", glm::vec3(0.73f))};
    scene.materials[kLight].emission = {17.0f, 12.0f, 4.0f};

    const float s = kRoomSize;
    // The floor is split into strips along x, so that any number of triangles tiles it without
    // T-junctions. An odd count splits one triangle at the midpoint of its edge on the open front
    // (z = 0), where no other triangle shares that edge.
    int strips = floorTriangles / 2;
    for (int i = 0; i < strips; ++i) {
        float x0 = s * float(i) / float(strips), x1 = s * float(i + 1) / float(strips);
        glm::vec3 a(x0, 0, 0), b(x0, 0, s), c(x1, 0, s), d(x1, 0, 0);
        addTriangle(scene, a, b, c, kWhite);
        if (i == 0 && floorTriangles % 2) {
            glm::vec3 m = 0.5f * (a + d);
            addTriangle(scene, a, c, m, kWhite);
            addTriangle(scene, m, c, d, kWhite);
        } else {
            addTriangle(scene, a, c, d, kWhite);
        }
    }
    // Every wall faces into the room.
    addQuad(scene, {0, s, 0}, {s, s, 0}, {s, s, s}, {0, s, s}, kWhite);  // ceiling
    addQuad(scene, {0, 0, s}, {0, s, s}, {s, s, s}, {s, 0, s}, kWhite);  // back
    // The camera looks along +z with +y up, so +x is on the image's left: red there, as in the Cornell box.
    addQuad(scene, {s, 0, 0}, {s, 0, s}, {s, s, s}, {s, s, 0}, kRed);    // left in the image
    addQuad(scene, {0, 0, 0}, {0, s, 0}, {0, s, s}, {0, 0, s}, kGreen);  // right in the image
    // The Cornell box's light in proportion (130 x 105 of 556), a little below the ceiling so that the
    // two never overlap.
    float hx = 0.5f * s * 130.0f / 556.0f, hz = 0.5f * s * 105.0f / 556.0f, y = 0.995f * s, c = 0.5f * s;
    addQuad(scene, {c - hx, y, c - hz}, {c + hx, y, c - hz}, {c + hx, y, c + hz}, {c - hx, y, c + hz},
            kLight);

    // The Cornell box's camera in proportion: the open front just fills the 39.3 degree field of view.
    Camera camera;
    camera.fovY = 39.3f;
    camera.target = {c, c, 0.0f};
    camera.eye = {c, c, -c / std::tan(0.5f * glm::radians(camera.fovY))};
    scene.camera = camera;
    return scene;
}

// SplitMix64 (Steele, Lea and Flood 2014): a tiny generator whose output is fixed by its definition, unlike
// the standard library's distributions, so a seed names the same soup everywhere.
class SplitMix64 {
  public:
    explicit SplitMix64(uint64_t seed) : state_(seed) {}
    uint64_t next() {
        uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1), from the top 24 bits: exactly representable, so never rounds up to 1.
    float uniform() { return float(next() >> 40) * (1.0f / 16777216.0f); }
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }

  private:
    uint64_t state_;
};

}  // namespace

SphereSceneLayout sphereSceneLayout(int triangles) {
    if (triangles < kMinSphereSceneTriangles)
        throw Error("a sphere scene needs at least " + std::to_string(kMinSphereSceneTriangles) +
                    " triangles, not " + std::to_string(triangles));
    // The sphere may take all but the room and a one-quad floor. With m = rings - 1 it has 2 * segments * m
    // triangles; quads are square-ish when segments is about 2m, so m is searched where segments / m
    // stays within [1, 4], and the m that leaves the fewest triangles to the floor wins (the nearer to 2:1
    // on a tie). That is usually none: the floor stays one quad.
    int budget = (triangles - kRoomTriangles - 2) / 2;  // segments * m at most
    double ideal = std::sqrt(double(budget) / 2.0);
    int lo = std::max(1, int(std::ceil(ideal / std::sqrt(2.0)))),
        hi = std::max(lo, int(std::floor(ideal * std::sqrt(2.0))));
    SphereSceneLayout best;
    int bestLeft = -1;
    double bestSkew = 0.0;
    for (int m = lo; m <= hi; ++m) {
        int segments = budget / m;
        if (segments < 3) continue;
        int left = budget - segments * m;
        double skew = std::abs(std::log(double(segments) / (2.0 * m)));
        if (bestLeft < 0 || left < bestLeft || (left == bestLeft && skew < bestSkew)) {
            bestLeft = left;
            bestSkew = skew;
            best.rings = m + 1;
            best.segments = segments;
        }
    }
    if (bestLeft < 0) {  // a budget too small for the aspect range: the smallest sphere
        best.rings = 2;
        best.segments = budget;
    }
    best.sphereTriangles = 2 * best.segments * (best.rings - 1);
    best.floorTriangles = triangles - kRoomTriangles - best.sphereTriangles;
    return best;
}

Scene benchmarkSphereScene(int triangles) {
    SphereSceneLayout layout = sphereSceneLayout(triangles);
    Scene scene = litRoom(layout.floorTriangles, "sphere scene, " + std::to_string(triangles) + " triangles");
    scene.triangles.reserve(size_t(triangles));
    // Off-centre towards the back so that the light falls on its front, and just above the floor.
    appendSphere(scene, {0.5f * kRoomSize, 0.33f * kRoomSize, 0.55f * kRoomSize}, 0.3f * kRoomSize,
                 layout.rings, layout.segments, kObject, true);
    return scene;
}

Scene randomTriangleSoup(int triangles, uint32_t seed) {
    if (triangles < kMinSoupTriangles)
        throw Error("a triangle soup scene needs at least " + std::to_string(kMinSoupTriangles) +
                    " triangles, not " + std::to_string(triangles));
    Scene scene = litRoom(
        2, "random triangle soup, " + std::to_string(triangles) + " triangles, seed " + std::to_string(seed));
    scene.triangles.reserve(size_t(triangles));
    SplitMix64 random(seed);
    const float reach = 0.06f * kRoomSize;
    // Centres keep every vertex inside the room, clear of the walls and the light.
    const glm::vec3 lo(0.15f * kRoomSize + reach), hi(0.85f * kRoomSize - reach);
    while (int(scene.triangles.size()) < triangles) {
        glm::vec3 centre(random.uniform(lo.x, hi.x), random.uniform(lo.y, hi.y), random.uniform(lo.z, hi.z));
        std::array<glm::vec3, 3> p;
        for (glm::vec3& v : p)
            v = centre + glm::vec3(random.uniform(-reach, reach), random.uniform(-reach, reach),
                                   random.uniform(-reach, reach));
        // Slivers far thinner than the rest would only test the repair of degenerate input: draw again.
        if (0.5f * glm::length(glm::cross(p[1] - p[0], p[2] - p[0])) < 1e-3f * reach * reach) continue;
        addTriangle(scene, p[0], p[1], p[2], kObject);
    }
    return scene;
}

namespace {

// The text of the JSON array assigned to `exports.<key>`, found by matching brackets (the arrays hold
// only numbers, so no bracket can hide in a string).
std::string exportedArray(const std::string& text, const std::string& key, const std::string& name) {
    std::string marker = "exports." + key;
    size_t at = text.find(marker);
    if (at == std::string::npos) throw Error(name + ": no " + marker);
    at += marker.size();
    while (at < text.size() && (std::isspace(static_cast<unsigned char>(text[at])) || text[at] == '=')) ++at;
    if (at >= text.size() || text[at] != '[') throw Error(name + ": " + marker + " is not an array");
    int depth = 0;
    for (size_t i = at; i < text.size(); ++i) {
        if (text[i] == '[') ++depth;
        if (text[i] == ']' && --depth == 0) return text.substr(at, i + 1 - at);
    }
    throw Error(name + ": " + marker + " never ends");
}

template <typename T, typename Convert>
std::vector<T> triples(const nlohmann::json& array, const char* key, const std::string& name,
                       Convert convert) {
    if (!array.is_array()) throw Error(name + ": " + key + " is not an array");
    std::vector<T> out;
    out.reserve(array.size());
    for (size_t i = 0; i < array.size(); ++i) {
        const nlohmann::json& item = array[i];
        if (!item.is_array() || item.size() != 3 || !item[0].is_number() || !item[1].is_number() ||
            !item[2].is_number())
            throw Error(name + ": " + key + "[" + std::to_string(i) + "] is not three numbers");
        out.push_back(convert(item, i));
    }
    return out;
}

}  // namespace

IndexedMesh parseMeshModule(const std::string& text, const std::string& name) {
    nlohmann::json positions, cells;
    try {
        size_t first = text.find_first_not_of(" \t\r\n");
        if (first != std::string::npos && text[first] == '{') {
            nlohmann::json j = nlohmann::json::parse(text);
            if (!j.contains("positions") || !j.contains("cells"))
                throw Error(name + ": needs the keys \"positions\" and \"cells\"");
            positions = j["positions"];
            cells = j["cells"];
        } else {
            positions = nlohmann::json::parse(exportedArray(text, "positions", name));
            cells = nlohmann::json::parse(exportedArray(text, "cells", name));
        }
    } catch (const nlohmann::json::exception& e) {
        throw Error(name + ": " + e.what());
    }
    IndexedMesh mesh;
    mesh.positions = triples<glm::vec3>(positions, "positions", name, [&](const nlohmann::json& p, size_t i) {
        glm::vec3 v(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            throw Error(name + ": positions[" + std::to_string(i) + "] is not finite");
        return v;
    });
    mesh.cells =
        triples<std::array<uint32_t, 3>>(cells, "cells", name, [&](const nlohmann::json& c, size_t i) {
            std::array<uint32_t, 3> cell{};
            for (int k = 0; k < 3; ++k) {
                if (!c[k].is_number_integer() || c[k].get<int64_t>() < 0 ||
                    c[k].get<int64_t>() >= int64_t(mesh.positions.size()))
                    throw Error(name + ": cells[" + std::to_string(i) + "] indexes no position");
                cell[k] = c[k].get<uint32_t>();
            }
            return cell;
        });
    return mesh;
}

Scene benchmarkMeshScene(const IndexedMesh& mesh, const std::string& name) {
    // No area is no direction to shade with (and the normalisation in addTriangle would divide by 0).
    auto hasArea = [](const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
        glm::vec3 n = glm::cross(b - a, c - a);
        float squared = glm::dot(n, n);
        return squared > 0.0f && std::isfinite(squared);
    };
    // Only the cells that are kept count towards the size, so a stray vertex cannot shrink the mesh.
    std::vector<std::array<uint32_t, 3>> kept;
    Aabb bounds;
    for (const std::array<uint32_t, 3>& cell : mesh.cells)
        if (hasArea(mesh.positions[cell[0]], mesh.positions[cell[1]], mesh.positions[cell[2]])) {
            kept.push_back(cell);
            for (uint32_t i : cell) bounds.grow(mesh.positions[i]);
        }
    if (kept.empty()) throw Error(name + ": no triangle has an area");
    glm::vec3 extent = bounds.extent();
    float scale = 0.6f * kRoomSize / std::max({extent.x, extent.y, extent.z});
    // The lowest point touches the floor, the middle of the footprint is the middle of the room.
    glm::vec3 foot(bounds.center().x, bounds.lo.y, bounds.center().z);
    glm::vec3 place(0.5f * kRoomSize, 0.0f, 0.5f * kRoomSize);
    Scene scene = litRoom(2, name);
    scene.triangles.reserve(scene.triangles.size() + kept.size());
    for (const std::array<uint32_t, 3>& cell : kept) {
        std::array<glm::vec3, 3> p;
        for (int k = 0; k < 3; ++k) p[k] = place + scale * (mesh.positions[cell[k]] - foot);
        // A cell far smaller than the mesh can still lose its area to rounding once placed.
        if (hasArea(p[0], p[1], p[2])) addTriangle(scene, p[0], p[1], p[2], kObject);
    }
    return scene;
}

}  // namespace fp
