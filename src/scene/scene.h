#pragma once
// The renderer's scene: a triangle soup with materials, as loaded and validated from files.
// Everything downstream (BVH, GPU layout) reads only this; nothing here knows about OpenGL.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/aabb.h"
#include "image/image.h"
#include "image/rgba8_image.h"
#include "settings/render_settings.h"
#include "settings/setting_table.h"

namespace fp {

// The surface models. Each has its own file of formulas in glsl/common/bsdf.glsl.
enum class MaterialType : uint32_t {
    Diffuse = 0,     // Lambertian: Kd
    Conductor = 1,   // GGX microfacet metal: F0 = Ks, roughness Pr
    Plastic = 2,     // GGX dielectric coat (ior Ni) over a Lambertian base Kd
    Dielectric = 3,  // glass: exact Fresnel, refraction (ior Ni, tint Tf), smooth or GGX-rough (Pr)
    // glTF 2.0's metallic-roughness model (MTL Pm): metallic * Conductor(F0 = base colour) +
    // (1 - metallic) * Plastic(white coat of index ior over a Lambertian base colour), one roughness.
    MetallicRoughness = 4,
    // glTF KHR_materials_unlit: the surface shows its base colour `diffuse` (times its map) as radiance
    // leaving both faces and scatters nothing; not a light (nothing samples it), it is seen only by the
    // rays that hit it, as Blender's importer makes it (emission = base colour, no scattering).
    Unlit = 5,
};

// How a material's alpha (coverage) is used, as glTF 2.0's material.alphaMode: OPAQUE ignores it, MASK
// shows the surface where alpha >= alphaCutoff and nothing elsewhere, BLEND shows it with probability
// alpha (stochastic opacity: rays pass through the rest, camera, bounce and shadow rays alike).
enum class AlphaMode : uint32_t { Opaque = 0, Mask = 1, Blend = 2 };

struct Material {
    std::string name = "default";
    MaterialType type = MaterialType::Diffuse;
    glm::vec3 diffuse{0.8f};       // MTL Kd: Lambertian reflectance, each channel in [0, 1]
    glm::vec3 emission{0.0f};      // MTL Ke: radiance of a one-sided Lambertian emitter (front face only)
    glm::vec3 specular{0.0f};      // MTL Ks: conductor reflectance at normal incidence, or coat tint
    glm::vec3 transmission{1.0f};  // MTL Tf: dielectric transmission tint, each channel in [0, 1]
    float roughness = 0.0f;  // MTL Pr (or from Ns): perceptual roughness in [0, 1]; GGX alpha = roughness^2
    float ior = 1.5f;        // MTL Ni: index of refraction of dielectrics and coats, in [1, 4]
    // MTL Vd (our extension): the Abbe number of a dispersive glass, 0 for none. Ni is then the index at
    // the Fraunhofer d line (587.6 nm) and the index follows Cauchy's equation n = A + B / lambda^2.
    float abbeNumber = 0.0f;
    // MetallicRoughness: glTF metallicFactor, MTL Pm, in [0, 1]. `diffuse` is the base colour
    // (glTF baseColorFactor.rgb), `roughness` glTF's roughnessFactor and `ior` the coat's index (1.5).
    float metallic = 0.0f;
    // MetallicRoughness, glTF KHR_materials_specular: specularFactor * specularColorFactor, the tint of
    // the dielectric coat's reflectance (its exact Fresnel at `ior` times this; 1: the plain model).
    glm::vec3 specularColor{1.0f};
    // Dielectric, glTF KHR_materials_volume: the absorption coefficient sigma_a per unit length of the
    // medium inside the mesh, -ln(attenuationColor) / attenuationDistance; a path inside loses
    // exp(-sigma_a d) over the distance d (Beer-Lambert). 0: clear glass.
    glm::vec3 absorption{0.0f};
    // MetallicRoughness, glTF KHR_materials_clearcoat: a second GGX lobe on top, a clear dielectric coat
    // of index 1.5 with its own roughness (perceptual, as `roughness`), weighted by `clearcoat` in [0, 1]
    // and by its Fresnel reflectance; what it lets through reaches the model below (bsdf.glsl).
    float clearcoat = 0.0f;
    float clearcoatRoughness = 0.0f;
    // MetallicRoughness, glTF KHR_materials_sheen: a sheen lobe (the Charlie distribution of Estevez &
    // Kulla 2017) of this colour (0: none) and roughness over the base, which it dims by what it reflects.
    glm::vec3 sheenColor{0.0f};
    float sheenRoughness = 0.0f;

    // Coverage, for every type (glTF baseColorFactor.a and alphaMode/alphaCutoff; MTL d and map_d).
    float alpha = 1.0f;  // in [0, 1]
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;  // MASK only
    // glTF doubleSided. False: the camera does not see the back face (glTF's back-face culling; every
    // other ray meets both sides: glsl/common/opacity.glsl); OBJ surfaces are double-sided. Emission is
    // one-sided (the front face) either way.
    bool doubleSided = true;

    // Texture maps: indices into Scene::textures, or -1. Each multiplies the factor it belongs to
    // (glTF's rule, and the MTL spec's for map_Kd), sampled as the Texture says (wrap, filter, uv slot).
    // Colour maps (diffuse, emission, specular) are sRGB-encoded; the others are linear.
    // diffuseTexture: MTL map_Kd, glTF baseColorTexture (rgb): multiplies `diffuse` wherever a model
    // uses it (Lambertian reflectance, the plastic's base, the metallic-roughness base colour).
    int32_t diffuseTexture = -1;
    // glTF metallicRoughnessTexture: roughness *= G, metallic *= B (MTL map_Pr / map_Pm are combined
    // into one such texture). Roughness applies to every type that has one.
    int32_t metallicRoughnessTexture = -1;
    int32_t emissionTexture = -1;  // glTF emissiveTexture, MTL map_Ke: multiplies `emission`
    // glTF normalTexture, MTL norm/map_Bump (a normal map): a tangent-space normal in rgb * 2 - 1, x and
    // y scaled by normalScale (glTF normalTexture.scale), relative to the triangle's tangent frame
    // (Scene::tangents, or computed from the uvs).
    int32_t normalTexture = -1;
    float normalScale = 1.0f;
    // Its A channel (linear) multiplies `alpha`: glTF points it at baseColorTexture, MTL map_d gets a
    // texture whose A holds the map's coverage.
    int32_t alphaTexture = -1;
    int32_t specularTexture = -1;  // MTL map_Ks: multiplies `specular` (Conductor F0, Plastic coat tint)

    bool isEmissive() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
    bool hasAlpha() const { return alphaMode != AlphaMode::Opaque; }
    // Whether traversal must look at this material's hits (alpha or back-face culling).
    bool needsOpacityTest() const { return hasAlpha() || !doubleSided; }
    // Every texture index it holds, -1 for the unused ones.
    std::array<int32_t, 6> textureIndices() const {
        return {diffuseTexture, metallicRoughnessTexture, emissionTexture, normalTexture,
                alphaTexture,   specularTexture};
    }
    bool hasTextures() const {
        for (int32_t t : textureIndices())
            if (t >= 0) return true;
        return false;
    }
};

struct Triangle {
    // Counter-clockwise as seen from the front: the geometric normal is (p1-p0) x (p2-p0).
    std::array<glm::vec3, 3> p;
    // Unit shading normals per vertex; equal to the geometric normal when the file gives none.
    std::array<glm::vec3, 3> n;
    // Texture coordinates per vertex (OBJ vt; v = 0 is the bottom row of an image); (0, 0) when the
    // face has none, in which case its material has no texture (see loadObj).
    std::array<glm::vec2, 3> uv{};
    uint32_t material = 0;  // index into Scene::materials

    glm::vec3 geometricNormal() const { return glm::cross(p[1] - p[0], p[2] - p[0]); }
    float area() const { return 0.5f * glm::length(geometricNormal()); }
    Aabb bounds() const {
        Aabb b;
        for (const glm::vec3& v : p) b.grow(v);
        return b;
    }
};

// A perspective camera: a pinhole, or a thin lens (pbrt-v4 section 5.2.3; Kolb et al. 1995) when
// aperture > 0. The lens is a disc of diameter `aperture` centred on the eye, perpendicular to the view
// direction; the plane in focus is perpendicular to the view direction at focusDistance from the eye
// (measured along the view direction, as pbrt's focaldistance). A point at that depth is imaged sharp;
// one at depth d spreads over a disc of diameter aperture * |d - f| / d on the plane of focus (the
// circle of confusion).
struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 1.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovY = 40.0f;  // vertical field of view in degrees, in (0, 180)
    // The lens's diameter in scene units (pbrt's lensradius is half of it); 0: a pinhole, nothing blurs.
    float aperture = 0.0f;
    // Distance from the eye to the plane in focus, > 0; unset: |target - eye|, the target in focus.
    std::optional<float> focusDistance = std::nullopt;
};

// The distance to the plane in focus: camera.focusDistance, else the distance from eye to target.
float resolvedFocusDistance(const Camera& camera);

// The camera's frame as every renderer uses it (glsl/common/camera.glsl): `right` and `up` are the unit
// basis vectors scaled by tan(fovY / 2) (and `right` by the aspect ratio width / height as well), so the
// point of the image plane at normalised device coordinates (x, y) in [-1, 1]^2 lies at
// eye + forward + x * right + y * up, one unit in front of the eye.
struct CameraFrame {
    glm::vec3 eye{0.0f}, forward{0.0f, 0.0f, 1.0f}, right{1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f};
    float lensRadius = 0.0f;     // aperture / 2; 0: a pinhole
    float focusDistance = 1.0f;  // along forward
};
CameraFrame cameraFrame(const Camera& camera, float aspect);

// Shirley & Chiu 1997, "A Low Distortion Map Between Disk and Square" (the concentric map; pbrt-v4
// A.5.1): [0, 1)^2 onto the unit disc, area-preserving, so a uniform (or stratified) u gives uniform
// (stratified) points on the disc. glsl/common/sampling.glsl has the same map.
glm::vec2 concentricDisk(glm::vec2 u);

// Light arriving from infinitely far away, from every direction no surface blocks: a constant colour,
// or an equirectangular HDR map (+y up; u = 0.5 + atan2(d.x, -d.z) / 2pi, v = acos(d.y) / pi) scaled by
// `intensity` and turned `rotationDegrees` about +y.
struct Environment {
    glm::vec3 color{0.0f};
    Image map;  // empty when the environment is the constant colour
    float intensity = 1.0f;
    float rotationDegrees = 0.0f;
    bool hasMap() const { return map.width > 0; }
    bool isBlack() const { return !hasMap() && color == glm::vec3(0.0f); }
};

// A light of no extent: a point, a spot or a directional light, with glTF's semantics
// (KHR_lights_punctual) so that a glTF node's light maps onto it field by field, in the renderer's
// radiometric units. The renderer's radiance is W/(sr m^2) per RGB channel, the unit of MTL Ke, with
// scene lengths taken as metres; so
//   point, spot:  `intensity` is radiant intensity I in W/sr (colour x intensity): a surface at distance
//                 r whose normal makes the angle theta with the way to the light receives the irradiance
//                 E = I cos(theta) / r^2 (inverse-square falloff, never cut off);
//   directional:  `intensity` is the irradiance E in W/m^2 on a surface facing the light, from the one
//                 direction -`direction` (no falloff with distance).
// glTF gives point and spot intensities in candela and directional ones in lux; they map onto these
// 1:1, colour times intensity, as Ke and glTF's emissive factors are taken as radiance 1:1: the renderer
// has no absolute photometric scale, and dividing by 683 lm/W would make a glTF lamp 683 times darker
// than an emissive surface of the same nominal value. glTF's `range` (a cut-off hint) is not
// represented: the falloff is the physical inverse square everywhere.
// The lights are delta distributions (pbrt-v4, section 12.2, 12.3): no ray can hit one and the camera
// never sees one directly; nee samples them and bdpt starts light subpaths on them, while the naive and
// bsdf integrators, which find light only by hitting it, cannot see them at all.
enum class PunctualLightType : uint32_t {
    Point = 0,        // from `position` in every direction
    Spot = 1,         // from `position` into a cone about `direction`
    Directional = 2,  // from infinitely far away, travelling along `direction`
};

struct PunctualLight {
    PunctualLightType type = PunctualLightType::Point;
    std::string name;          // for messages and the viewer's panel; may be empty
    glm::vec3 position{0.0f};  // point, spot: where the light is (a glTF node's world translation)
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // spot, directional: unit, the way the light travels (the
                                             // cone's axis; glTF: the node's -Z axis in world space)
    glm::vec3 intensity{1.0f};               // W/sr (point, spot) or W/m^2 (directional), per channel, >= 0
    // Spot only, glTF's innerConeAngle and outerConeAngle, in radians from the axis: full intensity up to
    // the inner angle, nothing beyond the outer one, and between them glTF's reference falloff, the
    // square of the cosine's linear ramp: t = (cos - cos outer) / (cos inner - cos outer), I t^2
    // (scene/punctual_light.h). 0 <= inner < outer <= pi / 2, glTF's defaults 0 and pi / 4.
    float innerConeAngle = 0.0f;
    float outerConeAngle = 0.78539816f;
};

// A texture map. Texels are kept as the file stores them, 8-bit codes; the renderer decodes colour maps
// (sRGB-encoded) with the exact sRGB curve before filtering, and reads the others (roughness, normals,
// coverage) as code / 255, so nothing is lost to an early conversion and the GPU copy is a quarter of a
// float one.
// How a map reads its texture outside [0, 1] along one axis (glTF sampler.wrapS / wrapT).
enum class TextureWrap : uint32_t { Repeat = 0, ClampToEdge = 1, MirroredRepeat = 2 };

struct Texture {
    std::string name;  // the file it came from, for messages
    Rgba8Image image;
    // How the maps that name this texture sample it (glTF's sampler; MTL maps use the defaults): the wrap
    // modes, nearest (glTF magFilter NEAREST: the texel the point falls in) instead of bilinear, and
    // which of a triangle's two texture coordinate slots they read: 0 is Triangle::uv, 1
    // Scene::texcoords1. A glTF image that two samplers or slots read becomes two textures.
    TextureWrap wrapS = TextureWrap::Repeat, wrapT = TextureWrap::Repeat;
    bool nearest = false;
    int uvSlot = 0;  // 0 or 1
};

// A mesh drawn in several places (a glTF mesh under several nodes), stored once in its own space and
// placed by Scene::instances (scene/instancing.h). Its materials emit nothing: emitters are always
// world triangles, which light sampling picks from.
struct InstancedMesh {
    std::string name;
    std::vector<Triangle> triangles;                     // in the mesh's own space; never empty
    std::vector<std::array<glm::vec4, 3>> tangents;      // as Scene::tangents, for these triangles
    std::vector<std::array<glm::vec2, 3>> texcoords1{};  // as Scene::texcoords1
    std::vector<std::array<glm::vec4, 3>> colors{};      // as Scene::colors
};

struct Instance {
    uint32_t mesh = 0;              // index into Scene::meshes
    glm::mat4 objectToWorld{1.0f};  // affine, with a positive determinant (no mirroring)
};

struct Scene {
    std::vector<Triangle> triangles;  // in world space; the instances' are in `meshes`
    std::vector<Material> materials;  // never empty once loaded
    std::vector<Texture> textures;    // what Material's *Texture fields index
    // Optional per-vertex tangents of normal-mapped triangles, one array per triangle (empty: computed
    // from positions and uvs when packing; so is a triangle with a w of 0): xyz the tangent (the
    // direction of increasing u), w = +-1 the bitangent's sign, bitangent = w cross(n, tangent), as
    // glTF's TANGENT attribute.
    std::vector<std::array<glm::vec4, 3>> tangents;
    // Optional, one entry per triangle, empty when no triangle needs them: the second texture
    // coordinate slot (Texture::uvSlot 1; glTF maps on a second TEXCOORD set or transform), and per-vertex
    // colours (glTF COLOR_0, linear rgba; 1 for triangles without), which multiply the base colour
    // (Material::diffuse) and alpha.
    std::vector<std::array<glm::vec2, 3>> texcoords1;
    std::vector<std::array<glm::vec4, 3>> colors;
    std::optional<Camera> camera;  // from a scene file; absent for a bare OBJ
    SettingValues fileSettings;    // the scene file's "render" block; command-line flags override it
    Environment environment;
    std::vector<PunctualLight> punctualLights;  // from a scene file's "lights" (scene/punctual_light.h)
    std::vector<InstancedMesh> meshes;          // what `instances` place (scene/instancing.h)
    std::vector<Instance> instances;
    std::string source;  // the file it came from, for messages

    // World triangles and every instance's (scene/instancing.h).
    Aabb bounds() const;
    size_t triangleCount() const;
};

// The camera of a scene that brings none, as model viewers frame a model: from the front (glTF's
// convention is that a model faces +z, so the eye is on the +z side looking towards -z), raised
// kFrameElevationDegrees above the horizontal (<model-viewer>'s default orbit, 75 degrees from the pole),
// aimed at the bounding box's centre, at the distance where all eight corners of the box are inside both
// the vertical field of view fovY and the horizontal one of an image of width / height `aspect`, with a
// margin of kFrameMargin. A flat model facing +z is seen nearly face-on, never edge-on.
constexpr float kFrameElevationDegrees = 15.0f;
constexpr float kFrameMargin = 1.1f;  // the box fills 1 / 1.1 of the image's tighter direction
Camera frameBounds(const Aabb& bounds, float fovY = 40.0f, float aspect = 1.0f);

}  // namespace fp

namespace fp {

// Throws fp::Error for a camera that cannot form an image: non-finite values, eye == target, up zero
// or parallel to the view direction, field of view outside (0, 180). `where` names the camera in the
// message as its fields are named ("camera" gives "camera.fov ...").
void validateCamera(const Camera& camera, const std::string& where);

}  // namespace fp
