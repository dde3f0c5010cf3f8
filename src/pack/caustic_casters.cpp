#include "pack/caustic_casters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/aabb.h"
#include "scene/instancing.h"

namespace fp {

namespace {

// The smallest sphere that holds spheres a and b.
glm::vec4 sphereUnion(const glm::vec4& a, const glm::vec4& b) {
    glm::vec3 d = glm::vec3(b) - glm::vec3(a);
    float distance = glm::length(d);
    if (distance + b.w <= a.w) return a;
    if (distance + a.w <= b.w) return b;
    float radius = 0.5f * (distance + a.w + b.w);
    glm::vec3 centre = glm::vec3(a) + d * ((radius - a.w) / distance);
    return glm::vec4(centre, radius);
}

// The sphere about the box's centre that holds `points`; a box alone (the instances') is held by the
// sphere through its corners.
glm::vec4 sphereAbout(const Aabb& box, const std::vector<glm::vec3>& points) {
    glm::vec3 centre = box.center();
    float radius2 = 0.0f;
    for (const glm::vec3& p : points) radius2 = std::max(radius2, glm::dot(p - centre, p - centre));
    if (points.empty()) radius2 = 0.25f * glm::dot(box.extent(), box.extent());
    return glm::vec4(centre, std::sqrt(radius2));
}

// The smallest G texel of a metallic-roughness map (255 for a map without texels).
uint8_t smallestG(const Texture& map) {
    const std::vector<uint8_t>& texels = map.image.texels;
    uint8_t g = 255;
    for (size_t i = 1; i < texels.size(); i += 4) g = std::min(g, texels[i]);
    return g;
}

// The smallest roughness a surface of material m can have, given its map's smallest G texel: the factor
// times that texel (0 for a map that is not there).
float smallestRoughness(const Material& m, size_t textureCount, uint8_t mapSmallestG) {
    if (m.metallicRoughnessTexture < 0) return m.roughness;
    if (size_t(m.metallicRoughnessTexture) >= textureCount) return 0.0f;
    return m.roughness * float(mapSmallestG) / 255.0f;
}

bool deltaLobeBelow(const Material& m, float smallest) {
    // Twice the threshold: the GPU's filtered value may round below the smallest texel, and a delta lobe
    // missed here would lose its caustics (the camera pass leaves them to the light pass).
    if (m.type == MaterialType::Diffuse || m.type == MaterialType::Unlit) return false;
    // A smooth clearcoat is a mirror whatever lies below it.
    if (m.type == MaterialType::MetallicRoughness && m.clearcoat > 0.0f &&
        m.clearcoatRoughness < 2.0f * kSmoothRoughness)
        return true;
    return smallest < 2.0f * kSmoothRoughness;
}

bool glossyCasterBelow(const Material& m, float smallest) {
    bool metal = m.type == MaterialType::Conductor ||
                 (m.type == MaterialType::MetallicRoughness && m.metallic >= 1.0f);
    // A margin of one texel's step over the threshold, for the same reason as deltaLobeBelow's.
    return metal && smallest < kGlossyCasterRoughness + 1.0f / 255.0f;
}

float smallestRoughness(const Material& m, const std::vector<Texture>& textures) {
    bool mapped = m.metallicRoughnessTexture >= 0 && size_t(m.metallicRoughnessTexture) < textures.size();
    return smallestRoughness(m, textures.size(),
                             mapped ? smallestG(textures[size_t(m.metallicRoughnessTexture)]) : uint8_t(255));
}

// Whether each material is a caster, judged when first asked and remembered, and each roughness map
// read at most once, so that the search costs O(triangles + texels) however many triangles and
// materials share a map (it had read a material's map for every triangle: minutes for a 100k-triangle
// model with 2048x2048 maps).
class CasterMaterials {
  public:
    explicit CasterMaterials(const Scene& scene)
        : scene_(scene), caster_(scene.materials.size(), kUnknown), mapG_(scene.textures.size(), kUnknown) {}

    bool operator()(uint32_t material) {
        if (material >= caster_.size()) return false;
        int& known = caster_[material];
        if (known == kUnknown) known = judge(scene_.materials[material]);
        return known != 0;
    }
    size_t mapsRead() const { return mapsRead_; }

  private:
    static constexpr int kUnknown = -1;

    int judge(const Material& m) {
        if (m.type == MaterialType::Diffuse) return 0;  // neither test holds, whatever the map says
        int texture = m.metallicRoughnessTexture;
        uint8_t g = 255;
        if (texture >= 0 && size_t(texture) < mapG_.size()) {
            int& known = mapG_[size_t(texture)];
            if (known == kUnknown) {
                known = smallestG(scene_.textures[size_t(texture)]);
                ++mapsRead_;
            }
            g = uint8_t(known);
        }
        float smallest = smallestRoughness(m, scene_.textures.size(), g);
        return deltaLobeBelow(m, smallest) || glossyCasterBelow(m, smallest);
    }

    const Scene& scene_;
    std::vector<int> caster_, mapG_;  // per material, per texture; kUnknown until asked
    size_t mapsRead_ = 0;
};

}  // namespace

bool hasDeltaLobe(const Material& m, const std::vector<Texture>& textures) {
    return deltaLobeBelow(m, smallestRoughness(m, textures));
}

bool isGlossyCasterMaterial(const Material& m, const std::vector<Texture>& textures) {
    return glossyCasterBelow(m, smallestRoughness(m, textures));
}

std::vector<glm::vec4> causticCasterSpheres(const Scene& scene, size_t* roughnessMapsRead) {
    CasterMaterials isCaster(scene);
    std::vector<glm::vec4> spheres;
    // World triangles, one sphere per material.
    std::map<uint32_t, std::pair<Aabb, std::vector<glm::vec3>>> byMaterial;
    for (const Triangle& t : scene.triangles) {
        if (!isCaster(t.material)) continue;
        auto& [box, points] = byMaterial[t.material];
        for (const glm::vec3& p : t.p) {
            box.grow(p);
            points.push_back(p);
        }
    }
    for (const auto& [material, group] : byMaterial)
        spheres.push_back(sphereAbout(group.first, group.second));
    // Instances: the box of each mesh's caster triangles, placed.
    std::vector<Aabb> meshCasters(scene.meshes.size());
    for (size_t i = 0; i < scene.meshes.size(); ++i)
        for (const Triangle& t : scene.meshes[i].triangles)
            if (isCaster(t.material)) meshCasters[i].grow(t.bounds());
    for (const Instance& instance : scene.instances)
        if (instance.mesh < meshCasters.size() && !meshCasters[instance.mesh].empty())
            spheres.push_back(
                sphereAbout(instanceBounds(meshCasters[instance.mesh], instance.objectToWorld), {}));
    if (roughnessMapsRead) *roughnessMapsRead = isCaster.mapsRead();

    if (spheres.size() > 64) {
        glm::vec4 all = spheres[0];
        for (const glm::vec4& s : spheres) all = sphereUnion(all, s);
        return {all};
    }
    while (spheres.size() > size_t(kMaxCausticCasters)) {
        size_t bestA = 0, bestB = 1;
        float best = std::numeric_limits<float>::infinity();
        for (size_t a = 0; a < spheres.size(); ++a)
            for (size_t b = a + 1; b < spheres.size(); ++b) {
                float r = sphereUnion(spheres[a], spheres[b]).w;
                if (r < best) {
                    best = r;
                    bestA = a;
                    bestB = b;
                }
            }
        spheres[bestA] = sphereUnion(spheres[bestA], spheres[bestB]);
        spheres.erase(spheres.begin() + std::ptrdiff_t(bestB));
    }
    return spheres;
}

}  // namespace fp
