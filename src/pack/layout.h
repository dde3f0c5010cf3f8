#pragma once
// THE GPU SCENE LAYOUT: the one place that says what every texel of the scene's buffer textures holds.
// The packer (pack/pack.cpp) writes it; glsl/common/scene_data.glsl reads it through the defines that
// layoutDefines() (gpu/layout_defines.h) injects, so the two cannot drift apart.
//
// All buffers are GL_TEXTURE_BUFFERs (fastest way to read scene data on llvmpipe, see
// docs/optimisation-log.md, "Traversal and layout" and entries 1-8).
// Where the context has GL_ARB_shader_image_load_store, the trace shaders read the buffers and the
// environment map that kImageUnits below lists with imageLoad, which llvmpipe generates inline, rather
// than texelFetch, which is an out-of-line call for every format but RGBA8 (docs/optimisation-log.md,
// entries 18 and 23); the texels are the same either way. That is every buffer but textureTexels, the
// one RGBA8 buffer, whose texelFetch llvmpipe already inlines.
// Triangles are stored in BVH leaf order; "triangle i" below means packed index i.
//
//  buffer        format     texels per item  contents
//  triangles     RGBA32F    3 per triangle   (v0.xyz, material index)  (e1.xyz, light pmf)  (e2.xyz, flags)
//                                            e1 = v1 - v0, e2 = v2 - v0; light pmf = probability that
//                                            light sampling picks this triangle (0 if not emissive);
//                                            flags (an exact float): + 1 if its material has alpha
//                                            (MASK or BLEND), + 2 if it is single-sided (the camera
//                                            does not see its back): traversal tests such hits (read
//                                            only with SURFACE_OPACITY).
//                                            (RGB32F positions, 36 bytes, with the rest moved to the
//                                            normals, rendered the same image 10 % slower on llvmpipe:
//                                            docs/optimisation-log.md, entry 6.)
//  normals       RGBA32F    3 per triangle   (n0.xyz, entry) (n1.xyz, 0) (n2.xyz, 0)  unit shading
//                                            normals; entry: an emitter's index in the lights buffer's
//                                            cdf (exact float; 0 for other triangles), for the light
//                                            tree's MIS density of an emitter a ray hits
//  nodes         RGBA32UI   4 per node       the 4-wide BVH (bvh/wide_bvh.h), one node in 64 bytes, so one
//                                            cache line (llvmpipe allocates buffers 64-byte aligned):
//                                            (grid origin.xyz as float bits, scale exponents)
//                                            (lo.x, hi.x, lo.y, hi.y) (lo.z, hi.z, 0, 0) (links)
//                                            the four children's boxes quantised to 8 bits per plane on
//                                            a grid local to the node, child i in byte i of each plane's
//                                            uint, rounded outwards so that each contains its exact box
//                                            (Ylitie, Karras & Laine 2017; pack/quantised_node.h has the
//                                            details); then the four children's links, one uint each
//                                            (encodeChild):
//                                            bit 31 set: a leaf of triangles [first, first + count) with
//                                            first in bits 0-26 and count - 1 in bits 27-30;
//                                            bit 31 clear: the interior node of that index; 0 for an
//                                            empty slot (node 0 is the root, never a child), whose box
//                                            is inverted and which the traversal skips by its link.
//                                            There are about half as many nodes as binary nodes. With
//                                            bvhOptions() below, leaves hold about 4 triangles and there
//                                            is about one node per 9 to 10 triangles, so positions + BVH
//                                            come to about 48 + 7 = 55 bytes per triangle (54.0-55.5
//                                            on cornell, sphere-100k and sphere-1m; the exact boxes of
//                                            112-byte nodes took 57.8-61.1; docs/optimisation-log.md,
//                                            entry 21).
//                                            With instances (scene/instancing.h), two levels
//                                            (the renderer then compiles INSTANCES): node 0 is the root
//                                            of a top level over the instances (and the world
//                                            triangles as one more, untransformed), whose leaves are
//                                            interior links to instance node pairs; then the world
//                                            triangles' BVH and each mesh's, with node and triangle
//                                            indices of the whole buffers; then, from node
//                                            INSTANCE_NODES_START, two nodes per instance: the first
//                                            holds the rows of its world-to-object transform (3 x 4,
//                                            float bits) and then (root of its BVH, 0, 0, 0), the second
//                                            the rows of object-to-world and (0, 0, 0, 0). Triangles are
//                                            stored once, in object space: the world's, then each
//                                            mesh's, in leaf order. Rays enter an instance in its space.
//  materials     RGBA32F   10 per material   (Kd.rgb, type) (Ke.rgb, roughness) (Ks.rgb, ior) (Tf.rgb, B)
//                                            (diffuse map, metallic-roughness map, emission map, normal map)
//                                            (alpha map, alpha, alpha cutoff, alpha mode)
//                                            (metallic, normal scale, specular map, 0)
//                                            (sigma_a.rgb, 0) (clearcoat, clearcoat roughness, 0, 0)
//                                            (sheen colour.rgb, sheen roughness)
//                                            Ks of a MetallicRoughness is its specularColor (the tint of
//                                            its dielectric coat: KHR_materials_specular); sigma_a a
//                                            Dielectric's absorption per unit length (KHR_materials_
//                                            volume), read only when MATERIAL_VOLUME is 1; the
//                                            clearcoat texel (KHR_materials_clearcoat) only when
//                                            MATERIAL_CLEARCOAT is 1, the sheen texel
//                                            (KHR_materials_sheen) only when MATERIAL_SHEEN is 1
//                                            B: Cauchy coefficient in nm^2 of a dispersive glass, else 0
//                                            (ior is then the index at 587.6 nm; scene/spectrum.h)
//                                            type: fp::MaterialType as an exact float, alpha mode
//                                            fp::AlphaMode; Kd is a MetallicRoughness's base colour
//                                            maps: indices into textureTable, -1 for none (Material's
//                                            *Texture fields); each is read only when the shader is
//                                            compiled with its bit in SURFACE_MAPS (layout::MapBit);
//                                            the alpha texel only with SURFACE_OPACITY; metallic only
//                                            when MATERIAL_TYPES has MetallicRoughness. Scenes without
//                                            them read the first four texels, as before.
//  lights        RGBA32F    1 per light,     the light-selection cdf, one entry per emitter triangle (in
//                           then 3 per       leaf order) and then one per punctual light (in the scene's
//                           punctual light   order), each (index, cdf up to and including it, pmf, 0):
//                                            index >= 0: the emitter triangle of that packed index;
//                                            index < 0: punctual light k = -1 - index.
//                                            The shader gets the number of entries as uLightCount.
//                                            Then, from texel uLightCount on, kPunctualTexels per punctual
//                                            light k (scene/scene.h PunctualLight; only in scenes that
//                                            have some, whose shaders the renderer compiles with
//                                            PUNCTUAL_LIGHTS):
//                                            (position.xyz, type) (direction.xyz, a) (intensity.rgb, b)
//                                            type: fp::PunctualLightType as an exact float; direction:
//                                            unit, the way the light travels; intensity: W/sr, or for a
//                                            directional light the irradiance in W/m^2;
//                                            spot: a = cos(outer cone angle), b = cos(inner cone angle);
//                                            directional: position = the centre of the sphere its light
//                                            subpaths start from (scene/punctual_light.h), a = its radius;
//                                            otherwise 0.
//                                            In scenes without punctual lights, from texel
//                                            LIGHT_TREE_FIRST on (PackedScene::lightTreeFirst), the light
//                                            tree (pack/light_tree.h), 3 per node in heap order:
//                                            (box lo.xyz, power) (box hi.xyz, cos(cone half-angle))
//                                            (cone axis.xyz, 0)
//
// Only when some material has a texture (the renderer then defines SURFACE_TEXTURES; without it the
// shader has no texture code at all and the three buffers are not allocated):
//  texcoords     RG32F      3 per triangle   (uv0) (uv1) (uv2): OBJ vt, v = 0 at the image's bottom row;
//                           and slot         with a second uv slot (some texture's Texture::uvSlot is 1;
//                                            the renderer then defines TEXCOORD_SLOTS 2) 6 per triangle:
//                                            the three of slot 0, then the three of slot 1
//  textureTexels RGBA8      1 per texel      every texture's texels, concatenated; each texture row-major
//                                            with its top row first; codes read as code / 255, the rgb
//                                            of colour maps (diffuse, emission, specular) then decoded
//                                            from sRGB in the shader; A is coverage (alpha maps)
//  textureTable  RGBA32I    1 per texture    (first texel in textureTexels, width, height, sampling)
//                                            sampling: the wrap mode along u (fp::TextureWrap) + 4 x the
//                                            one along v + kTextureNearestFlag + kTextureSlot1Flag
//                                            (Texture's fields); textures of one image share its texels.
//                                            Wrap modes other than repeat and nearest filtering are
//                                            compiled in only when some texture has one
//                                            (TEXTURE_SAMPLING)
// Only when some material has a normal map (SURFACE_MAPS has kNormalMapBit):
//  tangents      RGBA32F    3 per triangle   (t0.xyz, s0) (t1.xyz, s1) (t2.xyz, s2): per-vertex tangents
//                                            (Scene::tangents, or the triangle's own from its positions
//                                            and uvs at all three), s = +-1 the bitangent's sign
// Only when some triangle has vertex colours (Scene::colors; the renderer then defines VERTEX_COLORS):
//  colors        RGBA32F    3 per triangle   (c0) (c1) (c2): linear rgba, multiplying the base colour and
//                                            alpha (1 where a triangle has none)
//
// An environment map (only when the scene has one) is a 2D RGBA32F texture of W x H radiance texels,
// texel (x, y) covering u in [x, x+1)/W, v in [y, y+1)/H (v = 0 is straight up), and an R32F buffer
// texture of importance-sampling CDFs: H entries of the marginal CDF over rows, then for each row y
// W entries of the conditional CDF over its texels (each cumulative, ending at 1). The shaders get W
// and H as the define ENVIRONMENT_SIZE.
//
// Indices stored in float channels are exact integers below 2^24, which every GPU keeps exactly; the
// node links are integers in an integer format, so no GPU can flush them as denormals.
#include <cstddef>
#include <cstdint>

#include "bvh/bvh.h"
#include "pack/quantised_node.h"

namespace fp::layout {

constexpr int kTriangleTexels = 3;
constexpr int kNormalTexels = 3;
// The nodes' texels: kNodeTexels and kNodeLinkTexel are in pack/quantised_node.h.

// A child link of nodes (see above).
constexpr uint32_t kLeafBit = 1u << 31;
constexpr int kLeafCountShift = 27;
constexpr uint32_t kMaxLeafFirst = (1u << kLeafCountShift) - 1;
constexpr uint32_t kMaxLeafCount = 16;
struct ChildLink {
    uint32_t first = 0;  // first triangle of a leaf, or the interior node's index
    uint32_t count = 0;  // triangles of a leaf; 0 for an interior node
};
// Throws fp::Error when the leaf cannot be encoded (first > kMaxLeafFirst, count > kMaxLeafCount).
uint32_t encodeChild(const ChildLink& child);
ChildLink decodeChild(uint32_t link);
constexpr int kMaterialTexels = 10;
// The material texels the shaders address by name (the others are read together in fetchMaterial).
constexpr int kMaterialMapsTexel = 4;
constexpr int kMaterialAlphaTexel = 5;
constexpr int kMaterialExtraTexel = 6;
constexpr int kMaterialVolumeTexel = 7;
constexpr int kMaterialClearcoatTexel = 8;
constexpr int kMaterialSheenTexel = 9;
// SURFACE_MAPS: one bit per kind of texture map some material has, so that a scene compiles only the
// lookups it needs (glsl/common/textures.glsl).
enum MapBit : int {
    kDiffuseMapBit = 1,
    kRoughnessMapBit = 2,  // metallic-roughness
    kEmissionMapBit = 4,
    kNormalMapBit = 8,
    kAlphaMapBit = 16,
    kSpecularMapBit = 32,
};
// The flags of a triangle's third texel.
constexpr int kTriangleAlphaFlag = 1;
constexpr int kTriangleSingleSidedFlag = 2;
constexpr int kPunctualTexels = 3;  // per punctual light, after the cdf entries in the lights buffer
constexpr int kTexcoordTexels = 3;
constexpr int kTangentTexels = 3;
constexpr int kColorTexels = 3;
// The sampling field of a textureTable entry (above).
constexpr int kTextureWrapTShift = 2;
constexpr int kTextureNearestFlag = 16;
constexpr int kTextureSlot1Flag = 32;
constexpr uint32_t kMaxFloatIndex = 1u << 24;

// Scenes of more emitter triangles get no light tree (pack/light_tree.h): its 2 x 2^depth nodes of 3
// texels each stay under 7 MB.
constexpr size_t kMaxLightTreeEmitters = size_t(1) << 16;

// Texture units the scene buffers are bound to while tracing.
enum Unit : int {
    kTrianglesUnit = 0,
    kNormalsUnit,
    kNodesUnit,
    kMaterialsUnit,
    kLightsUnit,
    kTexcoordsUnit,
    kTextureTexelsUnit,
    kTextureTableUnit,
    kTangentsUnit,
    kEnvironmentMapUnit,
    kEnvironmentCdfUnit,
    kColorsUnit,
    kFirstFreeUnit
};

// The textures read with imageLoad when the context allows it (SceneReads::Images, gpu/scene_textures.h):
// each is bound read-only (level 0, not layered) to the image unit of the same number as its texture
// unit, where the scene has it (the texture buffers and the environment map are optional), and the
// shaders declare the same ones as images under SCENE_READS_IMAGES (glsl/common/scene_data.glsl, and
// textures.glsl and lights.glsl for the optional ones). A context without image units for all of them
// reads them all with texelFetch (resolveSceneReads).
constexpr Unit kImageUnits[] = {kTrianglesUnit,      kNormalsUnit,        kNodesUnit,        kMaterialsUnit,
                                kLightsUnit,         kTexcoordsUnit,      kTextureTableUnit, kTangentsUnit,
                                kEnvironmentMapUnit, kEnvironmentCdfUnit, kColorsUnit};
// The highest image unit used, plus one.
constexpr int kImageUnitsNeeded = [] {
    int highest = 0;
    for (Unit unit : kImageUnits) highest = unit > highest ? unit : highest;
    return highest + 1;
}();

// The BVH build options the renderer uses with this layout: leaves of up to 8 triangles, and a node
// visit priced at 3 triangle tests, so that the SAH builder makes leaves of about 4 triangles. On the
// suite this brings positions + BVH from about 76 to about 60 bytes per triangle at the same speed
// (docs/optimisation-log.md, entry 7). The native reference builds its tree with the same options.
// `threads` build it (0: every CPU); the tree is the same for any number.
BvhBuildOptions bvhOptions(int threads = 0);

}  // namespace fp::layout
