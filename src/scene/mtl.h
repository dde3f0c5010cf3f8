#pragma once
// MTL material libraries, mapped onto fragpath's four surface models (MaterialType in scene.h).
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace fp {

// How MTL statements become a Material. The MTL spec (Wavefront, "MTL material format", Lighting and
// illumination models) names a lighting model with `illum`; PBR extensions add Pr (roughness) and Pm
// (metallic), with map_Pr and map_Pm, and norm (a normal map). We read them as follows, first matching
// rule wins:
//
// 1. Dielectric (glass): `illum` 4, 6, 7 or 9 (the spec's transparent models), or, when the material
//    gives no `illum` at all, a `Tf` (alias `Kt`, as tinyobjloader reads it) that is not black.
//    An explicit opaque `illum` (0, 1, 2, 3, 5, 8, 10) wins over `Tf`: the spec's Tf is the filter for
//    light that passes through a transparent material, and exporters write `Tf 1 1 1` with `illum 2`
//    on every opaque material (3ds Max's, as in the Dabrovic Sponza), which must not turn into glass.
//      ior          = Ni if given, else 1.5 (the MTL default Ni 1 would make the glass invisible;
//                     an explicit Ni is kept, even 1)
//      dispersion   = Vd (our extension: the Abbe number, 10 to 100; 0 or absent: none)
//      transmission = Tf if not black, else white
//      roughness    = Pr if given, else 1 with map_Pr, else 0 (smooth glass)
//    `d` (dissolve) never selects glass: it is coverage (below), for every type.
// 2. MetallicRoughness, the PBR convention: a Pm or map_Pm statement (any value: Pm 0 is a dielectric
//    of the metallic-roughness model, Pm 1 a metal, between them the blend; glTF's model).
//      diffuse (base colour) = Kd, metallic = Pm if given, else 1 (map_Pm alone)
//      roughness = Pr if given, else 1 with map_Pr, else 0.5
//      ior (of the dielectric part's coat) = Ni if given and above 1, else 1.5; Ks is not used
// 3. Conductor, Fresnel mirror: `illum 5` with a non-black Ks and neither Pm nor map_Pm.
//      specular  = Ks, roughness = Pr if given, else 1 with map_Pr, else 0 (illum 5 is a ray-traced mirror)
// 4. Plastic: a non-black Ks, unless an explicit `illum 0` or `illum 1` switches specular off (the
//    spec's models 0 and 1 have no Ks term; exporters write them for materials without highlights).
//    This includes `illum 2`, `illum 3` (ray-traced reflection: a mirror-like coat) and no `illum`.
//      diffuse   = Kd, specular = Ks (coat tint), ior = Ni if given and above 1, else 1.5
//      roughness = Pr if given, else 1 with map_Pr, else roughnessFromPhong(Ns) if Ns is given, else 0.5
// 5. Diffuse: everything else (Kd only), as before materials had types.
// For every type: Ke (emission); `d` (dissolve, in [0, 1]) is the alpha (coverage) of a BLEND material
// when it is below 1 or a map_d is given, else the material is opaque. `Tr` (transparency) is accepted
// and ignored: exporters disagree whether it means 1 - d or d (and write `Tr 1` on opaque materials).
// Fields a type does not use keep Material's defaults.
//
// Texture maps (`map_X [options] file`; relative to the MTL file) multiply the value they map, which
// defaults to 1 when the map is given without it (map_Kd without Kd, map_Ke without Ke, ...):
//   map_Kd   colour (sRGB): Kd of Lambertian, plastic and metallic-roughness materials
//   map_Ks   colour (sRGB): Ks of illum-5 metals and plastics (their F0 and coat tint)
//   map_Ke   colour (sRGB): Ke, any type
//   map_Pr   roughness (linear), any type with a roughness (not Lambertian)
//   map_Pm   metallic (linear): selects the metallic-roughness model (rule 2)
//   map_d    coverage (linear), any type: the channel -imfchan names, else the file's alpha channel if it
//            has one, else its luminance
//   norm, map_Bump, bump   a tangent-space normal map (RGB = normal * 0.5 + 0.5, green up, as glTF's
//            and Blender's), any type; -bm scales its x and y (glTF's normalTexture.scale). norm wins
//            over the other two. The MTL spec's bump is a height map: a greyscale file named by
//            map_Bump or bump is taken for one and ignored with a warning (height maps are not
//            supported).
//   map_Pr and map_Pm are scalar maps: -imfchan r|g|b|l picks the channel (default l, luminance), so
//   that one packed file can serve both (glTF's metallicRoughness: `map_Pr -imfchan g`, `map_Pm
//   -imfchan b`). The loader combines them into one metallic-roughness texture (Material).
//   A map on a type that does not use it is ignored, with one warning per statement and file. Other
//   options (-s, -o, -clamp, -mm, ...) are not supported: "ignored N map_X -s/... options" once per
//   file; textures always repeat. A map statement without a file name is malformed.
//
// Sanitising (sanitizeMtl) happens first, with one warning per kind of repair and file:
//   Kd, Ks, Tf, Kt: each channel clamped to [0, 1]; Ke: negative channels set to 0; NaN or infinite
//     channels replaced by 0; `Kd 0.5` means grey; malformed, spectral and CIE XYZ colours ignored.
//   Pr, Pm, d clamped to [0, 1]; Ni clamped to [1, 4]; Ns < 0 set to 0; NaN or infinite Ni, Ns, Pr,
//     Pm, d and malformed scalar statements (or `illum` values that are not integers) ignored, so the
//     defaults above apply.
//   Statements we do not model (Ka, Tr, sharpness, Ps, Pc, Pcr, aniso, anisor, disp, decal, refl and
//   the other map_*) are accepted silently; any other statement gets "unknown MTL statement 'xyz'
//   ignored (first at line L)" once per statement name and file.

// The perceptual roughness (GGX alpha = roughness^2) equivalent to a Blinn-Phong exponent Ns: Walter
// et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 33, relates the Phong
// exponent to the Beckmann width by alpha = sqrt(2 / (Ns + 2)); we use that alpha for GGX, an
// approximation (the two distributions differ in their tails). Ns 0 gives 1, Ns 10 about 0.64,
// Ns 100 about 0.37, Ns 1000 about 0.21.
float roughnessFromPhong(float ns);

// What an MTL material says, after sanitizing; std::nullopt where it does not give a statement (the
// defaults of the rules above then apply, not the MTL spec's Ni 1 and Ns 1).
struct MtlMaterial {
    std::string name;
    glm::vec3 kd{0.0f}, ke{0.0f}, ks{0.0f}, tf{0.0f};
    std::optional<int> illum;
    std::optional<float> ni, ns, pr, pm, vd, d;
    bool roughnessMap = false, metallicMap = false, alphaMap = false;  // map_Pr, map_Pm, map_d given
};

// The rules above.
Material materialFromMtl(const MtlMaterial& mtl);

// The texture map statements we read, in the order of MtlGiven::maps.
enum class MtlMap : int { Kd, Ks, Ke, Pr, Pm, D, Norm, Bump, Count };
constexpr int kMtlMapCount = int(MtlMap::Count);
// The statement's name in messages ("map_Kd", ..., "norm", "map_Bump"; bump is reported as map_Bump).
const char* mtlMapName(MtlMap map);

// One texture map statement: the file as written (options removed; empty if the material has none),
// its line, and the options we read.
struct MtlMapStatement {
    std::string file;
    int line = 0;
    float bumpScale = 1.0f;  // -bm (norm, map_Bump, bump)
    char channel = 0;        // -imfchan r, g, b, m (matte: alpha) or l (luminance); 0 when not given
};

// Which statements of one material were given: tinyobjloader fills absent ones with the MTL defaults
// (Ni 1, Ns 1, illum 0, Pr 0, Pm 0, d from Tr), which cannot be told apart from explicit values.
struct MtlGiven {
    bool illum = false, ni = false, ns = false, pr = false, pm = false, vd = false, d = false;
    // tinyobjloader gives a material with map_Kd but no Kd the grey 0.6, but only until some earlier
    // material of the file had a Kd (it never resets its flag at newmtl); we decide from these instead.
    bool kd = false, ke = false, ks = false;
    std::array<MtlMapStatement, kMtlMapCount> maps;
    const MtlMapStatement& map(MtlMap m) const { return maps[size_t(m)]; }
};

// tinyobjloader's MTL reader takes `Kd 0.14` as (0.14, 0, 0) where the MTL spec means grey, reads "nan"
// and "abc" as 0, keeps values outside their ranges, and takes the name of `newmtl  x` (two blanks) as
// " x". This rewrites the newmtl, colour (Kd, Ke, Ks, Tf, Kt) and scalar (Ni, Ns, Pr, Pm, illum)
// statements so that it reads exactly what we mean, keeping line numbers, and warns once per kind of
// repair (and unknown statement), naming `name` and the first line. If `given` is not null it receives
// one entry per material tinyobjloader will return with a name, in the same order.
std::string sanitizeMtl(std::string_view text, const std::string& name,
                        std::vector<MtlGiven>* given = nullptr);

// How a texture an MTL library names is made from its file(s).
enum class MtlTextureKind {
    Color,              // the file's texels as they are (map_Kd, map_Ks, map_Ke)
    Alpha,              // A = the coverage: the channel `channel` names (map_d)
    Normal,             // as they are; a greyscale file is a height map: refused with a warning
    MetallicRoughness,  // G = map_Pr's channel (255 without one), B = map_Pm's (255 without one)
};

// A texture an MTL library names: the file as written (relative to the library) and the statement's line.
struct MtlTexture {
    std::string file;  // MetallicRoughness: map_Pr's file, empty if none
    int line = 0;
    MtlTextureKind kind = MtlTextureKind::Color;
    std::string statement = "map_Kd";  // for messages
    char channel = 0;                  // Alpha and MetallicRoughness (map_Pr's): as MtlMapStatement
    // MetallicRoughness only: map_Pm's file (empty if none), its line and channel.
    std::string metallicFile;
    int metallicLine = 0;
    char metallicChannel = 0;
};

// The materials of one MTL library, in file order (sanitized as above, read by tinyobjloader, then
// typed by materialFromMtl). Never throws for bad content: problems in a library only cost materials,
// with warnings. Material's *Texture fields index `*textures` (one entry per map used, appended); the
// caller loads the files.
std::vector<Material> parseMtl(std::string_view text, const std::string& name,
                               std::vector<MtlTexture>* textures);

}  // namespace fp
