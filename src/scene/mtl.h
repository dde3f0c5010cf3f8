#pragma once
// MTL material libraries, mapped onto fragpath's four surface models (MaterialType in scene.h).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace fp {

// How MTL statements become a Material. The MTL spec (Wavefront, "MTL material format", Lighting and
// illumination models) names a lighting model with `illum`; PBR extensions add Pr (roughness) and Pm
// (metallic). We read them as follows, first matching rule wins:
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
//      roughness    = Pr if given, else 0 (smooth glass)
//    `d` and `Tr` (dissolve) never select glass: they are opacity (cut-outs), which we do not model;
//    they are accepted and ignored silently.
// 2. Conductor, PBR style: Pm >= 0.5 (0 < Pm < 0.5 counts as not metallic).
//      specular  = Kd (the metalness convention: the base colour is the metal's F0)
//      roughness = Pr if given, else 0.5
// 3. Conductor, Fresnel mirror: `illum 5` with a non-black Ks and no Pm statement.
//      specular  = Ks, roughness = Pr if given, else 0 (illum 5 is a ray-traced mirror)
// 4. Plastic: a non-black Ks, unless an explicit `illum 0` or `illum 1` switches specular off (the
//    spec's models 0 and 1 have no Ks term; exporters write them for materials without highlights).
//    This includes `illum 2`, `illum 3` (ray-traced reflection: a mirror-like coat), no `illum`, and
//    `illum 5` when Pm is given (the file uses the PBR convention and said "not a metal").
//      diffuse   = Kd, specular = Ks (coat tint), ior = Ni if given and above 1, else 1.5
//      roughness = Pr if given, else roughnessFromPhong(Ns) if Ns is given, else 0.5
// 5. Diffuse: everything else (Kd only), as before materials had types.
// Ke (emission) is kept for every type. Fields a type does not use keep Material's defaults.
//
// Sanitising (sanitizeMtl) happens first, with one warning per kind of repair and file:
//   Kd, Ks, Tf, Kt: each channel clamped to [0, 1]; Ke: negative channels set to 0; NaN or infinite
//     channels replaced by 0; `Kd 0.5` means grey; malformed, spectral and CIE XYZ colours ignored.
//   Pr, Pm clamped to [0, 1]; Ni clamped to [1, 4]; Ns < 0 set to 0; NaN or infinite Ni, Ns, Pr, Pm
//     and malformed scalar statements (or `illum` values that are not integers) ignored, so the
//     defaults above apply.
//   map_Kd [options] file: a colour texture that multiplies Kd (the MTL spec's rule); a material with
//     map_Kd but no Kd takes Kd 1 (the texture alone), one with neither keeps Kd 0 (pure emitters are
//     often written that way). The file is relative to the MTL file. Its options (-s, -o, -clamp, ...)
//     are not supported: "ignored N map_Kd -s/-clamp options" once per file; textures always repeat.
//     A map_Kd without a file name is a malformed statement. Only Lambertian and plastic materials have
//     a diffuse colour: on metals and glass map_Kd is ignored with one warning per file. Other texture
//     maps and the statements we do not model (Ka, d, Tr, sharpness, Ps, Pc, Pcr, aniso, anisor, norm,
//     bump, disp, decal, refl, map_*) are accepted silently; any other statement gets "unknown MTL
//     statement 'xyz' ignored (first at line L)" once per statement name and file.

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
    std::optional<float> ni, ns, pr, pm, vd;
};

// The rules above.
Material materialFromMtl(const MtlMaterial& mtl);

// Which statements of one material were given: tinyobjloader fills absent ones with the MTL defaults
// (Ni 1, Ns 1, illum 0, Pr 0, Pm 0), which cannot be told apart from explicit values.
struct MtlGiven {
    bool illum = false, ni = false, ns = false, pr = false, pm = false, vd = false;
    // tinyobjloader gives a material with map_Kd but no Kd the grey 0.6, but only until some earlier
    // material of the file had a Kd (it never resets its flag at newmtl); we decide from these instead.
    bool kd = false;
    std::string diffuseMap;  // map_Kd's file as written (options removed), empty if none
    int diffuseMapLine = 0;
};

// tinyobjloader's MTL reader takes `Kd 0.14` as (0.14, 0, 0) where the MTL spec means grey, reads "nan"
// and "abc" as 0, keeps values outside their ranges, and takes the name of `newmtl  x` (two blanks) as
// " x". This rewrites the newmtl, colour (Kd, Ke, Ks, Tf, Kt) and scalar (Ni, Ns, Pr, Pm, illum)
// statements so that it reads exactly what we mean, keeping line numbers, and warns once per kind of
// repair (and unknown statement), naming `name` and the first line. If `given` is not null it receives
// one entry per material tinyobjloader will return with a name, in the same order.
std::string sanitizeMtl(std::string_view text, const std::string& name,
                        std::vector<MtlGiven>* given = nullptr);

// A texture an MTL library names: the file as written (relative to the library) and the statement's line.
struct MtlTexture {
    std::string file;
    int line = 0;
};

// The materials of one MTL library, in file order (sanitized as above, read by tinyobjloader, then
// typed by materialFromMtl). Never throws for bad content: problems in a library only cost materials,
// with warnings. Material::diffuseTexture indexes `*textures` (one entry per map_Kd used, appended);
// the caller loads the files.
std::vector<Material> parseMtl(std::string_view text, const std::string& name,
                               std::vector<MtlTexture>* textures);

}  // namespace fp
