// Texture maps (MTL map_Kd, map_Pr/map_Pm, map_Ke, norm/map_Bump, map_d, map_Ks; glTF's material
// textures), compiled in only when the scene has some (SURFACE_TEXTURES), and each kind of map only when
// some material has one (its bit in SURFACE_MAPS), so that other scenes pay nothing. The layout is in
// src/pack/layout.h: three texture coordinates per triangle, every texture's 8-bit texels in one RGBA8
// buffer, (first texel, width, height) per texture, the maps' indices in the material's texels, and, with
// normal maps, three tangents per triangle.
#include "common/scene_data.glsl"

#ifdef VERTEX_COLORS
// Per-vertex colours (glTF COLOR_0), compiled in only when some triangle has them: linear rgba that
// multiplies the base colour and the alpha (src/pack/layout.h, colors).
#ifdef SCENE_READS_IMAGES
layout(rgba32f) readonly uniform imageBuffer uColors;
#else
uniform samplerBuffer uColors;
#endif
vec4 fetchVertexColor(int i, vec2 b) {
    return (1.0 - b.x - b.y) * SCENE_TEXEL(uColors, i * COLOR_TEXELS) + b.x * SCENE_TEXEL(uColors, i * COLOR_TEXELS + 1) +
           b.y * SCENE_TEXEL(uColors, i * COLOR_TEXELS + 2);
}
#endif

#ifdef SURFACE_TEXTURES
#ifndef SURFACE_MAPS
#define SURFACE_MAPS DIFFUSE_MAP_BIT
#endif
#define HAS_MAP(bit) ((SURFACE_MAPS & (bit)) != 0)
// Read as images or texel fetches like the scene buffers (scene_data.glsl), except the RGBA8 texels,
// whose texelFetch llvmpipe already generates inline.
#ifdef SCENE_READS_IMAGES
layout(rg32f) readonly uniform imageBuffer uTexcoords;
layout(rgba32i) readonly uniform iimageBuffer uTextureTable;
#if HAS_MAP(NORMAL_MAP_BIT)
layout(rgba32f) readonly uniform imageBuffer uTangents;
#endif
#else
uniform samplerBuffer uTexcoords;
uniform isamplerBuffer uTextureTable;
#if HAS_MAP(NORMAL_MAP_BIT)
uniform samplerBuffer uTangents;
#endif
#endif
uniform samplerBuffer uTextureTexels;

vec2 texcoordTexel(int i) { return SCENE_TEXEL(uTexcoords, i).xy; }
ivec4 textureTableTexel(int t) { return SCENE_TEXEL(uTextureTable, t); }

int materialTexture(int m) { return int(materialTexel(m * MATERIAL_TEXELS + MATERIAL_MAPS_TEXEL).x); }

// The texture coordinates of both uv slots (xy: slot 0, zw: slot 1, the same as slot 0 in scenes of one
// slot, TEXCOORD_SLOTS 1) at barycentrics b of triangle i. Each map picks its slot (textureUv).
vec4 fetchTexcoord(int i, vec2 b) {
    int first = i * TEXCOORD_TEXELS * TEXCOORD_SLOTS;
    vec2 t0 = texcoordTexel(first), t1 = texcoordTexel(first + 1), t2 = texcoordTexel(first + 2);
    vec2 uv = (1.0 - b.x - b.y) * t0 + b.x * t1 + b.y * t2;
#if TEXCOORD_SLOTS == 2
    vec2 s0 = texcoordTexel(first + 3), s1 = texcoordTexel(first + 4), s2 = texcoordTexel(first + 5);
    return vec4(uv, (1.0 - b.x - b.y) * s0 + b.x * s1 + b.y * s2);
#else
    return uv.xyxy;
#endif
}

// The slot of the two in uvs that texture `info` reads (its table entry's sampling field).
vec2 textureUv(ivec4 info, vec4 uvs) {
#if TEXCOORD_SLOTS == 2
    if ((info.w & TEXTURE_SLOT1_FLAG) != 0) return uvs.zw;
#endif
    return uvs.xy;
}

// The exact sRGB decoding curve (IEC 61966-2-1:1999), as srgbDecode in src/image/tone_map.h.
vec3 srgbDecode(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

// Texel xy (integer-valued, any range) of a texture, wrapped as its sampler says (glTF's wrapS and
// wrapT, the OpenGL rules: repeat, clamp to the edge texel, or repeat mirrored every other time), as
// code / 255. The floor-modulo is done in float, exact for integers below 2^24 (GLSL leaves % of
// negatives undefined); the clamp only guards against a rounded division.
vec4 textureCode(ivec4 info, vec2 xy) {
    vec2 size = vec2(info.yz);
#ifdef TEXTURE_SAMPLING
    ivec2 wrap = ivec2(info.w, info.w >> TEXTURE_WRAP_T_SHIFT) & 3;  // fp::TextureWrap per axis
    vec2 period = mix(size, 2.0 * size, equal(wrap, ivec2(2)));
    vec2 m = xy - period * floor(xy / period);
    m = mix(m, min(m, 2.0 * size - 1.0 - m), equal(wrap, ivec2(2)));  // mirrored: the second half reversed
    xy = mix(m, xy, equal(wrap, ivec2(1)));                             // clamped below
#else
    xy = xy - size * floor(xy / size);
#endif
    ivec2 p = clamp(ivec2(xy), ivec2(0), info.yz - 1);
    return texelFetch(uTextureTexels, info.x + p.y * info.y + p.x);
}

// The linear colour of texel xy of a colour map.
vec3 textureTexel(ivec4 info, vec2 xy) { return srgbDecode(textureCode(info, xy).rgb); }

// Where uv falls in texture `info`, in texels with their centres at half-integers, minus 0.5: the texel
// to the lower left of the bilinear footprint is floor of it. Rows are stored top first and OBJ's v = 0
// is the bottom of the image. Nearest filtering (glTF magFilter NEAREST) puts the point on the centre
// of the texel it falls in, so that the bilinear weights pick that texel alone.
vec2 texelPosition(ivec4 info, vec2 uv) {
    vec2 xy = vec2(uv.x, 1.0 - uv.y) * vec2(info.yz);
#ifdef TEXTURE_SAMPLING
    if ((info.w & TEXTURE_NEAREST_FLAG) != 0) xy = floor(xy) + 0.5;
#endif
    return xy - 0.5;
}

// Bilinear filtering of colour map t at the uv slot it reads (uvs: fetchTexcoord), wrapped as its
// sampler says. Texels are decoded before filtering, as GPUs filter sRGB textures.
vec3 sampleTexture(int t, vec4 uvs) {
    ivec4 info = textureTableTexel(t);
    vec2 xy = texelPosition(info, textureUv(info, uvs));
    vec2 base = floor(xy), f = xy - base;
    vec3 top = mix(textureTexel(info, base), textureTexel(info, base + vec2(1.0, 0.0)), f.x);
    vec3 bottom = mix(textureTexel(info, base + vec2(0.0, 1.0)), textureTexel(info, base + vec2(1.0)), f.x);
    return mix(top, bottom, f.y);
}

// The same for a map of linear values (roughness and metallic, normals, coverage): the codes / 255,
// bilinear, all four channels.
vec4 sampleLinearTexture(int t, vec4 uvs) {
    ivec4 info = textureTableTexel(t);
    vec2 xy = texelPosition(info, textureUv(info, uvs));
    vec2 base = floor(xy), f = xy - base;
    vec4 top = mix(textureCode(info, base), textureCode(info, base + vec2(1.0, 0.0)), f.x);
    vec4 bottom = mix(textureCode(info, base + vec2(0.0, 1.0)), textureCode(info, base + vec2(1.0)), f.x);
    return mix(top, bottom, f.y);
}

// Material m's Kd at barycentrics b of triangle i: `diffuse` times its texture, if it has one.
vec3 texturedDiffuse(int m, vec3 diffuse, int i, vec2 b) {
    int t = materialTexture(m);
    return t < 0 ? diffuse : diffuse * sampleTexture(t, fetchTexcoord(i, b));
}

ivec4 materialMaps(int m) { return ivec4(materialTexel(m * MATERIAL_TEXELS + MATERIAL_MAPS_TEXEL)); }

#if HAS_MAP(NORMAL_MAP_BIT)
vec4 tangentTexel(int i) { return SCENE_TEXEL(uTangents, i); }

// Tangent-space normal mapping (glTF 2.0 material.normalTexture; the frame of Mikkelsen 2008, "Simulation
// of Wrinkled Surfaces Revisited", section 2.3): the map's rgb * 2 - 1, x and y scaled by `scale`,
// gives the normal in the frame (t, b, n) with n the interpolated vertex normal, t the interpolated
// tangent made orthogonal to n (Gram-Schmidt) and b = sign cross(n, t). The unit result may lean past
// the surface's plane where a map tilts steeply: surfaceAt tilts it back (valid_reflection.glsl).
vec3 normalMapped(int t, float scale, int i, vec2 b, vec4 uv, vec3 n) {
    vec4 tw = (1.0 - b.x - b.y) * tangentTexel(i * TANGENT_TEXELS) + b.x * tangentTexel(i * TANGENT_TEXELS + 1) +
              b.y * tangentTexel(i * TANGENT_TEXELS + 2);
#ifdef INSTANCE_NODES_START
    tw.xyz = gInstanceLinear * tw.xyz;  // an instance's tangents are in its mesh's space (surface.glsl)
#endif
    vec3 tangent = tw.xyz - n * dot(n, tw.xyz);
    if (!(dot(tangent, tangent) > 1e-12)) return n;
    tangent = normalize(tangent);
    vec3 bitangent = cross(n, tangent) * (tw.w < 0.0 ? -1.0 : 1.0);
    vec3 c = sampleLinearTexture(t, uv).xyz * 2.0 - 1.0;
    vec3 mapped = scale * (c.x * tangent + c.y * bitangent) + c.z * n;
    return dot(mapped, mapped) > 1e-12 ? normalize(mapped) : n;
}
#endif
#endif
